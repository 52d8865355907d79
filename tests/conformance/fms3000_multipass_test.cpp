// The FMS-3000 multi-pass turning cycles of fms3000.md §5.3: G152 and G153 (Tables 21, 22) and
// G162 (Table 31), reconstructions [R] of the spec. Each motion is worked by hand from the
// rules written in src/cycles/level_multipass.cpp and level_thread.cpp (machine coordinates,
// 4 decimals; a diameter-programmed X shows as its radius), and every bad parameter is a located
// error.
#include <gtest/gtest.h>

#include <cmath>

#include "support/fms3000_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

machine::Setup diameterX() {
  machine::Setup s;
  s.parameters["N7006"] = 1;
  return s;
}

V run(const std::string& program, const machine::Setup& setup = {}) {
  const MacroRun r = runFms(program, setup);
  EXPECT_EQ(r.errors, V{}) << r.rendered;
  V m = r.motion();
  if (!m.empty() && m.back() == "END") m.pop_back();
  return m;
}

V errorsOf(const std::string& program) {
  return runFms(program).errors;
}

// G152 X20 Z-30 Q4 from X30 Z2: levels 26 and 22 (18 lies beyond X), the finishing pass on X20
const V kG152{"R 30,0,2",        "L 26,0,2 F100",   "L 26,0,-30 F100", "R 26,0,2",
              "L 22,0,2 F100",   "L 22,0,-30 F100", "R 22,0,2",        "L 20,0,2 F100",
              "L 20,0,-30 F100", "R 20,0,2",        "R 30,0,2"};

TEST(FmsSpec_5_3_G152, PassesEveryQThenTheFinishingPassOnX_Table21) {
  EXPECT_EQ(run("G18 G90 G0 X30 Z2\nG152 X20 Z-30 Q4 F100\nM30\n"), kG152);
  // the cycle works on X and Z whatever the plane
  EXPECT_EQ(run("G90 G0 X30 Z2\nG152 X20 Z-30 Q4 F100\nM30\n"), kG152);
  // G91: X and Z are distances from И.Т.
  EXPECT_EQ(run("G18 G0 X30 Z2\nG91 G152 X-10 Z-32 Q4 F100\nM30\n"), kG152);
}

TEST(FmsSpec_5_3_G152, RapidFlagRetractDAndEndAtTheXLevelY_Table21) {
  // diameters X60 X40 Q8 D1 are radii 30 20 4 0.5; each pass: rapid X to the level (G0), Z to
  // Z-10, rapid X by D, rapid Z back; Y: the cycle ends after the finishing pass, at X
  EXPECT_EQ(run("G18 G0 X60 Z2\nG152 X40 Z-10 Q8 D1 G0 Y1 F100\nM30\n", diameterX()),
            (V{"R 30,0,2", "R 26,0,2", "L 26,0,-10 F100", "R 26.5,0,-10", "R 26.5,0,2", "R 22,0,2",
               "L 22,0,-10 F100", "R 22.5,0,-10", "R 22.5,0,2", "R 20,0,2", "L 20,0,-10 F100",
               "R 20.5,0,-10", "R 20.5,0,2"}));
}

TEST(FmsSpec_5_3_G152, ChipBreakingVWOnEveryCutAlongZ_Table21) {
  // V4 W1: the G86 steps along Z (-4, back to -3, -8, back to -7, -10) on the level 17 and on
  // the finishing pass at X16
  EXPECT_EQ(
      run("G18 G0 X20 Z0\nG91 G152 X-4 Z-10 Q3 V4 W1 F50\nM30\n"),
      (V{"R 20,0,0", "L 17,0,0 F50", "L 17,0,-4 F50", "R 17,0,-3", "L 17,0,-8 F50", "R 17,0,-7",
         "L 17,0,-10 F50", "R 17,0,0", "L 16,0,0 F50", "L 16,0,-4 F50", "R 16,0,-3",
         "L 16,0,-8 F50", "R 16,0,-7", "L 16,0,-10 F50", "R 16,0,0", "R 20,0,0"}));
}

