// NCT drilling cycles: every drilling vector of cycles.md §8 (TV-01 to TV-16, TV-30, TV-31 and
// the errors E1-E6 of TV-32) with its exact motion, run on the interpreter (drill_harness.h).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cycles/cycle_harness.h"
#include "cycles/drilling.h"
#include "diag/codes.h"

namespace gcx::test {
namespace {

using cycles::DrillCycle;

std::string repeat(const std::string& s, int n, const std::string& sep = " | ") {
  std::string out;
  for (int i = 0; i < n; ++i)
    out += (i ? sep : "") + s;
  return out;
}

TEST(CyclesSpec_8_TV01, G81ReturnLevelsAndG80RestoresGroup1) {
  const auto h = run("N1 G17 G90 G94 G0 X0 Y0 Z50\n"
                     "N2 G99 G81 X10 Y10 Z-5 R2 F120\n"
                     "N3 X20\n"
                     "N4 G98 Y20 Z-8\n"
                     "N5 G80\n"
                     "N6 X0 Y0\n");
  EXPECT_EQ(h.out.at("N1"), "G0 Z50");
  EXPECT_EQ(h.out.at("N2"), "G0 X10 Y10 | G0 Z2 | G1 Z-5 F120 | G0 Z2");
  EXPECT_EQ(h.out.at("N3"), "G0 X20 | G1 Z-5 F120 | G0 Z2");
  EXPECT_EQ(h.out.at("N4"), "G0 Y20 | G1 Z-8 F120 | G0 Z50");
  EXPECT_EQ(h.out.count("N5"), 0u);
  EXPECT_EQ(h.out.at("N6"), "G0 X0 Y0");
}

// The vector's added line is "N0 G94 F100"; N0 is outside NCT's block numbers 1-99999999
// (error 2002), so the line goes without a number here.
TEST(CyclesSpec_8_TV02, InitialLevelRegisteredOnce) {
  const auto h = run("G94 F100\n"
                     "N1 G17 G90 G0 Z200\n"
                     "N2 G81 X0 Y0 Z50 R150\n"
                     "N3 X100 Y30 Z80\n"
                     "N4 G80\n");
  EXPECT_EQ(h.out.at("N1"), "G0 Z200");
  EXPECT_EQ(h.out.at("N2"), "G0 Z150 | G1 Z50 F100 | G0 Z200");
  EXPECT_EQ(h.out.at("N3"), "G0 X100 Y30 | G0 Z150 | G1 Z80 F100 | G0 Z200");
}

TEST(CyclesSpec_8_TV03, RepetitionWithG91) {
  const auto h = run("N1 G90 G17 G0 X0 Y0 Z100 M3\n"
                     "N2 G91 G81 X100 Z-40 R-97 F50 L5\n");
  EXPECT_EQ(h.out.at("N1"), "G0 Z100 | M3");
  std::string holes;
  for (int x = 100; x <= 500; x += 100)
    holes += fmt::format("{}G0 X{} | G0 Z3 | G1 Z-37 F50 | G0 Z100", x > 100 ? " | " : "", x);
  EXPECT_EQ(h.out.at("N2"), holes); // re-emitting G91 afterwards is the emitter's (§1.2)
}

TEST(CyclesSpec_8_TV03, VariantBSameHoleFiveTimesWithG90) {
  const auto h = run("N1 G90 G17 G0 X0 Y0 Z100 M3\n"
                     "N2 G90 G81 X100 Z-37 R3 F50 L5\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X100 | " + repeat("G0 Z3 | G1 Z-37 F50 | G0 Z100", 5));
}

// Polar holes follow the G16 rules (000:2605-2660), not the manual's remark.
TEST(CyclesSpec_8_TV04, PolarPatternWithL) {
  const auto h = run("N1 G90 G17 G16 G0 X200 Y-60 Z50\n"
                     "N2 G81 YI60 Z-40 R3 F50 L6\n");
  EXPECT_EQ(h.out.at("N1"), "G0 X100 Y-173.2051 Z50");
  const char* holes[] = {"G0 X200 Y0",  "G0 X100 Y173.2051",   "G0 X-100",
                         "G0 X-200 Y0", "G0 X-100 Y-173.2051", "G0 X100"};
  std::string expected;
  for (const char* hole : holes)
    expected +=
        (expected.empty() ? "" : " | ") + std::string(hole) + " | G0 Z3 | G1 Z-40 F50 | G0 Z50";
  EXPECT_EQ(h.out.at("N2"), expected);
}

// `,A` is resolved by the interpreter (000:8957-8965): G91 X100 ,A30 is the hole (100, 57.735).
TEST(CyclesSpec_8_TV05, DirectionAngleInACycle) {
  diag::Engine diags;
  cycles::DrillModal modal;
  cycles::DrillWords w;
  w.code = DrillCycle::Drill;
  w.holeWord = true;
  w.axisPosition = 10;
  w.vars.r = val(-2, true);
  w.vars.z = val(-25, true);
  ASSERT_EQ(cycles::updateModal(modal, w, diags), 1);
  cycles::DrillRequest req;
  req.position = cycles::Vec3(0, 0, 10);
  req.hole = cycles::Vec3(100, 100 * std::tan(std::numbers::pi / 6), 0);
  req.initial = *modal.initial;
  req.vars = modal.vars;
  req.feed = 100;
  const auto res = cycles::expandHole(req, {}, {}, diags);
  ASSERT_TRUE(res);
  EXPECT_EQ(cycles::opsText(req.position, res->ops),
            "G0 X100 Y57.735 | G0 Z8 | G1 Z-17 F100 | G0 Z10");
}

TEST(CyclesSpec_8_TV06, G73NewQG80ClearsEAndRestoresG98) {
  const auto h = run("N1 G17 G90 G0 X0 Y0 Z10\n"
                     "N2 G99 G73 X5 Y5 Z-7 R2 Q3 E0.4 F80\n"
                     "N3 X15 Q4\n"
                     "N4 G80\n"
                     "N5 G73 X25 Y5 Z-4 R1 Q2.5 F100\n"
                     "N6 G80\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X5 Y5 | G0 Z2 | G1 Z-1 F80 | G0 Z-0.6 | G1 Z-4 F80 | G0 Z-3.6 | "
                            "G1 Z-7 F80 | G0 Z2");
  EXPECT_EQ(h.out.at("N3"),
            "G0 X15 | G1 Z-2 F80 | G0 Z-1.6 | G1 Z-6 F80 | G0 Z-5.6 | G1 Z-7 F80 | G0 Z2");
  EXPECT_EQ(h.out.at("N5"), "G0 X25 | G0 Z1 | G1 Z-1.5 F100 | G0 Z-1 | G1 Z-4 F100 | G0 Z2");
}

TEST(CyclesSpec_8_TV07, G83WithEThenASinglePeck) {
  const auto h = run("N1 G17 G90 G0 X0 Y0 Z20\n"
                     "N2 G83 X5 Y5 Z-12 R1 Q5 E0.5 F100\n"
                     "N3 X15 Z-3\n"
                     "N4 G80\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X5 Y5 | G0 Z1 | G1 Z-4 F100 | G0 Z1 | G0 Z-3.5 | G1 Z-9 F100 | "
                            "G0 Z1 | G0 Z-8.5 | G1 Z-12 F100 | G0 Z20");
  EXPECT_EQ(h.out.at("N3"), "G0 X15 | G0 Z1 | G1 Z-3 F100 | G0 Z20");
}

TEST(CyclesSpec_8_TV08, G82DwellAndG04KeepsTheCycleP) {
  const auto h = run("N1 G17 G90 G94 G0 X0 Y0 Z30\n"
                     "N2 G82 X10 Y0 Z-6 R2 P1.5 F150\n"
                     "N3 G4 P3\n"
                     "N4 X20\n"
                     "N5 G80\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X10 | G0 Z2 | G1 Z-6 F150 | G4 P1.5 | G0 Z30");
  EXPECT_EQ(h.out.at("N3"), "G4 P3");
  EXPECT_EQ(h.out.at("N4"), "G0 X20 | G0 Z2 | G1 Z-6 F150 | G4 P1.5 | G0 Z30");
}

TEST(CyclesSpec_8_TV09, G84FloatingTapUnderG98) { // §3.8
  const auto h = run("N1 G17 G90 G94 G0 X0 Y0 Z30 S500 M3\n"
                     "N2 G84 X20 Y10 Z-15 R5 P0.2 F625\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X20 Y10 | G0 Z5 | G63 | G1 Z-15 F625 | G4 P0.2 | M4 | "
                            "G1 Z5 F625 | M3 | G64 | G0 Z30");
  EXPECT_TRUE(h.warnings.empty());
}

TEST(CyclesSpec_8_TV09, G74FloatingTapUnderG99) { // §3.4
  const auto h = run("N1 G17 G90 G95 G0 X0 Y0 Z30 S400 M4\n"
                     "N2 G99 G74 X0 Y-10 Z-12 R3 F1.5\n");
  EXPECT_EQ(h.out.at("N2"), "G0 Y-10 | G0 Z3 | G63 | G1 Z-12 F1.5 | M3 | G1 Z3 F1.5 | M4 | G64");
  EXPECT_TRUE(h.warnings.empty());
}

TEST(CyclesSpec_8_TV10, G85OverrideIFKeptAcrossG80) {
  const auto h = run("N1 G17 G90 G94 G1 X0 Y0 Z10 F500\n"
                     "N2 G85 X5 Y0 Z-10 R1 F100 I200\n"
                     "N3 G80 X0\n"
                     "N4 G85 X15 Y0 Z-10 R1\n"
                     "N5 G80\n");
  EXPECT_EQ(h.out.at("N1"), "G1 Z10 F500");
  EXPECT_EQ(h.out.at("N2"), "G0 X5 | G0 Z1 | G1 Z-10 F100 | G1 Z1 F200 | G0 Z10");
  EXPECT_EQ(h.out.at("N3"), "G1 X0 F100");
  EXPECT_EQ(h.out.at("N4"), "G0 X15 | G0 Z1 | G1 Z-10 F100 | G1 Z1 F100 | G0 Z10");
}

TEST(CyclesSpec_8_TV11, G86) {
  const auto h = run("N1 G17 G90 G0 X0 Y0 Z25 S600 M3\n"
                     "N2 G99 G86 X12 Y8 Z-9 R2 F90\n"
                     "N3 G80\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X12 Y8 | G0 Z2 | G1 Z-9 F90 | M5 | G0 Z2 | M3");
}

TEST(CyclesSpec_8_TV12, G89) {
  const auto h = run("N1 G17 G90 G94 G0 X0 Y0 Z15\n"
                     "N2 G89 X0 Y20 Z-7 R1.5 P0.8 F70\n"
                     "N3 G80\n");
  EXPECT_EQ(h.out.at("N2"), "G0 Y20 | G0 Z1.5 | G1 Z-7 F70 | G4 P0.8 | G1 Z1.5 F70 | G0 Z15");
}

TEST(CyclesSpec_8_TV13, G87VariantAAndG88CarryZRF) {
  cycles::DrillConfig ori0;
  ori0.orient = false;
  const auto h = run("N1 G17 G90 G0 X0 Y0 Z50 S500 M3\n"
                     "N2 G99 G87 X10 Y0 Z-5 R2 F40\n"
                     "N3 G98 G88 X20 P2\n"
                     "N4 G80\n",
                     ori0);
  EXPECT_EQ(h.out.at("N2"), "G0 X10 | G0 Z2 | G1 Z-5 F40 | M5 | M0 | G0 Z2 | M3");
  EXPECT_EQ(h.out.at("N3"), "G0 X20 | G1 Z-5 F40 | G4 P2 | M5 | M0 | G0 Z50 | M3");
}

constexpr const char* kTv14 = "N1 G17 G90 G94 G0 X0 Y0 Z50 S800 M3\n"
                              "N2 G76 X40 Y30 Z-20 R2 I0.3 J-0.2 P1 F60\n"
                              "N3 G99 X60\n"
                              "N4 G80\n";

TEST(CyclesSpec_8_TV14, G76UnderG98ThenG99) {
  const auto h = run(kTv14);
  EXPECT_EQ(h.out.at("N2"), "G0 X40 Y30 | G0 Z2 | G1 Z-20 F60 | G4 P1 | M19 | G0 X40.3 Y29.8 | "
                            "G0 Z50 | G0 X40 Y30 | M3");
  EXPECT_EQ(h.out.at("N3"), "G0 X60 | G0 Z2 | G1 Z-20 F60 | G4 P1 | M19 | G0 X60.3 Y29.8 | "
                            "G0 Z2 | G0 X60 Y30 | M3");
}

TEST(CyclesSpec_8_TV14, WithoutOrientationIsError2137) {
  CycleHarness h;
  h.config.orient = false;
  EXPECT_FALSE(h.run(kTv14));
  EXPECT_EQ(h.error(), "N2 2137 2:1");
}

TEST(CyclesSpec_8_TV15, G87VariantBBackBoring) { // §3.10
  const auto h = run("N1 G17 G90 G0 X0 Y0 Z50 S700 M3\n"
                     "N2 G87 X10 Y0 Z-5 R-25 I-0.5 F40\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X10 | M19 | G0 X9.5 | G0 Z-25 | G0 X10 | M3 | G1 Z-5 F40 | "
                            "M19 | G0 X9.5 | G0 Z50 | G0 X10 | M3");
}

// The motion trace has no RTAP: a rigid tap is a spindle-synchronised feed (G33, lead F/S)
// with the spindle turning its way; M24 (close the position loop, N0823) moves nothing and is
// not in the trace. The reverse direction shows as M4, the next tap's as M3 (§3.9 lowering),
// and the spindle stands after the last tap, as in position control (000:9969-9971).
TEST(CyclesSpec_8_TV16, G84_2RigidTapWithoutAndWithQ) {
  const auto h = run("N1 G17 G90 G94 G0 X0 Y0 Z20 S1000 M3\n"
                     "N2 G84.2 X10 Y10 Z-10 R3 F1500\n"
                     "N3 X30 Q5\n"
                     "N4 G80\n");
  const std::string in = " F1500 S1000 DIR=CW", out = " F1500 S1000 DIR=CCW";
  EXPECT_EQ(h.out.at("N2"),
            "G0 X10 Y10 | G0 Z3 | RTAP Z-10" + in + " | M4 | RTAP Z3" + out + " | M5 | G0 Z20");
  EXPECT_EQ(h.out.at("N3"), "G0 X30 | G0 Z3 | M3 | RTAP Z-2" + in + " | M4 | RTAP Z-1.5" + out +
                                " | M3 | RTAP Z-7" + in + " | M4 | RTAP Z-6.5" + out +
                                " | M3 | RTAP Z-10" + in + " | M4 | RTAP Z3" + out +
                                " | M5 | G0 Z20");
}

TEST(CyclesSpec_8_TV30, ModalCarryOverG80AndGroup1Cancel) {
  const auto h = run("N1 G17 G90 G0 X0 Y0 Z50 M3\n"
                     "N2 G81 X10 Y10 Z-5 R2 F100\n"
                     "N3 X30\n"
                     "N4 G82 Y30 Z-8 P0.5\n"
                     "N5 G80 M5\n"
                     "N6 G85 Y50 Z-6 R3 P1 M3\n"
                     "N7 G0 X0\n");
  EXPECT_EQ(h.out.at("N1"), "G0 Z50 | M3");
  EXPECT_EQ(h.out.at("N2"), "G0 X10 Y10 | G0 Z2 | G1 Z-5 F100 | G0 Z50");
  EXPECT_EQ(h.out.at("N3"), "G0 X30 | G0 Z2 | G1 Z-5 F100 | G0 Z50");
  EXPECT_EQ(h.out.at("N4"), "G0 Y30 | G0 Z2 | G1 Z-8 F100 | G4 P0.5 | G0 Z50");
  EXPECT_EQ(h.out.at("N5"), "M5");
  EXPECT_EQ(h.out.at("N6"), "G0 Y50 | M3 | G0 Z3 | G1 Z-6 F100 | G1 Z3 F100 | G0 Z50");
  EXPECT_EQ(h.out.at("N7"), "G0 X0");
}

TEST(CyclesSpec_8_TV31, L0StoresWithoutDrilling) {
  const auto h = run("N1 G17 G90 G0 X0 Y0 Z20\n"
                     "N2 G81 Z-3 R1 F60 L0\n"
                     "N3 X10 Y5\n"
                     "N4 G80\n");
  EXPECT_EQ(h.out.count("N2"), 0u);
  EXPECT_EQ(h.out.at("N3"), "G0 X10 Y5 | G0 Z1 | G1 Z-3 F60 | G0 Z20");
}

// --- TV-32: error vectors (after `G17 G90 G0 X0 Y0 Z20`) -----------------------------------

// After `G17 G90 G0 X0 Y0 Z20`.
std::string failingAfterStart(const std::string& blocks, cycles::DrillConfig config = {},
                              bool wIsAxis = false) {
  return failing("G17 G90 G0 X0 Y0 Z20\n" + blocks, config, wIsAxis);
}

TEST(CyclesSpec_8_TV32, E1NoZOrRIsError2053) {
  EXPECT_EQ(failingAfterStart("G81 X10 Y10 F100\n"), "#2 2053 2:1");
}

TEST(CyclesSpec_8_TV32, E2DrillingAxisChangedWithoutRIsError2053) {
  EXPECT_EQ(failingAfterStart("G81 X0 Y0 Z-5 R2 F100\nG18 X5\n"), "#3 2053 3:1");
}

// The vector gives no F; F100 is added to the first block so that N2 can drill.
TEST(CyclesSpec_8_TV32, E2bNewDrillingAxisWWithoutRIsError2053) {
  EXPECT_EQ(failingAfterStart("F100\nG0 Z200 W50\nG81 X0 Y0 Z50 R150\nX100 Y30 W20\n", {}, true),
            "#5 2053 5:1");
}

TEST(CyclesSpec_8_TV32, E2bWithRDrillsFromTheInitialLevelOfW) {
  CycleHarness h;
  h.wIsAxis = true;
  ASSERT_TRUE(h.run("G17 G90 G0 X0 Y0 Z20 F100\n"
                    "G0 Z200 W50\n"
                    "G81 X0 Y0 Z50 R150\n"
                    "X100 Y30 W20 R25\n"))
      << h.error();
  EXPECT_EQ(h.out.at("#3"), "G0 Z150 | G1 Z50 F100 | G0 Z200");
  EXPECT_EQ(h.out.at("#4"), "G0 X100 Y30 | G0 W25 | G1 W20 F100 | G0 W50");
}

TEST(CyclesSpec_8_TV32, E3G76WithoutOrientationIsError2137) {
  cycles::DrillConfig c;
  c.orient = false;
  EXPECT_EQ(failingAfterStart("G76 X10 Z-5 R2 F50\n", c), "#2 2137 2:1");
}

TEST(CyclesSpec_8_TV32, E4RigidTapWithoutIndexingIsError2138) {
  cycles::DrillConfig c;
  c.indexable = false;
  EXPECT_EQ(failingAfterStart("G84.2 X10 Z-5 R2 F500 S500\n", c), "#2 2138 2:1");
}

TEST(CyclesSpec_8_TV32, E5G83WithoutQ) {
  EXPECT_EQ(failingAfterStart("G83 X10 Z-5 R2 F100\n"), "#2 CYC-Q-MISSING 2:1");
}

// G7.1 itself is not executed yet, so a drilling cycle can never run inside it; the cycle's own
// check (expandHole with cylindrical set) is in drilling_rules_test.
TEST(CyclesSpec_8_TV32, E6DrillingInCylindricalInterpolation) {
  EXPECT_EQ(failingAfterStart("G17 X0 A0\nG7.1 A28.65\nG81 X0 Z-5 R2\n"), "#3 GCX030 3:1");
}

} // namespace
} // namespace gcx::test
