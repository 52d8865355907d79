// Cutter radius compensation, direction change (nct.md §3.17.4, 000:7994-8103): G41 <-> G42 or
// a D of the other sign while compensating. The intersection of the offsets first; without one
// the block before the change ends on the perpendicular at the next block's start, a line on a
// straight line, an arc of the programmed radius R about a shifted centre (alarm 2047 if none).
#include <gtest/gtest.h>

#include "machine/comp_support.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

// Line-line, both along +X, G41 -> G42, r = 2 (000:8041-8050): the offsets y = 2 and y = -2 are
// parallel. The start-up ends on (0,2); the first line runs straight to the perpendicular at
// the second's start, (10,0) + 2·(0,-1) = (10,-2); the second runs on y = -2 to (20,-2) and the
// collinear cancel ends there before going to (30,0).
TEST(CompNctSpec_3_17_4, LineLineWithoutIntersectionEndsOnTheNextPerpendicular) {
  ProgramRun r = runNct("G17 G0 X-10 Y0\nG41 G1 X0 D1 F100\nX10\nG42 X20\nG40 X30\n", compSetup(2));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R -10,0,0", "L 0,2,0 F100", "L 10,-2,0 F100", "L 20,-2,0 F100", "L 30,0,0 F100"}));
}

// Arc-line, G41 -> G42, r = 2 (000:8083-8100). N3: CCW about (0,0), R = 10, (0,-10) to (10,0);
// G41 is inside, radius 8; the tangent start-up ends on (0,-8). N4: line (10,0) -> (10,20),
// G42 offset x = 12, which misses the circle of radius 8. The perpendicular at N4's start is
// (10,0) + 2·(1,0) = (12,0). N3 runs from (0,-8) to (12,0) on R = 10: the chord (12,8) has
// length √208, its midpoint is (6,-4), the centres lie √(100 − 52) = √48 from it along
// ±(−8,12)/√208, i.e. ±√(3/13)·(−8,12) = ±(−3.8431, 5.7646). The one nearer (0,0) is
// (2.1569,1.7646). Sweep CCW: atan2(−9.7646,−2.1569) = −102.456°, atan2(−1.7646,9.8431) =
// −10.164°: 92.29°. Then x = 12 to (12,20), the collinear cancel, (10,30).
TEST(CompNctSpec_3_17_4, ArcLineWithoutIntersectionShiftsTheArcsCentre) {
  ProgramRun r = runNct("G17 G0 X-10 Y-10\nG41 G1 X0 D1 F100\nG3 X10 Y0 I0 J10\nG42 G1 Y20\n"
                        "G40 X10 Y30\n",
                        compSetup(2));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R -10,-10,0", "L 0,-8,0 F100", "CCW 12,0,0 C2.1569,1.7646 r10 θ92.2924",
               "L 12,20,0 F100", "L 10,30,0 F100"}));
}

// Arc-arc, G41 -> G42, r = 2. N3 as above (offset radius 8 about (0,0)). N4: CW about (20,0)
// from (10,0) to (20,10); G42 is inside, radius 8 about (20,0): the centres are 20 apart,
// 8 + 8 < 20, no intersection. N3 runs to the perpendicular (10,0) + 2·(1,0) = (12,0) on
// R = 10 about (2.1569,1.7646) (arithmetic above); N4 from (12,0) about (20,0), r 8, 90° to
// (20,8), where the tangent (+X) cancel's perpendicular lies, then (30,10).
TEST(CompNctSpec_3_17_4, ArcArcWithoutIntersectionShiftsTheArcsCentre) {
  ProgramRun r = runNct("G17 G0 X-10 Y-10\nG41 G1 X0 D1 F100\nG3 X10 Y0 I0 J10\n"
                        "G42 G2 X20 Y10 I10 J0\nG40 G1 X30\n",
                        compSetup(2));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R -10,-10,0", "L 0,-8,0 F100", "CCW 12,0,0 C2.1569,1.7646 r10 θ92.2924",
               "CW 20,8,0 C20,0 r8 θ90", "L 30,10,0 F100"}));
}