TEST(FmsSpec_5_3_G153, PassesAlongZThenTheFinishingPassOnZ_Table22) {
  // levels Z-1 and Z-4 every 3 from Z2 (Z-7 lies beyond Z-5), each cut along X to X10; D along Z
  EXPECT_EQ(run("G18 G0 X30 Z2\nG153 X10 Z-5 Q3 D0.5 F100\nM30\n"),
            (V{"R 30,0,2", "L 30,0,-1 F100", "L 10,0,-1 F100", "R 10,0,-0.5", "R 30,0,-0.5",
               "L 30,0,-4 F100", "L 10,0,-4 F100", "R 10,0,-3.5", "R 30,0,-3.5", "L 30,0,-5 F100",
               "L 10,0,-5 F100", "R 10,0,-4.5", "R 30,0,-4.5", "R 30,0,2"}));
}

TEST(FmsSpec_5_3_G153, ChipBreakingAlongXInDiameters_Table22) {
  // X20 V8 W2 are radii 10 4 1; the level Z-2 is Z itself: only the finishing pass, its cut
  // along X in steps of 4 with a rapid back by 1
  EXPECT_EQ(run("G18 G0 X60 Z0\nG153 X20 Z-2 Q2 V8 W2 F100\nM30\n", diameterX()),
            (V{"R 30,0,0", "L 30,0,-2 F100", "L 26,0,-2 F100", "R 27,0,-2", "L 22,0,-2 F100",
               "R 23,0,-2", "L 18,0,-2 F100", "R 19,0,-2", "L 14,0,-2 F100", "R 15,0,-2",
               "L 10,0,-2 F100", "R 30,0,-2", "R 30,0,0"}));
}

TEST(FmsSpec_5_3_G152, BadParametersAreLocatedErrors) {
  const std::string at = "G18 G0 X30 Z2\n";
  // Q, the depth per pass, is mandatory (001:3943-3945)
  EXPECT_EQ(errorsOf(at + "G152 X20 Z-30 F100\nM30\n"), V{"main.fms:2:1 FMSX02"});
  // V without W (001:3950-3953)
  EXPECT_EQ(errorsOf(at + "G152 X20 Z-30 Q4 V2 F100\nM30\n"), V{"main.fms:2:1 FMSX02"});
  // no travel along X (001:3965-3966), along Z for G153 (001:3967-3968)
  EXPECT_EQ(errorsOf(at + "G152 X30 Z-30 Q4 F100\nM30\n"), V{"main.fms:2:1 FMSX02"});
  EXPECT_EQ(errorsOf(at + "X20 G153 X10 Z2 Q1 F100\nM30\n"), V{"main.fms:2:5 FMSX02"});
  // a word that is no parameter of G152
  EXPECT_EQ(errorsOf(at + "G152 X20 Z-30 Q4 R1 F100\nM30\n"), V{"main.fms:2:1 FMSX02"});
  // Q 0 would never reach X
  EXPECT_EQ(errorsOf(at + "G152 X20 Z-30 Q0 F100\nM30\n"), V{"main.fms:2:1 FMSX02"});
  // the cone: the manual gives its length P but not its other end (fms3000.md §10 Q10)
  EXPECT_EQ(errorsOf(at + "G152 X20 Z-30 Q4 P5 F100\nM30\n"), V{"main.fms:2:1 GCX030"});
  EXPECT_EQ(errorsOf(at + "G153 X10 Z-5 Q1 P5 F100\nM30\n"), V{"main.fms:2:1 GCX030"});
}

