// Intersection calculations of nct.md §4.3 (chapter 17.3, 000:8967-9406): an over-determined
// line or circle ends the element before at their intersection, Q choosing between two
// points; exact motion (TV21-TV23, the manual's O9985 and chain listings) and located errors.
// Expected points are the spec's vectors or computed by hand from the listings' geometry.
#include <gtest/gtest.h>

#include "machine/comp_support.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

// O9981/O9982 (000:9141-9151), F100 added: the line N20 ends on the circle C(20,-10) R50 of
// N30, whose I J are absolute; Q-1 the point nearer along the line's direction, Q1 the farther.
TEST(CompNctSpec_7, TV22_IntersectionLineCircle) {
  const std::string head = "N10 G17 G42 G0 X100 Y20 D0\nN20 G1 X-30 Y-20 F100\n";
  const std::string tail = "N40 G40 G0 Y60\nN50 X120\n";
  ProgramRun nearer = runNct(head + "N30 G3 X20 Y40 I20J-10 R50 Q-1\n" + tail);
  ASSERT_TRUE(nearer.errors.empty()) << nearer.rendered;
  EXPECT_EQ(compMotion(nearer.motion()),
            (V{"R 100,20,0", "L 66.0216,9.5451,0 F100", "CCW 20,40,0 C20,-10 r50 θ66.9894",
               "R 20,60,0", "R 120,60,0"}));
  ProgramRun farther = runNct(head + "N30 G3 X20 Y40 I20 J-10 R50 Q1\n" + tail);
  ASSERT_TRUE(farther.errors.empty()) << farther.rendered;
  EXPECT_EQ(compMotion(farther.motion()),
            (V{"R 100,20,0", "L -29.0486,-19.7073,0 F100", "CCW 20,40,0 C20,-10 r50 θ258.8052",
               "R 20,60,0", "R 120,60,0"}));
  ASSERT_GE(farther.events.size(), 3u);
  EXPECT_EQ(farther.events[1].from.at.line, 2u); // the shortened line keeps N20's provenance
  EXPECT_EQ(farther.events[2].from.at.line, 3u);
}

// TV21 with N10 given by a point of its line instead of its direction (000:9050-9060): X50
// Y33.094 is no end point, only a point the line passes; the spec's result within 0.001.
TEST(CompNctSpec_7, TV21_PassThroughPointVariant) {
  ProgramRun r = runNct("G17 G90 G41 D0\nG0 X90 Y10\nN10 G1 X50 Y33.094 F100\nN20 X10 Y20 ,A225\n"
                        "G0 X0 Y20\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R 90,10,0", "L 32.9423,42.9423,0 F100", "L 10,20,0 F100", "R 0,20,0"}));
  ASSERT_GE(r.events.size(), 3u);
  EXPECT_EQ(r.events[1].from.at.line, 3u);
  EXPECT_EQ(r.events[2].from.at.line, 4u);
}

// 000:9071-9086: a chamfer or rounding on the element before is measured back from the
// computed intersection (the chamfer 10 from (32.9423,42.9423) on both lines; the rounding
// R10 tangent to both, turning left through 75 degrees).
TEST(CompNctSpec_4_3, ChamferAndRoundingAtAnIntersection) {
  const std::string head = "G17 G90 G41 D0\nG0 X90 Y10\nN10 G1 X50 Y33.094 F100 ";
  const std::string tail = "\nN20 X10 Y20 ,A225\nG0 X0 Y20\n";
  ProgramRun chamfer = runNct(head + ",C10" + tail);
  ASSERT_TRUE(chamfer.errors.empty()) << chamfer.rendered;
  EXPECT_EQ(compMotion(chamfer.motion()),
            (V{"R 90,10,0", "L 41.6025,37.9423,0 F100", "L 25.8712,35.8712,0 F100",
               "L 10,20,0 F100", "R 0,20,0"}));
  ProgramRun rounding = runNct(head + ",R10" + tail);
  ASSERT_TRUE(rounding.errors.empty()) << rounding.rendered;
  EXPECT_EQ(compMotion(rounding.motion()),
            (V{"R 90,10,0", "L 39.5875,39.1056,0 F100",
               "CCW 27.5165,37.5165,0 C34.5875,30.4454 r10 θ75", "L 10,20,0 F100", "R 0,20,0"}));
}

// 000:9163-9172: O9981 with ,R15 on the line: the rounding (a right turn, so clockwise, its
// centre 65 from the circle's) is fitted to the computed line-circle intersection.
TEST(CompNctSpec_4_3, RoundingAtALineCircleIntersection) {
  ProgramRun r = runNct("N10 G17 G42 G0 X100 Y20 D0\nN20 G1 X-30 Y-20 ,R15 F100\n"
                        "N30 G3 X20 Y40 I20 J-10 R50 Q-1\nN40 G40 G0 Y60\nN50 X120\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R 100,20,0", "L 77.5527,13.0931,0 F100",
               "CW 60.878,18.7922,0 C73.1414,27.4298 r15 θ71.944",
               "CCW 20,40,0 C20,-10 r50 θ54.8413", "R 20,60,0", "R 120,60,0"}));
}

