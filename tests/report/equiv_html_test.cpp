#include "report/equiv_html.h"

#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "report/equiv_page_samples.h"

namespace gcx::report {
namespace {

std::string html(const EquivPage& page, const PathRecorder& a, const PathRecorder& b) {
  std::ostringstream out;
  writeEquivHtml(out, page, a, b);
  return out.str();
}

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1))
    ++n;
  return n;
}

// The <path> elements inside <g id="...">.
std::vector<std::string> pathsOf(const std::string& page, const std::string& id) {
  const auto begin = page.find("<g id=\"" + id + "\"");
  const auto end = page.find("</g>", begin);
  std::vector<std::string> out;
  for (auto p = page.find("<path ", begin); p < end; p = page.find("<path ", p + 1))
    out.push_back(page.substr(p, page.find("/>", p) - p + 2));
  return out;
}

TEST(EquivHtml, BothPathsTheMarkerTheExcerptsAndTheSummary) {
  PathRecorder a, b;
  test::recordSamplePaths(a, b);
  const std::string page = html(test::samplePage(), a, b);
  EXPECT_EQ(page.rfind("<!DOCTYPE html>\n<html lang=\"en\">\n", 0), 0u);
  EXPECT_EQ(page.substr(page.size() - 8), "</html>\n");
  EXPECT_EQ(count(page, "<svg "), 1u);
  EXPECT_NE(page.find("<svg id=\"plot\""), std::string::npos);

  // each side: the rapid approach (a point in XY) and the rectangle
  const auto pa = pathsOf(page, "path-a"), pb = pathsOf(page, "path-b");
  ASSERT_EQ(pa.size(), 2u) << page;
  ASSERT_EQ(pb.size(), 2u);
  EXPECT_EQ(pa[1], "<path class=\"feed\" stroke=\"#1f5fbf\" stroke-width=\"5\" "
                   "vector-effect=\"non-scaling-stroke\" d=\"M0 0L100 0 100 -60 0 -60 0 0\"/>");
  EXPECT_NE(pa[0].find("class=\"rapid\""), std::string::npos);
  EXPECT_NE(pa[0].find("stroke-dasharray="), std::string::npos);
  EXPECT_NE(pb[1].find("stroke=\"#e8730c\""), std::string::npos);
  EXPECT_NE(pb[1].find("d=\"M0 0L100 0 100 -70 0 -70 0 0\""), std::string::npos);
  EXPECT_LT(page.find("id=\"path-a\""), page.find("id=\"path-b\"")); // B drawn over A

  // the marker at X100 Y60 (SVG y flipped), and the button that zooms to it
  EXPECT_NE(page.find("<g id=\"divergence\" data-x=\"100\" data-y=\"-60\" "
                      "transform=\"translate(100 -60) scale("),
            std::string::npos);
  EXPECT_NE(page.find("<circle r=\"13\" stroke-width=\"4\"/>"), std::string::npos);
  EXPECT_NE(page.find("id=\"zoom-divergence\""), std::string::npos);
  EXPECT_NE(page.find("id=\"fit\""), std::string::npos);

  // the excerpts: the divergent line marked, a caret under column 4
  EXPECT_NE(page.find("<section class=\"excerpt\" id=\"excerpt-a\">\n<h2>A: part&lt;1&gt;.nct:12:4"
                      "</h2>"),
            std::string::npos);
  EXPECT_NE(page.find("<div class=\"row hit\"><span class=\"ln\">12</span>G1 Y60</div>"
                      "<div class=\"row caret\"><span class=\"ln\"></span>   ^</div>"),
            std::string::npos);
  EXPECT_NE(page.find("<div class=\"row\"><span class=\"ln\">11</span>G1 X100 (A &amp; B "
                      "&lt;C&gt;)</div>"),
            std::string::npos);
  EXPECT_NE(page.find("<p class=\"chain\">in O9010 called from 3</p>"), std::string::npos);
  EXPECT_NE(page.find("<div class=\"row hit\"><span class=\"ln\">7</span>G1 Y70</div>"),
            std::string::npos);

  // the summary
  EXPECT_NE(page.find("<p class=\"verdict different\">Different: end point Y differs by 10.000 "
                      "mm (60 &lt; 70)</p>"),
            std::string::npos);
  EXPECT_NE(page.find("<tr><th>path length (mm, up to the "
                      "divergence)</th><td>330.000</td><td>350.000</td></tr>"),
            std::string::npos);
  EXPECT_NE(
      page.find("<tr><th>time (s, up to the divergence)</th><td>24.50</td><td>26.25</td></tr>"),
      std::string::npos);
  EXPECT_NE(page.find("<td>part&lt;1&gt;.nct:12:4</td><td>out&amp;.ngc:7:1</td>"),
            std::string::npos);
  EXPECT_NE(page.find("<td colspan=\"2\">X100.000 Y60.000 Z0.000</td>"), std::string::npos);
  EXPECT_NE(page.find("<td colspan=\"2\">0.0003</td>"), std::string::npos); // max deviation
  EXPECT_NE(page.find("<td colspan=\"2\">0.0010</td>"), std::string::npos); // tolerance
  // nothing raw from the programs
  EXPECT_EQ(page.find("part<1>"), std::string::npos);
  EXPECT_EQ(page.find("out&.ngc"), std::string::npos);
}

