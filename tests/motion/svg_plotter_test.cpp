#include "motion/svg_plotter.h"

#include <gtest/gtest.h>
#include <regex>
#include <sstream>

#include "motion/event_builders.h"

namespace gcx::motion {
namespace {

using namespace test;

// A tiny well-formedness check: tags balance, attribute values are quoted and free of '<',
// every '&' starts an entity, exactly one root element.
::testing::AssertionResult wellFormed(const std::string& xml) {
  std::vector<std::string> open;
  int roots = 0;
  for (std::size_t i = 0; i < xml.size();) {
    if (xml[i] == '&') {
      const auto semi = xml.find(';', i);
      const std::string ent = xml.substr(i, semi == std::string::npos ? 8 : semi - i + 1);
      if (!std::regex_match(ent, std::regex("&(amp|lt|gt|quot|apos|#[0-9]+);")))
        return ::testing::AssertionFailure() << "bad entity at " << i;
      i += ent.size();
      continue;
    }
    if (xml[i] != '<') {
      if (open.empty() && !std::isspace(static_cast<unsigned char>(xml[i])))
        return ::testing::AssertionFailure() << "text outside the root at " << i;
      ++i;
      continue;
    }
    if (xml.compare(i, 2, "<?") == 0) {
      i = xml.find("?>", i) + 2;
      continue;
    }
    // scan the tag, honouring quotes
    std::size_t j = i + 1;
    char quote = 0;
    for (; j < xml.size() && (quote || xml[j] != '>'); ++j) {
      if (quote && xml[j] == '<') return ::testing::AssertionFailure() << "'<' in attribute";
      if (xml[j] == '"' || xml[j] == '\'') quote = quote == xml[j] ? 0 : quote ? quote : xml[j];
    }
    if (j >= xml.size()) return ::testing::AssertionFailure() << "unterminated tag at " << i;
    std::string tag = xml.substr(i + 1, j - i - 1);
    i = j + 1;
    if (tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (open.empty() || open.back() != name)
        return ::testing::AssertionFailure() << "unbalanced </" << name << ">";
      open.pop_back();
      continue;
    }
    const bool selfClosing = tag.back() == '/';
    const std::string name = tag.substr(0, tag.find_first_of(" \t\n/"));
    if (open.empty()) ++roots;
    if (!selfClosing) open.push_back(name);
  }
  if (!open.empty()) return ::testing::AssertionFailure() << "<" << open.back() << "> not closed";
  if (roots != 1) return ::testing::AssertionFailure() << roots << " root elements";
  return ::testing::AssertionSuccess();
}

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1))
    ++n;
  return n;
}

std::vector<std::string> pathElements(const std::string& svg) {
  std::vector<std::string> out;
  for (auto p = svg.find("<path "); p != std::string::npos; p = svg.find("<path ", p + 1))
    out.push_back(svg.substr(p, svg.find("/>", p) - p));
  return out;
}

// The example in svg_plotter.h: 4 runs.
std::vector<Event> program() {
  return {
      rapid({0, 0, 10}, {0, 0, 2}),
      rapid({0, 0, 2}, {10, 0, 2}), // continues the rapid run                    run 1
      valueEvent(Kind::Spindle, 1000),
      feed({10, 0, 2}, {10, 0, 0}), //                                             run 2
      arc(Plane::XY, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, false),
      valueEvent(Kind::Dwell, 1),   // does not break the run
      feed({0, 10, 0}, {0, 10, 0}), // zero length: not drawn, does not break the run
      feed({0, 10, 0}, {0, 20, 0}),
      rapid({0, 20, 0}, {0, 20, 5}), //                                            run 3
      feed({5, 5, 5}, {6, 6, 5}),    // starts elsewhere                           run 4
  };
}

std::string plot(const std::vector<Event>& events, SvgOptions opt = {}) {
  std::ostringstream out;
  SvgPlotter p(out, opt);
  for (const Event& e : events)
    p.event(e);
  p.finish();
  return out.str();
}

TEST(SvgPlotter, OnePathPerRunInEveryView) {
  for (const char* name : {"xy", "xz", "yz", "iso"}) {
    SvgOptions opt;
    opt.view = *parseView(name);
    const std::string svg = plot(program(), opt);
    EXPECT_TRUE(wellFormed(svg)) << name << "\n" << svg;
    const auto paths = pathElements(svg);
    ASSERT_EQ(paths.size(), 4u) << name;
    // rapids dashed, feeds solid
    for (std::size_t i : {0u, 2u}) {
      EXPECT_NE(paths[i].find("class=\"rapid\""), std::string::npos);
      EXPECT_NE(paths[i].find("stroke-dasharray="), std::string::npos);
    }
    for (std::size_t i : {1u, 3u}) {
      EXPECT_NE(paths[i].find("class=\"feed\""), std::string::npos);
      EXPECT_EQ(paths[i].find("stroke-dasharray"), std::string::npos);
    }
  }
  EXPECT_FALSE(parseView("XY").has_value());
}

