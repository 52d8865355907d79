// Cutter radius compensation: corner rules, look-ahead and the located alarms of nct.md §3.17
// (docs/compensation.md), as exact tool-centre motion or file:line:col and code.
#include <gtest/gtest.h>

#include "machine/comp_support.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

// nct.md §3.17.1 [F, Fanuc type C]: an acute outer corner is passed on the extended vectors,
// three lines; an inner cancel ends on the perpendicular of the last element.
TEST(CompNctSpec_3_17_1, AcuteOuterCornerTypeC) {
  ProgramRun r =
      runNct("G17 G0 X-10 Y0\nG41 G1 X0 Y0 D1 F100\nX20\nX0 Y-5\nG40 X0 Y-20\n", compSetup(1));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(
      compMotion(r.motion()),
      (V{"R -10,0,0", "L 0,1,0 F100", "L 20,1,0 F100", "L 21,1,0 F100", "L 21.2127,-0.7276,0 F100",
         "L 20.2425,-0.9701,0 F100", "L 0.2425,-5.9701,0 F100", "L 0,-20,0 F100"}));
}

// nct.md §3.15: a mirror of one plane axis swaps G41 and G42, so the tool path is the mirror
// image of the unmirrored one.
TEST(CompNctSpec_3_15, MirrorSwapsTheSide) {
  ProgramRun r = runNct("G17 G51.1 X0\nG0 X-10 Y0\nG41 G1 X0 Y0 D1 F100\nX20\nX0 Y-5\n"
                        "G40 X0 Y-20\n",
                        compSetup(1));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R 10,0,0", "L 0,1,0 F100", "L -20,1,0 F100", "L -21,1,0 F100",
               "L -21.2127,-0.7276,0 F100", "L -20.2425,-0.9701,0 F100", "L -0.2425,-5.9701,0 F100",
               "L 0,-20,0 F100"}));
}

// cycles.md Q-20: a drilling cycle's holes are not compensated; the cycle breaks the look-ahead
// like G43 (nct.md §3.17.7): the waiting element ends on its programmed point.
TEST(CompNctSpec_3_17_7, DrillingCycleBreaksTheLookAhead) {
  ProgramRun r = runNct("G17 G90 G0 X0 Y0 Z10\nG41 G1 X10 D1 F100\nG81 X20 Y20 Z-5 R2\nX30\n"
                        "G80\nG40 G1 X0 Y0\n",
                        compSetup(1));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()), (V{"R 0,0,10", "L 10,0,10 F100", "R 20,20,10", "R 20,20,2",
                                       "L 20,20,-5 F100", "R 20,20,10", "R 30,20,10", "R 30,20,2",
                                       "L 30,20,-5 F100", "R 30,20,10", "L 0,0,10 F100"}));
}

// nct.md §3.17.5 (000:8139-8211): G39 passes the next outer corner on an arc of the radius about
// the corner point, clockwise under G41.
TEST(CompNctSpec_3_17_5, G39CornerArc) {
  ProgramRun r =
      runNct("G17 G90 G0 X0 Y-10\nG41 G1 X0 Y0 D1 F100\nY30\nG39\nX30\nG40 X40\n", compSetup(1));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R 0,-10,0", "L -1,0,0 F100", "L -1,30,0 F100", "CW 0,31,0 C0,30 r1 θ90",
               "L 30,31,0 F100", "L 40,30,0 F100"}));
  EXPECT_EQ(runNct("G17 G39\n", compSetup(1)).errors, V{"1:5 GCX076"});
}

// nct.md §3.17.5 (000:8105-8137): G38 ends its block with the vector it starts with, whatever
// the next corner; the next element starts there.
TEST(CompNctSpec_3_17_5, G38VectorHold) {
  ProgramRun r = runNct("G17 G90 G0 X0 Y-10\nG41 G1 X0 Y0 D1 F100\nY30\nG38 X30\nY0\n"
                        "G40 X30 Y-10\n",
                        compSetup(1));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()), (V{"R 0,-10,0", "L -1,0,0 F100", "L -1,31,0 F100",
                                       "L 29,31,0 F100", "L 31,0,0 F100", "L 30,-10,0 F100"}));
}

// nct.md §3.17.1: a block out of the plane between two plane elements keeps the corner; it runs
// at the corner point. An obtuse outer cancel goes through the offsets' intersection.
TEST(CompNctSpec_3_17_1, OutOfPlaneBlockInsideTheLookAhead) {
  ProgramRun r = runNct("G17 G41 G1 X10 D1 F100\nZ-1\nY10\nG40 X20\n", compSetup(1));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"L 9,0,0 F100", "L 9,0,-1 F100", "L 9,11,-1 F100", "L 20,10,-1 F100"}));
}

