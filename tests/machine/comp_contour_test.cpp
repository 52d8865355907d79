// Automatic contour geometry of nct.md §4 (chapter 17): direction angle ,A, chamfer ,C and
// rounding ,R, as exact motion (TV10-TV12) and located errors.
#include <gtest/gtest.h>

#include "machine/comp_support.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

TEST(CompNctSpec_7, TV10_DirectionAngle) {
  ProgramRun r = runNct("G17 G90 G0 X57.735 Y0\nG1 G91 F100\nX100 ,A30\nY100 ,A120\n"
                        "X-100 ,A210\nY-100 ,A300\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R 57.735,0,0", "L 157.735,57.735,0 F100", "L 100,157.735,0 F100", "L 0,100,0 F100",
               "L 57.735,0,0 F100"}));
}

TEST(CompNctSpec_7, TV11_Chamfer) {
  ProgramRun r = runNct("G90 G0 X0 Y0\nN1 G17 G1 G91 X30 ,C10 F100\nN2 X10 Y40\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"L 20,0,0 F100", "L 32.4254,9.7014,0 F100", "L 40,40,0 F100"}));
}

TEST(CompNctSpec_7, TV12_RoundingBetweenLineAndArc) {
  ProgramRun r = runNct("G90 G0 X0 Y0\nN1 G17 G91 G01 X30 ,R8 F100\nN2 G03 X-30 Y30 R30\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"L 20.4939,0,0 F100", "CCW 27.9462,10.9091,0 C20.4939,8 r8 θ111.3237",
               "CCW 0,30,0 C0,0 r30 θ68.6763"}));
}

// nct.md §4.1 (000:8886-8892): chamfers and roundings chained on consecutive blocks, an arc
// with a chamfer measured as a chord. The manual's ,R22 does not fit this start point (the
// rounding's centre would lie outside the arc's offset), so the rounding here is ,R8.
TEST(CompNctSpec_4_1, ChainedChamferAndRounding) {
  ProgramRun r = runNct("G17 G90 G0 X20 Y0\nG1 Y40 ,C10 F100\nX60 ,R8\nG3 X20 Y80 R40 ,C10\n"
                        "G1 Y110\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R 20,0,0", "L 20,30,0 F100", "L 30,40,0 F100", "L 50.9839,40,0 F100",
               "CCW 58.7298,50,0 C50.9839,48 r8 θ104.4775",
               "CCW 29.9216,78.75,0 C20,40 r40 θ61.161", "L 20,90,0 F100", "L 20,110,0 F100"}));
}

// nct.md §4.3 line-line (000:9045-9060): a line by its direction alone ends where the next,
// over-determined line (absolute X Y and ,A) meets it; D0 keeps the path uncompensated.
TEST(CompNctSpec_7, TV21_IntersectionLineLine) {
  ProgramRun r = runNct("G17 G90 G41 D0\nG0 X90 Y10\nN10 G1 ,A150 F100\nN20 X10 Y20 ,A225\n"
                        "G0 X0 Y20\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R 90,10,0", "L 32.9423,42.9423,0 F100", "L 10,20,0 F100", "R 0,20,0"}));
  ASSERT_GE(r.events.size(), 3u);
  EXPECT_EQ(r.events[1].from.at.line, 3u); // the intersection ends N10's own move
  ProgramRun square = runNct("G17 G90 G41 D0\nG1 ,A0 F100\nX10 Y10 ,A90\n");
  EXPECT_EQ(compMotion(square.motion()), (V{"L 10,0,0 F100", "L 10,10,0 F100"})) << square.rendered;
}

// nct.md §4.3: a line by its direction alone needs the next block to be an over-determined line
// or circle; a plain move there is the located error, not a silent skip of the waiting line.
TEST(CompNctSpec_7, DirectionLineBeforeAPlainMoveIsAnError) {
  ProgramRun r = runNct("G17 G90 G41 D0\nG1 ,A150 F100\nX10 Y20\nX30 Y40\nM30\n");
  EXPECT_EQ(r.errors, V{"3:1 GCX077"}) << r.rendered; // at the plain move, not at the end
}

// nct.md §3.15 (000:8694-8697): under unequal factors a rounding is ,R * (I+J)/2 = 6.25 in the
// scaled path (the manual's own example); a chamfer has no rule and stays an error.
TEST(CompNctSpec_4_1, RoundingUnderUnequalScaling) {
  const std::string head = "G17 G90 G0 X0 Y0\nG51 X0 Y0 Z0 I0.5 J0.75 K1.25\n";
  ProgramRun r = runNct(head + "G1 X100 ,R10 F100\nY100\nX10\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()), (V{"L 43.75,0,0 F100", "CCW 50,6.25,0 C43.75,6.25 r6.25 θ90",
                                       "L 50,75,0 F100", "L 5,75,0 F100"}));
  EXPECT_EQ(runNct(head + "G1 X100 ,C10 F100\nY100\n").errors, V{"3:9 GCX030"});
}

TEST(CompNctSpec_4_1, ChamferAndRoundingInOneBlock2082) {
  ProgramRun r = runNct("G17 G1 X30 ,C5 ,R5 F100\nY30\n");
  EXPECT_EQ(r.errors, V{"1:16 2082"}) << r.rendered;
}

TEST(CompNctSpec_4_1, ChamferBeforeAMoveOutOfThePlane2085) {
  ProgramRun r = runNct("G17 G1 X30 ,C5 F100\nZ-5\n");
  EXPECT_EQ(r.errors, V{"1:1 2085"}) << r.rendered;
}

TEST(CompNctSpec_4_1, ChamferTooBig) {
  ProgramRun r = runNct("G17 G1 X30 ,C40 F100\nY30\n");
  EXPECT_EQ(r.errors, V{"1:1 GCX074"}) << r.rendered;
}

} // namespace
} // namespace gcx::test