TEST(SvgPlotter, RunCountMatchesPathElements) {
  std::ostringstream unused;
  SvgPlotter p(unused);
  for (const Event& e : program())
    p.event(e);
  EXPECT_EQ(p.runCount(), 4u);
  // A feed after a rapid that ends where the feed starts is still a new run (new style).
  p.event(feed({6, 6, 5}, {6, 6, 0}));
  p.event(rapid({6, 6, 0}, {6, 6, 10}));
  p.event(feed({6, 6, 10}, {7, 6, 10}));
  EXPECT_EQ(p.runCount(), 6u);
}

TEST(SvgPlotter, FlipsYAndFitsTheViewBox) {
  const std::string svg = plot({feed({0, 0, 0}, {10, 20, 0})});
  // size 20, margin 1, font 0.5, band 3.5·0.5 = 1.75 above; the scale adds a gutter of
  // (0.6·2 characters + 2)·0.5 = 1.6 on the left, 2.8·0.5 = 1.4 below, 1.5·0.5 = 0.75 right
  EXPECT_NE(svg.find("d=\"M0 0L10 -20\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("viewBox=\"-2.6 -22.75 14.35 25.15\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("width=\"800\" height=\"1402.0906\""), std::string::npos) << svg;
}

std::vector<std::string> elements(const std::string& svg, const std::string& group,
                                  const std::string& tag) {
  const auto begin = svg.find("<g class=\"" + group + "\"");
  if (begin == std::string::npos) return {};
  const auto end = svg.find("</g>", begin);
  std::vector<std::string> out;
  for (auto p = svg.find("<" + tag + " ", begin); p < end; p = svg.find("<" + tag + " ", p + 1)) {
    const std::string close = tag == "text" ? "</text>" : "/>";
    out.push_back(svg.substr(p, svg.find(close, p) - p + close.size()));
  }
  return out;
}

TEST(SvgPlotter, GridEveryTwoMillimetresWithLabelsAndAxisNames) {
  // size 20 → step 2 (1-2-5 series, about ten lines); the area is −1..11 × −1..21
  const std::string svg = plot({feed({0, 0, 0}, {10, 20, 0})});
  EXPECT_TRUE(wellFormed(svg));
  const auto grid = elements(svg, "grid", "line");
  ASSERT_EQ(grid.size(), 6u + 11u) << svg;
  EXPECT_EQ(grid[0], "<line x1=\"0\" y1=\"-21\" x2=\"0\" y2=\"1\"/>");
  EXPECT_EQ(grid[5], "<line x1=\"10\" y1=\"-21\" x2=\"10\" y2=\"1\"/>");
  EXPECT_EQ(grid[6], "<line x1=\"-1\" y1=\"0\" x2=\"11\" y2=\"0\"/>");
  EXPECT_EQ(grid[16], "<line x1=\"-1\" y1=\"-20\" x2=\"11\" y2=\"-20\"/>");
  // the axes through zero
  EXPECT_EQ(elements(svg, "axes", "line"),
            (std::vector<std::string>{"<line x1=\"0\" y1=\"-21\" x2=\"0\" y2=\"1\"/>",
                                      "<line x1=\"-1\" y1=\"0\" x2=\"11\" y2=\"0\"/>"}));
  const auto labels = elements(svg, "scale", "text");
  ASSERT_EQ(labels.size(), 6u + 11u + 2u);
  EXPECT_NE(svg.find("<text x=\"10\" y=\"1.55\" text-anchor=\"middle\">10</text>"),
            std::string::npos);
  EXPECT_NE(svg.find("<text x=\"-1.2\" y=\"-19.825\" text-anchor=\"end\">20</text>"),
            std::string::npos);
  EXPECT_NE(svg.find(">X (mm)</text>"), std::string::npos);
  EXPECT_NE(svg.find("transform=\"rotate(-90 -2.1 -10)\">Y (mm)</text>"), std::string::npos);
  // the grid lies behind the path
  EXPECT_LT(svg.find("class=\"grid\""), svg.find("<path "));
}

TEST(SvgPlotter, GridStepFollowsTheOneTwoFiveSeries) {
  struct Case {
    double length;
    const char* firstLabel; // the x label right of zero
  };
  // size/10 rounded up to 1, 2 or 5 times a power of ten
  for (const Case& c : {Case{73, ">10<"}, Case{0.3, ">0.05<"}, Case{4, ">0.5<"},
                        Case{1000, ">100<"}, Case{0.012, ">0.002<"}}) {
    const std::string svg = plot({feed({0, 0, 0}, {c.length, 0, 0})});
    const auto labels = elements(svg, "scale", "text");
    ASSERT_GE(labels.size(), 3u) << c.length;
    EXPECT_NE(labels[1].find(c.firstLabel), std::string::npos) << c.length << " " << labels[1];
  }
}