// G162 from X30 Z5 to X24 Z-20 at H300 with the spindle on: X is the thread's end point
TEST(FmsSpec_5_3_G162, SinglePassCylindricalThread_Table31) {
  const MacroRun r = runFms("G18 G0 X30 Z5\nM3 S200\nG162 X24 Z-20 H300 F1.5\nM30\n");
  ASSERT_EQ(r.errors, V{}) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 30,0,5", "EV S200 M3", "L 24,0,5 F300", "L 24,0,-20 F1.5",
                           "L 30,0,-20 F300", "L 30,0,5 F300", "END"}));
  int synchronised = 0; // the thread follows the spindle at 1.5 mm per revolution
  for (const motion::Event& e : r.events)
    synchronised += e.kind == motion::Kind::Feed && e.lead == 1.5;
  EXPECT_EQ(synchronised, 1);
}

TEST(FmsSpec_5_3_G162, DepthsQThenTheRestSplitInHalves_Table31) {
  // P1.3 Q0.5: 0.5, 1.0, then B = 0.3 as B/2, B/4, B/8 and the rest (001:3190-3199):
  // 1.15, 1.225, 1.2625, 1.3; X is the start of the multi-pass thread
  std::string out;
  V expected{"R 30,0,5", "EV S200 M3"};
  for (const char* x : {"23.5", "23", "22.85", "22.775", "22.7375", "22.7"}) {
    const std::string at = x;
    for (const std::string& m : {"L " + at + ",0,5 F300", "L " + at + ",0,-20 F2",
                                 std::string("L 30,0,-20 F300"), std::string("L 30,0,5 F300")})
      expected.push_back(m);
  }
  EXPECT_EQ(run("G18 G0 X30 Z5\nM3 S200\nG162 X24 Z-20 H300 P1.3 Q0.5 F2\nM30\n"), expected);
}

TEST(FmsSpec_5_3_G162, InfeedAngleShiftsEachPassAlongZ_Table31) {
  // A30 (counterclockwise): an external thread's pass at depth d starts d*tan(30°) toward +Z
  EXPECT_EQ(run("G18 G0 X30 Z5\nM3 S200\nG162 X24 Z-20 H300 P1 Q0.5 A30 F1.5\nM30\n"),
            (V{"R 30,0,5", "EV S200 M3", "L 30,0,5.2887 F300", "L 23.5,0,5.2887 F300",
               "L 23.5,0,-20 F1.5", "L 30,0,-20 F300", "L 30,0,5 F300", "L 30,0,5.5774 F300",
               "L 23,0,5.5774 F300", "L 23,0,-20 F1.5", "L 30,0,-20 F300", "L 30,0,5 F300"}));
  // clockwise: toward -Z
  EXPECT_EQ(run("G18 G0 X30 Z5\nM3 S200\nG162 X24 Z-20 H300 P0.5 Q0.5 A-30 F1.5\nM30\n"),
            (V{"R 30,0,5", "EV S200 M3", "L 30,0,4.7113 F300", "L 23.5,0,4.7113 F300",
               "L 23.5,0,-20 F1.5", "L 30,0,-20 F300", "L 30,0,5 F300"}));
}

TEST(FmsSpec_5_3_G162, InternalThreadUnderG91_Table31) {
  // X4 Z-15 from X10 Z5: an approach toward +X, the passes 0.2 and 0.4 deeper along +X
  EXPECT_EQ(run("G18 G0 X10 Z5\nM4 S100\nG91 G162 X4 Z-15 H200 P0.4 Q0.2 F1\nM30\n"),
            (V{"R 10,0,5", "EV S100 M4", "L 14.2,0,5 F200", "L 14.2,0,-10 F1", "L 10,0,-10 F200",
               "L 10,0,5 F200", "L 14.4,0,5 F200", "L 14.4,0,-10 F1", "L 10,0,-10 F200",
               "L 10,0,5 F200"}));
}

