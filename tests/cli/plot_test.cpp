// gcx plot on two examples: a well-formed SVG with one <path> per run of rapids or feeds,
// rapids dashed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fmt/format.h>
#include <regex>

#include "support/test_support.h"

namespace gcx::test {
namespace {

struct Picture {
  int exitCode = -1;
  std::string svg;
};

Picture plot(const std::string& example, const std::string& view) {
  const fs::path out = fs::temp_directory_path() / fmt::format("gcx-plot-{}-{}.svg", example, view);
  const std::string cmd =
      fmt::format("{} plot {} -o {} --view {} 2>/dev/null", GCX_BINARY,
                  (sourceDir() / "examples" / "nct" / example).string(), out.string(), view);
  Picture p;
  p.exitCode = WEXITSTATUS(std::system(cmd.c_str()));
  p.svg = readFile(out);
  fs::remove(out);
  return p;
}

std::size_t count(const std::string& text, const std::regex& re) {
  return static_cast<std::size_t>(
      std::distance(std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator()));
}

void expectWellFormed(const std::string& svg) {
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  ASSERT_GT(svg.size(), 6u);
  EXPECT_EQ(svg.substr(svg.find_last_not_of('\n') - 5, 6), "</svg>");
  // every element is closed: as many <path as path elements ending in />
  EXPECT_EQ(count(svg, std::regex("<path ")), count(svg, std::regex("<path [^>]*/>")));
}

TEST(Plot, FaceAndContourHasSevenRunsFourOfThemRapid) {
  // O1001: rapids (approach) | face pass 1 | rapid | face pass 2 | rapids (tool change, approach)
  // | contour | rapids (retract, G28)
  Picture p = plot("O1001.nct", "xy");
  ASSERT_EQ(p.exitCode, 0);
  expectWellFormed(p.svg);
  EXPECT_EQ(count(p.svg, std::regex("<path ")), 7u);
  EXPECT_EQ(count(p.svg, std::regex("<path [^>]*stroke-dasharray")), 4u);
}

TEST(Plot, SpiralPocketIsoViewHasThreeRuns) {
  // O1015: approach rapids | helices, spirals and circles at feed | retract rapids
  Picture p = plot("O1015.nct", "iso");
  ASSERT_EQ(p.exitCode, 0);
  expectWellFormed(p.svg);
  EXPECT_EQ(count(p.svg, std::regex("<path ")), 3u);
  EXPECT_EQ(count(p.svg, std::regex("<path [^>]*stroke-dasharray")), 2u);
}

} // namespace
} // namespace gcx::test
