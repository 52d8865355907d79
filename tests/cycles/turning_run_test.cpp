// NCT turning cycles run on the interpreter (cycles.md §4, §8 TV-17 to TV-25): the contour found
// by N number, resolved by the engine itself, the cycle's passes, execution resuming after the
// contour, G70.7 running the blocks, the modal G77.7-G79.7 repeating, and the errors the
// interpreter owns (§7: CYC-PQ-NOTFOUND, CYC-CONTOUR-CMD).
#include <algorithm>
#include <gtest/gtest.h>

#include "cycles/cycle_harness.h"

namespace gcx::test {
namespace {

// X is a diameter axis in every vector (G10.9 X1); G33 prints its lead as F.
CycleHarness runTurning(const std::string& program) {
  CycleHarness h;
  h.diameter = 1;
  h.threads = true;
  EXPECT_TRUE(h.run(program)) << h.error();
  return h;
}

constexpr const char* kTv17 = "N10 G10.9 X1\n"
                              "N15 G18 G90 G95\n"
                              "N20 G0 X60 Z2 S800 M3\n"
                              "N30 G71.7 U3 R1\n"
                              "N40 G71.7 P50 Q90 U0.4 W0.1 F0.3\n"
                              "N50 G0 X30\n"
                              "N60 G1 Z-20 F0.15\n"
                              "N70 X50 Z-30\n"
                              "N80 Z-40\n"
                              "N90 X60\n"
                              "N100 G70.7 P50 Q90\n"
                              "N110 G0 X100 Z50\n";

TEST(CyclesSpec_8_TV17, G71RoughingThenG70FinishingOnTheInterpreter) {
  const auto h = runTurning(kTv17);
  EXPECT_EQ(h.out.count("N30"), 0u); // the first block only stores Δd and e
  EXPECT_EQ(h.out.at("N40"), "G0 X54 | G1 Z-39.9 F0.3 | G0 X56 Z-38.9 | G0 Z2 | "
                             "G0 X48 | G1 Z-28.7 F0.3 | G0 X50 Z-27.7 | G0 Z2 | "
                             "G0 X42 | G1 Z-25.7 F0.3 | G0 X44 Z-24.7 | G0 Z2 | "
                             "G0 X36 | G1 Z-22.7 F0.3 | G0 X38 Z-21.7 | G0 Z2 | "
                             "G0 X30.4 Z2.1 | G1 Z-19.9 F0.3 | G1 X50.4 Z-29.9 F0.3 | "
                             "G1 Z-39.9 F0.3 | G1 X60.4 F0.3 | G0 X60 Z2");
  // the contour ran once, as G70.7's blocks (§4.7: not again after the roughing)
  EXPECT_EQ(h.out.at("N50"), "G0 X30");
  EXPECT_EQ(h.out.at("N60"), "G1 Z-20 F0.15");
  EXPECT_EQ(h.out.at("N70"), "G1 X50 Z-30 F0.15");
  EXPECT_EQ(h.out.at("N80"), "G1 Z-40 F0.15");
  EXPECT_EQ(h.out.at("N90"), "G1 X60 F0.15");
  EXPECT_EQ(h.out.at("N100"), "G0 Z2"); // back to the G70.7 start point X60 Z2 (§4.11)
  EXPECT_EQ(h.out.at("N110"), "G0 X100 Z50");
}

TEST(CyclesSpec_8_TV18, G72FacingOnTheInterpreter) {
  const auto h = runTurning("N10 G10.9 X1\n"
                            "N15 G18 G90 G95\n"
                            "N20 G0 X62 Z2\n"
                            "N30 G72.7 W2 R0.5\n"
                            "N40 G72.7 P50 Q80 U0.2 W0.1 F0.25\n"
                            "N50 G0 Z-6\n"
                            "N60 G1 X40 F0.1\n"
                            "N70 X20 Z-2\n"
                            "N80 Z2\n"
                            "N90 G0 X100\n");
  EXPECT_EQ(h.out.at("N40"), "G0 Z0 | G1 X20.2 F0.25 | G0 X21.2 Z0.5 | G0 X62 | "
                             "G0 Z-2 | G1 X20.7 F0.25 | G0 X21.7 Z-1.5 | G0 X62 | "
                             "G0 Z-4 | G1 X30.7 F0.25 | G0 X31.7 Z-3.5 | G0 X62 | "
                             "G0 X62.2 Z-5.9 | G1 X40.2 F0.25 | G1 X20.2 Z-1.9 F0.25 | "
                             "G1 Z2.1 F0.25 | G0 X62 Z2");
  EXPECT_EQ(h.out.count("N50"), 0u); // skipped: execution resumes after N80
  EXPECT_EQ(h.out.at("N90"), "G0 X100");
}

TEST(CyclesSpec_8_TV19, G73PatternRepeatOnTheInterpreter) {
  const auto h = runTurning("N10 G10.9 X1\n"
                            "N15 G18 G90 G95\n"
                            "N20 G0 X60 Z5\n"
                            "N30 G73.7 U4 W2 R3\n"
                            "N40 G73.7 P50 Q80 U0.4 W0.1 F0.25\n"
                            "N50 G0 X30 Z2\n"
                            "N60 G1 Z-15 F0.1\n"
                            "N70 X50 Z-25\n"
                            "N80 X60\n"
                            "N90 G0 X100 Z50\n");
  EXPECT_EQ(h.out.at("N40"),
            "G0 X38.4 Z4.1 | G1 Z-12.9 F0.25 | G1 X58.4 Z-22.9 F0.25 | G1 X68.4 F0.25 | "
            "G0 X60 Z5 | "
            "G0 X34.4 Z3.1 | G1 Z-13.9 F0.25 | G1 X54.4 Z-23.9 F0.25 | G1 X64.4 F0.25 | "
            "G0 X60 Z5 | "
            "G0 X30.4 Z2.1 | G1 Z-14.9 F0.25 | G1 X50.4 Z-24.9 F0.25 | G1 X60.4 F0.25 | "
            "G0 X60 Z5");
  EXPECT_EQ(h.out.at("N90"), "G0 X100 Z50");
}

// In G20 the lengths convert to mm, the pass count R3 of the first block does not.
TEST(CyclesSpec_4_10, G73PassCountIsNotConvertedFromInch) {
  const auto h = runTurning("N10 G10.9 X1\n"
                            "N15 G18 G20 G90 G95\n"
                            "N20 G0 X6 Z0.5\n"
                            "N30 G73.7 U0.4 W0.2 R3\n"
                            "N40 G73.7 P50 Q80 U0.04 W0.01 F0.01\n"
                            "N50 G0 X3 Z0.2\n"
                            "N60 G1 Z-1.5\n"
                            "N70 X5 Z-2.5\n"
                            "N80 X6\n");
  const std::string& out = h.out.at("N40");
  std::size_t passes = 0;
  for (std::size_t at = out.find("G0 X152.4 Z12.7"); at != std::string::npos;
       at = out.find("G0 X152.4 Z12.7", at + 1))
    ++passes; // each pass ends with the rapid back to A (6 in, 0.5 in)
  EXPECT_EQ(passes, 3u) << out;
  EXPECT_EQ(out.substr(0, out.find(" |")), "G0 X97.536 Z10.414"); // (3+0.8+0.04) in, 0.41 in
}

TEST(CyclesSpec_8_TV20, G74PeckDrillingOnTheInterpreter) {
  const auto h = runTurning("N10 G18 G90 G95\n"
                            "N20 G0 X0 Z3 S600 M3\n"
                            "N30 G74.7 R0.5\n"
                            "N40 G74.7 Z-12 Q4 F0.1\n");
  EXPECT_EQ(h.out.at("N40"), "G1 Z-1 F0.1 | G0 Z-0.5 | G1 Z-5 F0.1 | G0 Z-4.5 | G1 Z-9 F0.1 | "
                             "G0 Z-8.5 | G1 Z-12 F0.1 | G0 Z3");
}

TEST(CyclesSpec_8_TV21, G75GroovingOnTheInterpreter) {
  const auto h = runTurning("N10 G10.9 X1\n"
                            "N15 G18 G90 G95\n"
                            "N20 G0 X32 Z-5 S500 M3\n"
                            "N30 G75.7 R0.5\n"
                            "N40 G75.7 X20 Z-10 P3 Q2.5 F0.05\n");
  const std::string column = "G1 X26 F0.05 | G0 X27 | G1 X20 F0.05 | G0 X32";
  EXPECT_EQ(h.out.at("N40"),
            column + " | G0 Z-7.5 | " + column + " | G0 Z-10 | " + column + " | G0 Z-5");
}

TEST(CyclesSpec_8_TV22, G76ThreadingOnTheInterpreter) {
  const auto h = runTurning("N10 G10.9 X1\n"
                            "N15 G18 G90 G95 G97 S500 M3\n"
                            "N20 G0 X32 Z5\n"
                            "N30 G76.7 P010060 Q0.1 R0.05\n"
                            "N40 G76.7 X27.4 Z-20 P1.3 Q0.6 F2\n");
  std::string expected;
  for (const char* start : {"X28.8 Z4.6536", "X28.3029 Z4.5101", "X27.9215 Z4.4", "X27.6 Z4.3072",
                            "X27.5 Z4.2783", "X27.4 Z4.2494"})
    expected += std::string(expected.empty() ? "" : " | ") + "G0 " + start +
                " | G33 Z-20 F2 | G0 X32 | G0 Z5";
  EXPECT_EQ(h.out.at("N40"), expected);
}

TEST(CyclesSpec_8_TV23, G77ModalTurningCycleRepeats) { // 000:7221-7231, tool offsets left out
  const auto h = runTurning("N10 G10.9 X1\n"
                            "N20 G18 G95 G0 X101 Z1 S400 M3\n"
                            "N30 G77.7 X90 Z-30 R-3 F0.5\n"
                            "N40 X80\n"
                            "N50 X70\n"
                            "N60 G0 X200 Z100\n");
  EXPECT_EQ(h.out.at("N30"), "G0 X84 | G1 X90 Z-30 F0.5 | G1 X101 F0.5 | G0 Z1");
  EXPECT_EQ(h.out.at("N40"), "G0 X74 | G1 X80 Z-30 F0.5 | G1 X101 F0.5 | G0 Z1");
  EXPECT_EQ(h.out.at("N50"), "G0 X64 | G1 X70 Z-30 F0.5 | G1 X101 F0.5 | G0 Z1");
  EXPECT_EQ(h.out.at("N60"), "G0 X200 Z100"); // group 1 G0 ends the cycle
}

TEST(CyclesSpec_8_TV24, G78ThreadCycleRepeats) {
  const auto h = runTurning("N10 G10.9 X1\n"
                            "N15 G18 G90 G95 G97 S500 M3\n"
                            "N20 G0 X32 Z5\n"
                            "N30 G78.7 X29.2 Z-20 F2\n"
                            "N40 X28.6\n"
                            "N50 G0 X50\n");
  EXPECT_EQ(h.out.at("N30"), "G0 X29.2 | G33 Z-20 F2 | G0 X32 | G0 Z5");
  EXPECT_EQ(h.out.at("N40"), "G0 X28.6 | G33 Z-20 F2 | G0 X32 | G0 Z5");
  EXPECT_EQ(h.out.at("N50"), "G0 X50");
}

TEST(CyclesSpec_8_TV25, G79FacingCycleRepeats) {
  const auto h = runTurning("N10 G10.9 X1\n"
                            "N15 G18 G90 G95\n"
                            "N20 G0 X52 Z2\n"
                            "N30 G79.7 X20 Z-2 F0.2\n"
                            "N40 Z-4\n"
                            "N50 G0 X60 Z10\n");
  EXPECT_EQ(h.out.at("N30"), "G0 Z-2 | G1 X20 F0.2 | G1 Z2 F0.2 | G0 X52");
  EXPECT_EQ(h.out.at("N40"), "G0 Z-4 | G1 X20 F0.2 | G1 Z2 F0.2 | G0 X52");
  EXPECT_EQ(h.out.at("N50"), "G0 X60 Z10");
}

// TV-26 (000:10464-10531), the manual's own example in G19, end to end: the finishing pass
// G70.7 P110 Q170 runs N110-N170 under G41 with D2 = 0.4 (tool-centre path in the Y-Z plane,
// Y a diameter) and rounds N140/N150 with ,R5, offset to 4.6 (docs/compensation.md).
TEST(CyclesSpec_8_TV26, ManualExampleRunsWithCompensationAndRounding) {
  CycleHarness h;
  h.diameter = 2; // Y
  h.setup.tools[1].radius = 0.8;
  h.setup.tools[2].radius = 0.4;
  ASSERT_TRUE(h.run(readFile(sourceDir() / "tests/corpus/nct/spec/cycles-s8-tv26/O0001.nct")))
      << h.error();
  // N110 start-up: perpendicular to N120; N120/N130 and N130/N140 inner corners; N140 ends
  // where the rounding's centre (Y-25 Z34.641, radius 5 tangent to both) projects on it
  EXPECT_EQ(h.out["N110"], "G0 Y-79.2");
  EXPECT_EQ(h.out["N120"], "G1 Z50.1657 F1.5");
  EXPECT_EQ(h.out["N130"], "G1 Y-59.2 Z40.1657 F1.5");
  EXPECT_EQ(h.out["N140"], "G1 Z34.641 F1.5 | G3 Y-51.3143 Z30.0882 R4.6 F1.5");
  EXPECT_EQ(h.out["N150"], "G2 Y0.8 Z0 R30.4 F1.5"); // cancel: ends on its perpendicular
  EXPECT_EQ(h.out["N160"], "G1 Y0 Z-1 F1.5");
  EXPECT_EQ(h.out["N170"], "G1 Y4 F1.5");
}

// §4.11 inside a subprogram: a contour block's motion names the G70.7 and the call, once each.
TEST(CyclesSpec_4_11, G70ProvenanceNamesTheCycleAndTheCallOnce) {
  const MacroRun r = runMacro({{"O0001.nct", "G10.9 X1\nG18 G90 G95 G0 X60 Z2\nM98 P2\nM30\n"},
                               {"O0002.nct", "N10 G70.7 P50 Q60\nM99\nN50 G0 X30\n"
                                             "N60 G1 Z-20 F0.15\n"}},
                              "O0001.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  const auto feed = std::find_if(r.events.begin(), r.events.end(), [](const motion::Event& e) {
    return e.kind == motion::Kind::Feed;
  });
  ASSERT_NE(feed, r.events.end());
  EXPECT_EQ(feed->from.at.line, 4u);
  ASSERT_EQ(feed->from.chain.size(), 2u);
  EXPECT_EQ(feed->from.chain[0].what, "O0002 (M98 P2)");
  EXPECT_EQ(feed->from.chain[1].what, "G70.7 P50 Q60");
  EXPECT_EQ(feed->from.chain[1].call.line, 1u);
}

// --- §7 errors the interpreter owns -------------------------------------------------------

TEST(CyclesSpec_8_TV32, E7MissingContourBlockIsPQNotFound) {
  EXPECT_EQ(failing("G18 G90 G0 X40 Z2\n"
                    "G71.7 U2 R1\n"
                    "G71.7 P900 Q910 U0.2 W0.1 F0.2\n"),
            "#3 CYC-PQ-NOTFOUND 3:7");
}

TEST(CyclesSpec_4_7, ForbiddenCommandInsideTheContour) {
  EXPECT_EQ(failing("N1 G18 G90 G0 X40 Z2\n"
                    "N2 G71.7 U2 R1\n"
                    "N3 G71.7 P4 Q6 U0.2 W0.1 F0.2\n"
                    "N4 G0 X20\n"
                    "N5 G1 Z-10 M8\n"
                    "N6 X40\n"),
            "N5 CYC-CONTOUR-CMD 5:12");
}

TEST(CyclesSpec_4_7, G70WithoutQIsPQNotFound) {
  EXPECT_EQ(failing("N1 G18 G90 G0 X40 Z2\nN2 G70.7 P4\n"), "N2 CYC-PQ-NOTFOUND 2:4");
}

// The contour blocks resolve like any block: an incremental W and an arc by R (§4.7). The G2
// from (z-10, x10) to (z-20, x20) with R10 turns about (z-10, x20); level x15 meets it where
// (z+10)² = 10² - 5², at z = -10 - 8.6603.
TEST(CyclesSpec_4_8, ContourWithIncrementalWordsAndAnArc) {
  const auto h = runTurning("N10 G10.9 X1\n"
                            "N15 G18 G90 G95\n"
                            "N20 G0 X50 Z2\n"
                            "N30 G71.7 U5 R1\n"
                            "N40 G71.7 P50 Q80 U0 W0 F0.2\n"
                            "N50 G0 X20\n"
                            "N60 G1 W-12 F0.1\n"
                            "N70 G2 X40 W-10 R10\n"
                            "N80 G1 X50\n");
  EXPECT_EQ(h.out.at("N40"), "G0 X40 | G1 Z-20 F0.2 | G0 X42 Z-19 | G0 Z2 | "
                             "G0 X30 | G1 Z-18.6603 F0.2 | G0 X32 Z-17.6603 | G0 Z2 | "
                             "G0 X20 | G1 Z-10 F0.2 | G2 X40 Z-20 R10 F0.2 | G1 X50 F0.2 | "
                             "G0 Z2");
}

} // namespace
} // namespace gcx::test
