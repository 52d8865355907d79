// WL4 motion semantics (wl4.md §3): G12/G13 fillets with the exact geometry of §3.5 (TV1, TV2,
// the table of §3.5), dwell by G4 E, the automatic chamfer B (§3.16).
#include <gtest/gtest.h>

#include "support/wl4_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

TEST(Wl4Motion_8, TV1_G12IsTheQuarterCircleAboutTheCornerGivingClockwise) {
  MacroRun r = runWl4("%TV1\nG90G54G17G0X0Y100\nG12X100Y0F100\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 0,100,0", "CW 100,0,0 C0,0 r100 θ90", "END"}));
}

TEST(Wl4Motion_8, TV2_G13AndIncrementalG12) {
  MacroRun r = runWl4("%TV2\nG90 G17 G0 X0 Y100\nG13 X100 Y0 F100\nG91 G12 X-20 Y-20\nG90 M2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(),
            (V{"R 0,100,0", "CCW 100,0,0 C100,100 r100 θ90", "CW 80,-20,0 C80,0 r20 θ90", "END"}));
}

TEST(Wl4Motion_3_5, TheTableOfCentres) {
  // from (50,50): G91 G12 X-20 Y-20 turns about (30,50)
  MacroRun r = runWl4("%P\nG90 G0 X50 Y50\nG91 G12 X-20 Y-20 F10\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 50,50,0", "CW 30,30,0 C30,50 r20 θ90", "END"}));
}

TEST(Wl4Motion_3_5, UnequalLegsAreAnError) {
  MacroRun r = runWl4("%P\nG90 G0 X0 Y100\nG12 X100 Y10 F100\nM2\n%\n");
  EXPECT_EQ(errorsAt(r), (V{"3:1 2015"})) << r.rendered;
}

TEST(Wl4Motion_3_9, G4DwellsForESeconds) {
  MacroRun r = runWl4("%P\nG4 E1.5\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"DW 1.5s", "END"}));
}

TEST(Wl4Motion_8, TV20_G51MirrorsAnAxisAboutZeroAndReversesArcs) {
  MacroRun r = runWl4("%TV20\nG90 G17 G0 X0 Y0 Z0\nG51 X-1\nG1 X10 Y5 F100\nG2 X20 Y15 I10 J0\n"
                      "G50\nG0 X0 Y0\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L -10,5,0 F100", "CCW -20,15,0 C-20,5 r10 θ90", "R 0,0,0", "END"}));
}

TEST(Wl4Motion_3_13, G51WithXOneEndsTheMirrorOfXOnly) {
  MacroRun r = runWl4("%P\nG51 X-1 Y-1\nG0 X1 Y2\nG51 X1\nG0 X3 Y4\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R -1,-2,0", "R 3,-4,0", "END"}));
}

TEST(Wl4Motion_3_13, G51TakesOnlyMinusOneOrOne) {
  MacroRun r = runWl4("%P\nG51 X2\nM2\n%\n");
  EXPECT_EQ(errorsAt(r), (V{"2:5 2002"})) << r.rendered;
}

TEST(Wl4Motion_8, TV21_SelectingAWorkOffsetEndsG92) {
  machine::Setup setup;
  setup.workOffsets["G54"] = {200, 100, 0};
  MacroRun r = runWl4("%TV21\nG92 X100 Y250 Z30\nG90 G0 X0 Y0\nG54 G0 X0 Y0\nM2\n%\n", setup);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // machine coordinates: G53 is the power-on system, so G92 measures from machine zero
  std::vector<std::string> machine;
  for (const motion::Event& e : r.events)
    if (e.kind == motion::Kind::Rapid)
      machine.push_back(n4(e.end.x()) + "," + n4(e.end.y()) + "," + n4(e.end.z()));
  EXPECT_EQ(machine, (V{"-100,-250,0", "200,100,0"}));
}

} // namespace
} // namespace gcx::test

namespace gcx::test {
namespace {

machine::Setup bChamfer() {
  machine::Setup s;
  s.parameters["b_chamfer"] = 1; // the reference profile's B.role = chamfer (§0.2)
  return s;
}

TEST(Wl4Motion_3_16, BIsTheChamferLegBetweenTwoLinesWithBRoleChamfer) {
  // TV19's program on the mill profile's XY plane (X a plain coordinate, no diameter): the
  // corner (100,70) is cut from 10 before it on the first line to 10 after it on the second
  MacroRun r = runWl4("%P\nG90 G17 G0 X40 Y70\nG1 X100 F100 B10\nY10\nM2\n%\n", bChamfer());
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(),
            (V{"R 40,70,0", "L 90,70,0 F100", "L 100,60,0 F100", "L 100,10,0 F100", "END"}));
}

TEST(Wl4Motion_3_16, WithoutBRoleChamferBIsTheRotaryAxis) {
  MacroRun r = runWl4("%P\nG90 G17 G0 X40 Y70\nG1 X100 F100 B10\nY10\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 40,70,0", "L 100,70,0 B10 F100", "L 100,10,0 B10 F100", "END"}));
}

TEST(Wl4Motion_3_16, ALegLongerThanTheNextMoveIsAnError) {
  MacroRun r = runWl4("%P\nG90 G17 G0 X40 Y70\nG1 X100 F100 B10\nY65\nM2\n%\n", bChamfer());
  EXPECT_EQ(errorsAt(r), (V{"3:1 GCX074"})) << r.rendered; // the chamfer does not fit
}

} // namespace
} // namespace gcx::test