// E44 (001:3185-3189): a 2 mm pitch on a 50 mm cone whose diameters differ by 20 is F1.961, the
// pitch along Z (the axis of the longer travel). Here in diameters (N7006 = 1): X30 W-20 are the
// radii 15 and -10 over Z2..-48, with a 45° run-out V2 at the end: the thread line reaches X5.4
// at Z-46, the run-out leaves it by 2 to X7.4 at Z-48.
TEST(FmsSpec_5_3_G162, E44TaperPitchAlongTheLongerTravelAndTheRunOut) {
  const MacroRun r =
      runFms("G18 G0 X40 Z2\nM3 S100\nG162 X30 Z-48 H500 W-20 V2 F1.961\nM30\n", diameterX());
  ASSERT_EQ(r.errors, V{}) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 20,0,2", "EV S100 M3", "L 15,0,2 F500", "L 5.4,0,-46 F1.961",
                           "L 7.4,0,-48 F1.961", "L 20,0,-48 F500", "L 20,0,2 F500", "END"}));
  const motion::Event* cone = nullptr;
  for (const motion::Event& e : r.events)
    if (e.kind == motion::Kind::Feed && e.lead > 0 && !cone) cone = &e;
  ASSERT_NE(cone, nullptr);
  // along the cone's line the pitch is the manual's 2 mm (F = 2*50/sqrt(50^2 + 10^2) = 1.961)
  const double dz = std::abs(cone->end.z() - cone->start.z());
  EXPECT_NEAR(cone->lead * (cone->end - cone->start).norm() / dz, 2.0, 0.001);
  EXPECT_NEAR(2 * 50 / std::sqrt(50.0 * 50 + 10 * 10), 1.961, 0.0005);
  // a steep taper: W-20 over 10 along Z, F2 leads X, so Z covers 1 mm per revolution
  EXPECT_EQ(run("G18 G0 X30 Z5\nM3 S100\nG162 X20 Z-5 H100 W-20 F2\nM30\n"),
            (V{"R 30,0,5", "EV S100 M3", "L 20,0,5 F100", "L 0,0,-5 F1", "L 30,0,-5 F100",
               "L 30,0,5 F100"}));
}

TEST(FmsSpec_5_3_G162, BadParametersAreLocatedErrors) {
  const std::string at = "G18 G0 X30 Z5\nM3 S200\n";
  // X, Z and H are mandatory (001:3940-3941)
  EXPECT_EQ(errorsOf(at + "G162 X24 Z-20 F1.5\nM30\n"), V{"main.fms:3:1 FMSX02"});
  // P without Q (001:3946-3949)
  EXPECT_EQ(errorsOf(at + "G162 X24 Z-20 H300 P1 F1.5\nM30\n"), V{"main.fms:3:1 FMSX02"});
  // no travel along X or along Z (001:3965-3968)
  EXPECT_EQ(errorsOf(at + "G162 X30 Z-20 H300 F1.5\nM30\n"), V{"main.fms:3:1 FMSX02"});
  EXPECT_EQ(errorsOf(at + "X28 G162 X24 Z5 H300 F1.5\nM30\n"), V{"main.fms:3:5 FMSX02"});
  // the spindle must turn for a synchronised cut
  EXPECT_EQ(errorsOf("G18 G0 X30 Z5\nG162 X24 Z-20 H300 F1.5\nM30\n"), V{"main.fms:2:1 FMSX02"});
  // a run-out as long as the thread, an infeed angle of 90°, a pitch of 0
  EXPECT_EQ(errorsOf(at + "G162 X24 Z-20 H300 V25 F1.5\nM30\n"), V{"main.fms:3:1 FMSX02"});
  EXPECT_EQ(errorsOf(at + "G162 X24 Z-20 H300 P1 Q0.5 A90 F1.5\nM30\n"), V{"main.fms:3:1 FMSX02"});
  EXPECT_EQ(errorsOf("G18 G0 X30 Z5\nM3 S200\nG162 X24 Z-20 H300\nM30\n"),
            V{"main.fms:3:1 FMSX02"});
  // H is a feed per minute: under G95 gcx has no such move yet
  EXPECT_EQ(errorsOf(at + "G95 G162 X24 Z-20 H300 F1.5\nM30\n"), V{"main.fms:3:5 GCX030"});
}

} // namespace
} // namespace gcx::test