// Arc-arc by the sign of D (D1 = 2, D2 = −2 under G41 is the right side), CW first arc.
// N3: CW about (0,0), R = 10, (0,10) to (10,0); G41 (left of CW) is outside, radius 12; the
// tangent start-up (+X) ends on (0,12). N4: G41 D2, CW about (20,0) from (10,0) to (20,10);
// right of CW is inside, radius 8 about (20,0): 12 + 8 = 20 = the centres' distance, the
// circles touch at (12,0) — the intersection is used, the programmed centre stays: N3 (0,12)
// -> (12,0) about (0,0), r 12, 90°. N4 (12,0) -> (20,8) about (20,0), r 8, 90°; the tangent
// (+X) cancel ends on (20,8), then (30,10).
TEST(CompNctSpec_3_17_4, ArcArcByTheSignOfDUsesTheIntersectionFirst) {
  machine::Setup setup = compSetup(2);
  setup.tools[2].radius = -2;
  ProgramRun r = runNct("G17 G0 X-10 Y10\nG41 G1 X0 D1 F100\nG2 X10 Y0 I0 J-10\n"
                        "G2 X20 Y10 I10 J0 D2\nG40 G1 X30\n",
                        setup);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()), (V{"R -10,10,0", "L 0,12,0 F100", "CW 12,0,0 C0,0 r12 θ90",
                                       "CW 20,8,0 C20,0 r8 θ90", "L 30,10,0 F100"}));
}

// Arc-arc, D sign change, no intersection, shifted centre. N3: CW about (0,0), R = 10, (0,10)
// to (10,0), G41 outside (radius 12), start (0,12). N4: D2 (right), CCW about (20,0) from
// (10,0) to (30,0) via (20,-10); right of CCW is outside, radius 12 about (20,0): 12 + 12 > 20,
// the circles meet at (10,±√44): the intersection (10,-6.6332), nearest (10,0), is used.
// N3 ends there about (0,0) (atan2(12,0) = 90° to atan2(−6.6332,10) = −33.56°: 123.56° CW).
// N4: (10,-6.6332) -> (32,0) about (20,0), r 12 (from −146.44° to 0°, CCW 146.44°).
TEST(CompNctSpec_3_17_4, ArcArcByTheSignOfDCrossingOffsets) {
  machine::Setup setup = compSetup(2);
  setup.tools[2].radius = -2;
  ProgramRun r = runNct("G17 G0 X-10 Y10\nG41 G1 X0 D1 F100\nG2 X10 Y0 I0 J-10\n"
                        "G3 X30 Y0 I10 J0 D2\nG40 G1 Y10\n",
                        setup);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R -10,10,0", "L 0,12,0 F100", "CW 10,-6.6332,0 C0,0 r12 θ123.5573",
               "CCW 32,0,0 C20,0 r12 θ146.4427", "L 30,10,0 F100"}));
}

// The manual's example (000:8016-8040), r = 5: the full circle N50 under G42 (outside, radius
// 55) between lines under G41 (y = −5 before, y = 5 after; the circle is CCW). The offsets
// meet: y = ∓5 on the circle of 55 at x = √(3025 − 25) = √3000 = 54.7723. N40 ends on
// (54.7723,−5); N50 makes its full turn from there and goes on to (54.7723,5): one turn more
// than the sweep of 2·atan(5/54.7723) = 10.4318°, 370.4318° in all; N60 ends on the collinear
// cancel's perpendicular (80,5), N70 goes to (100,0).
TEST(CompNctSpec_3_17_4, FullCircleWithDirectionChangeMakesMoreThanOneTurn) {
  ProgramRun r = runNct("N10 G17 G0 X100 Y0\nN30 G41 X80 D1\nN40 G1 X50 F100\nN50 G42 G3 I-50\n"
                        "N60 G41 G1 X80\nN70 G40 X100\n",
                        compSetup(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R 100,0,0", "R 80,-5,0", "L 54.7723,-5,0 F100",
               "CCW 54.7723,5,0 C0,0 r55 θ370.4318", "L 80,5,0 F100", "L 100,0,0 F100"}));
}

// The impossible case (000:8098-8100), r = 2. N3: CCW half circle about (0,0), R = 10, (0,-10)
// to (0,10), G42 outside (radius 12), start (0,-12). N4: G41 CCW about (3,10), radius 3, from
// (0,10): inside, radius 1 about (3,10), which lies within 10.44 + 1 < 12 of (0,0): no
// intersection. The perpendicular at N4's start is (0,10) + 2·(1,0) = (2,10); the chord from
// (0,-12) is √(4 + 484) = 22.09 > 2R = 20: no arc of radius 10 joins them, 2047 at N3.
TEST(CompNctSpec_3_17_4, ImpossibleShiftedArc2047) {
  ProgramRun r = runNct("G17 G0 X-10 Y-10\nG42 G1 X0 D1 F100\nG3 X0 Y10 I0 J10\n"
                        "G41 G3 X6 Y10 I3 J0\nG40 G1 X10\n",
                        compSetup(2));
  EXPECT_EQ(r.errors, V{"3:1 2047"}) << r.rendered;
}

} // namespace
} // namespace gcx::test