// O9983/O9984 (000:9229-9245), F100 added: the arc N30 (X-50 Y0 only a point of its circle)
// ends where the over-determined line N40 crosses it, Q along the line's direction ,A.
TEST(CompNctSpec_7, TV23_IntersectionCircleLine) {
  const std::string head = "N10 G17 G0 X90 Y0\nN20 G42 G1 X50 D0 F100\nN30 G3 X-50 Y0 R50\n";
  const std::string tail = "N50 G40 G0 Y70\nN60 X90\n";
  ProgramRun nearer = runNct(head + "N40 G1 X-50 Y42.857 ,A171.87 Q-1\n" + tail);
  ASSERT_TRUE(nearer.errors.empty()) << nearer.rendered;
  EXPECT_EQ(compMotion(nearer.motion()),
            (V{"R 90,0,0", "L 50,0,0 F100", "CCW 40,30,0 C0,0 r50 θ36.8699", "L -50,42.857,0 F100",
               "R -50,70,0", "R 90,70,0"}));
  ProgramRun farther = runNct(head + "N40 G1 X-50 Y42.857 ,A171.87 Q1\n" + tail);
  ASSERT_TRUE(farther.errors.empty()) << farther.rendered;
  EXPECT_EQ(compMotion(farther.motion()),
            (V{"R 90,0,0", "L 50,0,0 F100", "CCW -30.0001,39.9999,0 C0,0 r50 θ126.8701",
               "L -50,42.857,0 F100", "R -50,70,0", "R 90,70,0"}));
}

// O9985/O9986 (000:9332-9346), F100 added: circle-circle, Q-1 the first point met along the
// first arc (N30, G3 about (130,10)), Q1 the second (nct.md Q26). The manual's comment "the
// nearest point clockwise" for Q-1 names the same point, seen back from N40's end. The
// listing's rounded Y87.446 lies 0.0003 off the circle R70: N40 is a spiral within tolerance.
TEST(CompNctSpec_4_3, CircleCircleO9985) {
  const std::string head = "N10 G17 G54 G0 X200 Y10\nN20 G42 G1 X180 D0 F100\nN30 G3 X130 Y-40 "
                           "R-50\n";
  const std::string tail = "N50 G40 G0 Y100\nN60 X200\n";
  ProgramRun first = runNct(head + "N40 X90 Y87.446 I50J30 R70 Q-1\n" + tail);
  ASSERT_TRUE(first.errors.empty()) << first.rendered;
  EXPECT_EQ(compMotion(first.motion()),
            (V{"R 200,10,0", "L 180,10,0 F100", "CCW 114.3739,57.4955,0 C130,10 r50 θ108.2113",
               "CCW 90,87.446,0 C50,30 r70->70.0003 θ32.0219", "R 90,100,0", "R 200,100,0"}));
  ProgramRun second = runNct(head + "N40 X90 Y87.446 I50 J30 R70 Q1\n" + tail);
  ASSERT_TRUE(second.errors.empty()) << second.rendered;
  EXPECT_EQ(compMotion(second.motion()),
            (V{"R 200,10,0", "L 180,10,0 F100", "CCW 93.8614,-24.5543,0 C130,10 r50 θ223.7162",
               "CCW 90,87.446,0 C50,30 r70->70.0003 θ106.3512", "R 90,100,0", "R 200,100,0"}));
}

// The same listing with D1 = 5 (the manual gives no value): the intersection is computed on
// the programmed contour, then compensated. G42 on these CCW arcs is outside: radii 55 and
// 75; the corner between them is inner (offsets' intersection), the cancel inner (end
// perpendicular at N40's end).
TEST(CompNctSpec_4_3, CircleCircleCompensated) {
  ProgramRun r = runNct("N10 G17 G54 G0 X200 Y10\nN20 G42 G1 X180 D1 F100\nN30 G3 X130 Y-40 "
                        "R-50\nN40 X90 Y87.446 I50J30 R70 Q-1\nN50 G40 G0 Y100\nN60 X200\n",
                        compSetup(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R 200,10,0", "L 185,10,0 F100", "CCW 117.1175,63.47,0 C130,10 r55 θ103.5461",
               "CCW 92.8571,91.5493,0 C50,30 r75->75.0003 θ28.6459", "R 90,100,0", "R 200,100,0"}));
}

