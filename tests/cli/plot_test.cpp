// gcx plot on two examples: a well-formed SVG with one <path> per run of rapids or feeds,
// rapids dashed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fmt/format.h>
#include <regex>
#include <unistd.h>

#include "support/test_support.h"

namespace gcx::test {
namespace {

struct Picture {
  int exitCode = -1;
  std::string svg;
};

Picture plot(const std::string& example, const std::string& view, const std::string& args = "") {
  // ctest runs tests as parallel processes: a name of this process's own, not just the example's
  static int serial = 0;
  const fs::path out = fs::temp_directory_path() /
                       fmt::format("gcx-plot-{}-{}-{}-{}.svg", example, view, getpid(), serial++);
  const std::string cmd =
      fmt::format("{} plot {} -o {} --view {} {} 2>/dev/null", GCX_BINARY,
                  (sourceDir() / "examples" / "nct" / example).string(), out.string(), view, args);
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

// O1001's setup puts G54 at X−412.5 Y−230 Z−380.25 and T1's length at 92.4; the program starts
// at machine zero and goes G0 X−30 Y10, then G43 Z20 H1, then faces along Y10 from X−30 to X130.
TEST(Plot, WorkFrameByDefaultMachineFrameOnRequest) {
  const std::string setup =
      "--setup " + (sourceDir() / "examples" / "nct" / "O1001.setup.json").string();
  Picture work = plot("O1001.nct", "xy", setup);
  ASSERT_EQ(work.exitCode, 0);
  expectWellFormed(work.svg);
  // machine zero is X412.5 Y230 of the work frame (SVG y flipped); the face pass at Y10
  EXPECT_NE(work.svg.find("d=\"M412.5 -230L-30 -10\""), std::string::npos);
  EXPECT_NE(work.svg.find("class=\"feed\" stroke=\"#1f5fbf\" stroke-width=\"1.106\" "
                          "d=\"M-30 -10L-30 -10 130 -10\""),
            std::string::npos);
  EXPECT_NE(work.svg.find("<circle cx=\"0\" cy=\"0\" r=\"5.531\"/>"), std::string::npos);
  EXPECT_NE(work.svg.find("O1001.nct, work frame (XY)"), std::string::npos);
  // G43 H1 and G43 H2 each change the work origin between two rapids: 2 more runs than 7
  EXPECT_EQ(count(work.svg, std::regex("<path ")), 9u);

  Picture machine = plot("O1001.nct", "xy", setup + " --frame machine");
  ASSERT_EQ(machine.exitCode, 0);
  EXPECT_NE(machine.svg.find("d=\"M-442.5 220L-442.5 220 -282.5 220\""), std::string::npos);
  EXPECT_NE(machine.svg.find("<circle cx=\"-412.5\" cy=\"230\" r=\"5.531\"/>"), std::string::npos);
  EXPECT_EQ(count(machine.svg, std::regex("<path ")), 7u);
}

TEST(Plot, UnknownFrameIsAUsageError) {
  EXPECT_EQ(plot("O1001.nct", "xy", "--frame tool").exitCode, 2);
}

} // namespace
} // namespace gcx::test
