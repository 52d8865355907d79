// The report of two small NCT programs run on the interpreter: the recorders take the
// interpreter's events (arcs included), the excerpts come from the program files.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "report/equiv_html.h"
#include "support/run_support.h"

namespace gcx::report {
namespace {

namespace fs = std::filesystem;

TEST(InterpretedReport, PathsFromTheInterpreterExcerptsFromTheFiles) {
  // A and B differ in line 4: A's arc from X10 Y0 to X20 Y10 turns counter-clockwise, B's clockwise
  const std::string a = "(PART A & <B>)\nG90 G17 G21\nG1 X10 Y0 F500\nG3 X20 Y10 R10\nG1 Y30\n",
                    b = "(PART A & <B>)\nG90 G17 G21\nG1 X10 Y0 F500\nG2 X20 Y10 R10\nG1 Y30\n";
  const fs::path dir =
      fs::temp_directory_path() / ("gcx-interpreted-report-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "a.nct") << a;
  std::ofstream(dir / "b.nct") << b;
  PathRecorder pa, pb;
  ASSERT_TRUE(gcx::test::runNct(a, {}, &pa).errors.empty());
  ASSERT_TRUE(gcx::test::runNct(b, {}, &pb).errors.empty());

  EquivPage page;
  page.summary = "arc direction differs";
  page.a = {"A", (dir / "a.nct").string(), 0, 0, {}};
  page.b = {"B", (dir / "b.nct").string(), 0, 0, {}};
  page.a.excerpt = {page.a.file, 4, 1, readExcerpt(page.a.file, 4, 5), ""};
  page.b.excerpt = {page.b.file, 4, 1, readExcerpt(page.b.file, 4, 5), ""};
  page.divergence = motion::Vec3(10, 0, 0);
  std::ostringstream out;
  writeEquivHtml(out, page, pa, pb);
  const std::string html = out.str();

  // the feed along X, then the sampled arc, which bulges to a different side in A and B
  auto feedPath = [&html](const char* id) {
    const auto at = html.find("<path class=\"feed\"", html.find(id));
    return html.substr(at, html.find("/>", at) - at);
  };
  const std::string feedA = feedPath("id=\"path-a\""), feedB = feedPath("id=\"path-b\"");
  EXPECT_NE(feedA.find("d=\"M0 0L10 0 "), std::string::npos) << feedA;
  EXPECT_NE(feedB.find("d=\"M0 0L10 0 "), std::string::npos) << feedB;
  EXPECT_NE(feedA.substr(feedA.find(" d=")), feedB.substr(feedB.find(" d=")));
  EXPECT_EQ(pa.vertices().back().p, motion::Vec3(20, 30, 0));
  EXPECT_EQ(pb.vertices().back().p, motion::Vec3(20, 30, 0));
  EXPECT_GT(pa.vertices().size(), 10u); // the arc is sampled
  // the excerpts: all five lines, line 4 marked, the comment escaped
  EXPECT_NE(html.find("<div class=\"row\"><span class=\"ln\">1</span>(PART A &amp; &lt;B&gt;)"
                      "</div>"),
            std::string::npos);
  EXPECT_NE(html.find("<div class=\"row hit\"><span class=\"ln\">4</span>G3 X20 Y10 R10</div>"),
            std::string::npos);
  EXPECT_NE(html.find("<div class=\"row hit\"><span class=\"ln\">4</span>G2 X20 Y10 R10</div>"),
            std::string::npos);
  EXPECT_NE(html.find("<span class=\"ln\">5</span>G1 Y30</div>"), std::string::npos);
  fs::remove_all(dir);
}

} // namespace
} // namespace gcx::report