// The chain of 000:9377-9386 (D0 instead of D1): while the next element is over-determined,
// the coordinates of the current one are only a point of its line or circle; N60, followed
// by a normal block, ends at its programmed point.
TEST(CompNctSpec_4_3, ChainedIntersections) {
  ProgramRun r = runNct("N10 G17 G54 G0 G42 X230 Y20 D0 F300\nN20 G1 X170 Y50\n"
                        "N30 G3 X110 Y10 I150 J40 R50 Q-1\nN40 X60 Y70 I100 J70 R40 Q1\n"
                        "N50 G1 X80 Y60 ,A135 Q1\nN60 X10 Y108 ,A180\nN70 G40 G0 Y130\nN80 X240\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(
      compMotion(r.motion()),
      (V{"R 230,20,0", "L 199.7612,35.1194,0 F300", "CCW 101.0076,30.0127,0 C150,40 r50 θ197.1238",
         "CCW 61.0208,78.9792,0 C100,70 r40 θ255.5843", "L 32,108,0 F300", "L 10,108,0 F300",
         "R 10,130,0", "R 240,130,0"}));
}

// 000:9043-9044: the over-determined block's coordinates are absolute whatever G90/G91 say.
TEST(CompNctSpec_4_3, OverDeterminedCoordinatesAreAbsoluteUnderG91) {
  ProgramRun r = runNct("G17 G90 G41 D0\nG0 X90 Y10\nN10 G91 G1 ,A150 F100\nN20 X10 Y20 ,A225\n"
                        "G0 X-10\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R 90,10,0", "L 32.9423,42.9423,0 F100", "L 10,20,0 F100", "R 0,20,0"}));
}

TEST(CompNctSpec_4_3, OverDeterminedLineOutsideCompensationGCX077) {
  ProgramRun r = runNct("G17 G90 G0 X0 Y0\nG1 X10 Y10 ,A45 F100\n");
  EXPECT_EQ(r.errors, V{"2:12 GCX077"}) << r.rendered;
}

TEST(CompNctSpec_4_3, OverDeterminedCircleWithoutAnElementBeforeGCX077) {
  ProgramRun r = runNct("G17 G90 G0 X0 Y0\nG42 D0\nG3 X10 Y0 I0 J0 R10 Q1 F100\n");
  EXPECT_EQ(r.errors, V{"3:17 GCX077"}) << r.rendered;
}

TEST(CompNctSpec_4_3, DirectionLineNotFollowedByAnOverDeterminedElementGCX077) {
  ProgramRun next = runNct("G17 G90 G41 D0\nG0 X90 Y10\nN10 G1 ,A150 F100\nN20 X10 Y20\n");
  EXPECT_EQ(next.errors, V{"4:1 GCX077"}) << next.rendered;
  ProgramRun end = runNct("G17 G90 G41 D0\nG0 X90 Y10\nN10 G1 ,A150 F100\n");
  EXPECT_EQ(end.errors, V{"3:1 GCX077"}) << end.rendered;
}

TEST(CompNctSpec_4_3, RoundingOnADirectionOnlyLineIsNotImplemented) {
  ProgramRun r = runNct("G17 G90 G41 D0\nG0 X90 Y10\nN10 G1 ,A150 ,R5 F100\nN20 X10 Y20 ,A225\n");
  EXPECT_EQ(r.errors, V{"3:14 GCX030"}) << r.rendered;
}

TEST(CompNctSpec_4_3, TwoPointsWithoutQGCX078) {
  ProgramRun r = runNct("N10 G17 G42 G0 X100 Y20 D0\nN20 G1 X-30 Y-20 F100\n"
                        "N30 G3 X20 Y40 I20 J-10 R50\n");
  EXPECT_EQ(r.errors, V{"3:25 GCX078"}) << r.rendered;
}

TEST(CompNctSpec_4_3, ElementsThatDoNotMeet2047) {
  ProgramRun line = runNct("G17 G42 G0 X100 Y20 D0\nG1 X90 Y20 F100\nX0 Y0 ,A0\n");
  EXPECT_EQ(line.errors, V{"3:7 2047"}) << line.rendered;
  ProgramRun circle = runNct("G17 G42 G0 X100 Y100 D0\nG1 X90 Y100 F100\n"
                             "G3 X20 Y40 I20 J-10 R50 Q1\n");
  EXPECT_EQ(circle.errors, V{"3:21 2047"}) << circle.rendered;
}

TEST(CompNctSpec_4_3, OverDeterminedCircleEndOffItsCircle2012) {
  ProgramRun r = runNct("G17 G42 G0 X100 Y20 D0\nG1 X-30 Y-20 F100\nG3 X20 Y41 I20 J-10 R50 Q1\n");
  EXPECT_EQ(r.errors, V{"3:21 2012"}) << r.rendered;
}

} // namespace
} // namespace gcx::test
