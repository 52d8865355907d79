// The lathe tool data of wl4.md §4.1 (002:1268-1328, 1547-1577): T makes the offsets of its
// working point (the setup's `turning` [dXw, 0, dZw], machine mm) move the program zero, T0
// clears them; the compensation radius is the selected tool's nose radius Rt (`nose_radius`)
// plus corrector D, which may be negative, never below 0 in sum. And the two checks of §2.4
// and §3.6: G96/G97 switched without a new S, a G32 sequence that does not end with G9 and G0-G3.
#include <gtest/gtest.h>

#include "support/wl4_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

TEST(Wl4ToolData_4_1, TMovesTheProgramZeroByItsWorkingPointAndT0ClearsIt) {
  machine::Setup s = wl4Lathe();
  s.tools[1].turning = {10, 0, -5}; // dXw, -, dZw
  MacroRun r = runWl4("%P\nG18 G90 G0 X20 Z10\nT1\nG0 X20 Z10\nG0 X30\nT0\nG0 X30 Z10\nM2\n%\n", s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // machine frame, X radius: T1 alone moves nothing; the next moves go to the shifted zero;
  // after T0 the program zero is the machine's again
  EXPECT_EQ(r.motion(), (V{"R 10,0,10", "R 20,0,5", "R 25,0,5", "R 15,0,10", "END"}));
}

TEST(Wl4ToolData_4_1, TheOffsetActsOnTheNextMoveOfEachAxis) {
  // T2 with a move in its block: the move already goes to the new zero (T acts before motion);
  // Z is not written, so Z keeps its machine position until it moves (§3.1)
  machine::Setup s = wl4Lathe();
  s.tools[2].turning = {-4, 0, 3};
  MacroRun r = runWl4("%P\nG18 G90 G0 X20 Z10\nT2 G0 X20\nZ10\nM2\n%\n", s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 10,0,10", "R 6,0,10", "R 6,0,13", "END"}));
}

TEST(Wl4ToolData_4_2, TheCompensationRadiusIsTheNoseRadiusPlusD) {
  // Rt 0.8 + D -0.3 = 0.5 on the left of a line along +X (G17): the start-up ends on the
  // perpendicular at X10 Y0.5, the cancel returns to the path at X30
  machine::Setup s;
  s.tools[1].noseRadius = 0.8;
  s.tools[2].radius = -0.3;
  MacroRun r = runWl4("%P\nG17 G90 T1 D2 G0 X0 Y0\nG41 G1 X10 Y0 F100\nG1 X20\nG40 G1 X30\n"
                      "M2\n%\n",
                      s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L 10,0.5,0 F100", "L 20,0.5,0 F100", "L 30,0,0 F100", "END"}));
}

TEST(Wl4ToolData_4_2, T0LeavesOnlyTheCorrector) {
  // T0: Rt = 0 (002:1575-1577); D2 = 0.5 alone
  machine::Setup s;
  s.tools[1].noseRadius = 0.8;
  s.tools[2].radius = 0.5;
  MacroRun r = runWl4("%P\nG17 G90 T1\nT0 D2 G0 X0 Y0\nG41 G1 X10 Y0 F100\nG1 X20\nG40 G1 X30\n"
                      "M2\n%\n",
                      s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L 10,0.5,0 F100", "L 20,0.5,0 F100", "L 30,0,0 F100", "END"}));
}

TEST(Wl4ToolData_4_1, ANoseRadiusPlusDBelowZeroIsAnError) {
  machine::Setup s;
  s.tools[1].noseRadius = 0.2;
  s.tools[2].radius = -0.3;
  MacroRun r = runWl4("%P\nG17 G90 T1 D2 G0 X0 Y0\nG41 G1 X10 Y0 F100\nM2\n%\n", s);
  EXPECT_EQ(errorsAt(r), (V{"3:1 GCX090"})) << r.rendered;
}

TEST(Wl4Spindle_2_4, SwitchingG96AndG97NeedsANewSInTheBlock) {
  // 002:1265-1267: "switching from G97 to G96 and back without a new S word in the same block
  // is not allowed"
  EXPECT_EQ(errorsAt(runWl4("%P\nG18 G0 X40 Z5\nS500 M3\nG96\nM2\n%\n")), (V{"4:1 GCX092"}));
  EXPECT_EQ(errorsAt(runWl4("%P\nG18 G0 X40 Z5\nG96 S120 M3\nG0 X10\nG97 M5\nM2\n%\n")),
            (V{"5:1 GCX092"}));
  MacroRun r = runWl4("%P\nG18 G0 X40 Z5\nG96 S120 M3\nG96 X10\nG97 S800\nG97 X20\nM2\n%\n");
  EXPECT_TRUE(r.errors.empty()) << r.rendered; // with S, or no switch at all
}

TEST(Wl4Threads_3_6, AG32SequenceEndsWithG9AndAG0ToG3) {
  MacroRun r = runWl4("%P\nG18 G0 X20 Z5 S500 M3\nG32 Z-20 F1.5\nX24 Z-22 G9\nG0 X40\nM2\n%\n");
  EXPECT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_TRUE(r.warnings.empty()) << r.rendered;
}

TEST(Wl4Threads_3_6, ALastThreadMoveWithoutG9Warns) {
  MacroRun r = runWl4("%P\nG18 G0 X20 Z5 S500 M3\nG32 Z-20 F1.5\nX24 Z-22\nG0 X40\nM2\n%\n");
  EXPECT_TRUE(r.errors.empty()) << r.rendered;
  ASSERT_EQ(r.warnings.size(), 1u) << r.rendered;
  EXPECT_NE(r.warnings[0].find(":4:1 GCXW26"), std::string::npos) << r.warnings[0];
}

TEST(Wl4Threads_3_6, ASequenceNotEndedByG0ToG3IsAnError) {
  // the program ends inside it; another motion code follows it
  EXPECT_EQ(errorsAt(runWl4("%P\nG18 G0 X20 Z5 S500 M3\nG32 Z-20 F1.5 G9\nM2\n%\n")),
            (V{"4:1 GCX091"}));
  EXPECT_EQ(errorsAt(runWl4("%P\nG17 G0 X20 Y5 Z5 S500 M3\nG32 Z-20 F1.5 G9\nG12 X40 Y25\n"
                            "M2\n%\n")),
            (V{"4:1 GCX091"}));
  EXPECT_EQ(errorsAt(runWl4("%P\nG18 G0 X20 Z5 S500 M3\nG32 Z-20 F1.5 G9\nG33 Z-30\nM2\n%\n")),
            (V{"4:1 GCX091"}));
}

} // namespace
} // namespace gcx::test