TEST(SvgPlotter, MarksTheOriginAndKeepsItInTheDrawing) {
  SvgOptions opt;
  opt.origin = Vec3(-30, -40, 7);
  opt.originLabel = "work <zero>";
  const std::string svg = plot({feed({0, 0, 0}, {10, 20, 0})}, opt);
  EXPECT_TRUE(wellFormed(svg));
  // size 60 (y −40..20): font 1.5, marker radius 0.75, drawn at (−30, 40) in SVG coordinates
  EXPECT_NE(svg.find("<circle cx=\"-30\" cy=\"40\" r=\"0.75\"/>"), std::string::npos) << svg;
  EXPECT_NE(svg.find("work &lt;zero&gt;</text>"), std::string::npos);
  // the drawing area reaches 3 (5 % of 60) beyond the origin
  EXPECT_NE(svg.find("<line x1=\"-33\" y1=\"0\" x2=\"13\" y2=\"0\"/>"), std::string::npos);
  opt.origin.reset();
  EXPECT_EQ(plot({feed({0, 0, 0}, {10, 20, 0})}, opt).find("<circle"), std::string::npos);
}

TEST(SvgPlotter, XzFollowsTheLatheConvention) {
  // Z to the right, X (a radius) up: a face from X10 Z−30 to X20 Z−40
  SvgOptions opt;
  opt.view = View::XZ;
  const std::string svg = plot({feed({10, 0, -30}, {20, 0, -40})}, opt);
  EXPECT_NE(svg.find("d=\"M-30 -10L-40 -20\""), std::string::npos) << svg;
  EXPECT_NE(svg.find(">Z (mm)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">X (mm, radius)</text>"), std::string::npos);
}

TEST(SvgPlotter, IsometricViewHasNoGrid) {
  SvgOptions opt;
  opt.view = View::Iso;
  const std::string svg = plot(program(), opt);
  EXPECT_EQ(svg.find("class=\"grid\""), std::string::npos);
  EXPECT_EQ(svg.find("class=\"scale\""), std::string::npos);
  EXPECT_NE(svg.find("class=\"origin\""), std::string::npos);
}

TEST(SvgPlotter, IsometricProjection) {
  // (1,1,0) lies on the screen's right axis; (0,0,1) straight up.
  const std::string svg =
      plot({feed({0, 0, 0}, {1, 1, 0}), feed({1, 1, 0}, {1, 1, 1})}, SvgOptions{View::Iso});
  EXPECT_NE(svg.find("d=\"M0 0L1.41421 0 1.41421 -0.8165\""), std::string::npos) << svg;
}

TEST(SvgPlotter, EscapesTheTitleAndHandlesAnEmptyPath) {
  SvgOptions opt;
  opt.title = "a<b & \"c\" \x01 \xff";
  const std::string svg = plot({}, opt);
  EXPECT_TRUE(wellFormed(svg)) << svg;
  EXPECT_EQ(count(svg, "<path"), 0u);
  EXPECT_NE(svg.find("a&lt;b &amp; &quot;c&quot;   \xEF\xBF\xBD (XY)"), std::string::npos) << svg;
}

TEST(SvgPlotter, ArcsAreSampled) {
  const std::string svg =
      plot({arc(Plane::XY, {10, 0, 0}, {10, 0, 0}, {0, 0, 0}, false)}); // full circle
  const auto paths = pathElements(svg);
  ASSERT_EQ(paths.size(), 1u);
  // tolerance 1e-3 · 20 = 0.02 on radius 10: ceil(2π / √(8·0.02/10)) = 50 segments
  EXPECT_EQ(count(paths[0], " "), 4u + 2 * 50) << paths[0];
}

TEST(SvgPlotter, ModalChangesAndRotaryOnlyMovesDoNotBreakRuns) {
  const std::vector<Event> plain = {rapid({0, 0, 5}, {0, 0, 0}), feed({0, 0, 0}, {10, 0, 0}),
                                    feed({10, 0, 0}, {10, 10, 0})};
  Event zx = valueEvent(Kind::PlaneChange, 0);
  zx.plane = Plane::ZX;
  const std::vector<Event> mixed = {
      valueEvent(Kind::UnitsChange, 20),
      rapid({0, 0, 5}, {0, 0, 0}),
      feed({0, 0, 0}, {10, 0, 0}),
      zx,
      valueEvent(Kind::FeedModeChange, 95),
      withExtra(feed({10, 0, 0}, {10, 0, 0}), Extra::Zero(), extra(90, 0, 0)),
      withExtra(feed({10, 0, 0}, {10, 10, 0}), extra(90, 0, 0), extra(90, 0, 0)),
  };
  EXPECT_EQ(plot(mixed), plot(plain));
}

} // namespace
} // namespace gcx::motion