TEST(CompNctSpec_3_17_1, LookAheadBufferFull2090) {
  // N1404 = 0: the next plane motion must come within 2 blocks
  ProgramRun ok = runNct("G17 G41 G1 X10 D1 F100\nM8\nY20\n", compSetup(1));
  EXPECT_TRUE(ok.errors.empty()) << ok.rendered;
  ProgramRun r = runNct("G17 G41 G1 X10 D1 F100\nM8\nS100\nY20\n", compSetup(1));
  EXPECT_EQ(r.errors, V{"1:1 2090"}) << r.rendered;
}

TEST(CompNctSpec_3_17_1, InnerCornerWithoutIntersection2047) {
  ProgramRun r =
      runNct("G17 G0 X-10 Y0\nG41 G1 X0 D1 F100\nX10\nG3 X6 Y4 I-2 J2\nG1 X0\n", compSetup(2.5));
  EXPECT_EQ(r.errors, V{"3:1 2047"}) << r.rendered;
}

// nct.md §3.17.1 (000:7700-7712): an outer corner turning by 91 degrees is acute: type C
// extends the end and start vectors by r, and their ends (-5,35) and (-4.912,35.0865) lie
// 0.09 apart. With
// N1405 DELTV = 0.2 the second is skipped; the second element's start vector stays.
TEST(CompNctSpec_3_17_1, Deltv1405MergesCloseVectors) {
  const std::string program = "G17 G90 G0 X0 Y-10\nG41 G1 X0 Y0 D1 F100\nY30\nX30 Y29.476342\n"
                              "G40 X60 Y28.952685\n";
  ProgramRun typeC = runNct(program, compSetup(5));
  ASSERT_TRUE(typeC.errors.empty()) << typeC.rendered;
  EXPECT_EQ(compMotion(typeC.motion()),
            (V{"R 0,-10,0", "L -5,0,0 F100", "L -5,30,0 F100", "L -5,35,0 F100",
               "L -4.912,35.0865,0 F100", "L 0.0873,34.9992,0 F100", "L 30.0873,34.4756,0 F100",
               "L 60,28.9527,0 F100"}));
  machine::Setup merging = compSetup(5);
  merging.parameters["N1405"] = 0.2;
  ProgramRun merged = runNct(program, merging);
  ASSERT_TRUE(merged.errors.empty()) << merged.rendered;
  EXPECT_EQ(compMotion(merged.motion()),
            (V{"R 0,-10,0", "L -5,0,0 F100", "L -5,30,0 F100", "L -5,35,0 F100",
               "L 0.0873,34.9992,0 F100", "L 30.0873,34.4756,0 F100", "L 60,28.9527,0 F100"}));
}

TEST(CompNctSpec_3_17_6, Interference2049) {
  ProgramRun r = runNct("G17 G0 X-10 Y-10\nG41 G1 X0 Y0 D1 F100\nX10\nY1\nX0\nG40 G0 X-10 Y10\n",
                        compSetup(5));
  EXPECT_EQ(r.errors, V{"4:1 2049"}) << r.rendered;
}

TEST(CompNctSpec_3_17_1, RadiusLargerThanInnerArc) {
  ProgramRun r = runNct("G17 G41 G1 X10 D1 F100\nG3 X10 Y4 R2\n", compSetup(5));
  EXPECT_EQ(r.errors, V{"2:1 GCX070"}) << r.rendered;
}

TEST(CompNctSpec_3_17_1, PlaneChangeWhileOn) {
  ProgramRun r = runNct("G17 G41 G1 X10 D1 F100\nG18 X20\n", compSetup(1));
  EXPECT_EQ(r.errors, V{"2:1 GCX071"}) << r.rendered;
}

TEST(CompNctSpec_3_17_2, StartUpInAnArcBlock) {
  ProgramRun r = runNct("G17 G0 X0 Y0\nG41 G2 X10 Y10 R10 D1 F100\n", compSetup(1));
  EXPECT_EQ(r.errors, V{"2:1 GCX072"}) << r.rendered;
}

TEST(CompNctSpec_3_17_3, CancelInAnArcBlock2043) {
  ProgramRun r = runNct("G17 G41 G1 X10 D1 F100\nG40 G2 X20 Y10 R10\n", compSetup(1));
  EXPECT_EQ(r.errors, V{"2:1 2043"}) << r.rendered;
}

} // namespace
} // namespace gcx::test