TEST(EquivHtml, SelfContained) {
  PathRecorder a, b;
  test::recordSamplePaths(a, b);
  const std::string page = html(test::samplePage(), a, b);
  for (const char* link : {"src=", "href=", "url(", "@import", "<link", "@font-face"})
    EXPECT_EQ(page.find(link), std::string::npos) << link;
  // the only address is the SVG namespace, which is a name, not a download
  const std::regex address("[a-z]+://[^\"]*");
  for (auto it = std::sregex_iterator(page.begin(), page.end(), address);
       it != std::sregex_iterator(); ++it)
    EXPECT_EQ(it->str(), "http://www.w3.org/2000/svg");
  EXPECT_EQ(count(page, "<style>"), 1u);
  EXPECT_EQ(count(page, "<script>"), 1u);
}

TEST(EquivHtml, AnEquivalentPairHasNoMarker) {
  PathRecorder a, b;
  test::recordSamplePaths(a, b, false);
  EquivPage p = test::samplePage();
  p.equivalent = true;
  p.summary = "same motion";
  p.divergence.reset();
  p.a.excerpt = {};
  p.b.excerpt = {};
  const std::string page = html(p, a, a);
  EXPECT_NE(page.find("<p class=\"verdict equivalent\">Equivalent: same motion</p>"),
            std::string::npos);
  EXPECT_EQ(page.find("id=\"divergence\""), std::string::npos);
  EXPECT_EQ(page.find("zoom-divergence\""), std::string::npos);
  EXPECT_NE(page.find("<td colspan=\"2\">—</td>"), std::string::npos);
  EXPECT_NE(page.find("<tr><th>path length (mm)</th>"), std::string::npos);
  EXPECT_NE(page.find("<h2>A: part&lt;1&gt;.nct</h2>"), std::string::npos);
}

TEST(EquivHtml, TurningProgramsAreShownInTheLatheView) {
  PathRecorder mill, turn, empty;
  test::recordSamplePaths(mill, empty, false);
  turn.event(test::feed({20, 0, 0}, {20, 0, -30}));
  turn.event(test::feed({20, 0, -30}, {25, 0, -35}));
  EXPECT_EQ(defaultView(turn, turn), motion::View::XZ);
  EXPECT_EQ(defaultView(turn, mill), motion::View::XY);
  EXPECT_EQ(defaultView(empty, empty), motion::View::XY);
  std::ostringstream out;
  writeEquivHtml(out, test::samplePage(), turn, turn, defaultView(turn, turn));
  EXPECT_NE(out.str().find("d=\"M0 -20L-30 -20 -35 -25\""), std::string::npos);
  EXPECT_NE(out.str().find(">X (mm, radius)</text>"), std::string::npos);
}

} // namespace
} // namespace gcx::report
