// G39 with I J K (nct.md §3.17.5, 000:8176-8211): the corner arc about the end point of the
// element before ends on the perpendicular of the vector I J K, at once, whatever comes next;
// exact motion of the manual's two listings (D1 = 5, the manual gives no value) and errors.
// Expected points computed by hand: corner + r * perpendicular of the unit vector.
#include <gtest/gtest.h>

#include "machine/comp_support.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

// 000:8183-8187 (absolute here): N120 G39 I50 J-60 before the cancel; the arc (clockwise under
// G41) ends at (100,0) + 5 * (60,50)/|(50,-60)|, the cancel leaves from there.
TEST(CompNctSpec_3_17_5, G39EndVectorBeforeACancel) {
  ProgramRun r = runNct("G17 G90 G0 X0 Y-10\nG41 G1 X0 Y0 D1 F100\nN110 X100\nN120 G39 I50 J-60\n"
                        "N130 G40 X210 Y30\n",
                        compSetup(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R 0,-10,0", "L -5,5,0 F100", "L 100,5,0 F100",
               "CW 103.8411,3.2009,0 C100,0 r5 θ50.1944", "L 210,30,0 F100"}));
}

// The manual's triangular slot (000:8195-8211): G42 outside a counter-clockwise triangle, G39
// at each corner; at the last one I J repeat N60's move so that the contour closes on N60's
// start vector. N130 then starts with a move to its own start perpendicular.
TEST(CompNctSpec_3_17_5, G39ClosesTheTriangleSlot) {
  ProgramRun r = runNct("N20 G0 G17 G40 G54\nN30 X-30 Y150 Z5 M3 S300\nN40 G42 X0 Y86.603 D1\n"
                        "N50 Z-2\nN60 G1 X-50 Y0 F1000\nN70 G39\nN80 X50\nN90 G39\n"
                        "N100 X0 Y86.603\nN110 G39 I-50 J-86.603\nN120 Z5\nN130 X-40\n"
                        "N140 G40 Y120\n",
                        compSetup(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R -30,150,5", "EV S300 M3", "R -4.3301,89.103,5", "R -4.3301,89.103,-2",
               "L -54.3301,2.5,-2 F1000", "CCW -50,-5,-2 C-50,0 r5 θ119.9999", "L 50,-5,-2 F1000",
               "CCW 54.3301,2.5,-2 C50,0 r5 θ119.9999", "L 4.3301,89.103,-2 F1000",
               "CCW -4.3301,89.103,-2 C0,86.603 r5 θ120.0003", "L -4.3301,89.103,5 F1000",
               "L 0,91.603,5 F1000", "L -40,91.603,5 F1000", "L -40,120,5 F1000"}));
}

// 000:8190-8191: mirror turns the vector I J K (and swaps G41/G42), scaling does not count.
TEST(CompNctSpec_3_17_5, G39EndVectorUnderMirrorAndScaling) {
  ProgramRun r = runNct("G17 G90 G0 X0 Y-10\nG51.1 X0\nG51 X0 Y0 P2\nG41 G1 X0 Y0 D1 F100\n"
                        "X50\nG39 I50 J-60\nG40 X105 Y15\n",
                        compSetup(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R 0,-10,0", "L 5,5,0 F100", "L -100,5,0 F100",
               "CCW -103.8411,3.2009,0 C-100,0 r5 θ50.1944", "L -210,30,0 F100"}));
}

TEST(CompNctSpec_3_17_5, G39WithAxisWordsGCX079) {
  ProgramRun r =
      runNct("G17 G90 G0 X0 Y-10\nG41 G1 X0 Y0 D1 F100\nX100\nG39 X110 I1\n", compSetup(5));
  EXPECT_EQ(r.errors, V{"4:1 GCX079"}) << r.rendered;
}

TEST(CompNctSpec_3_17_5, G39VectorOutsideThePlaneOrZeroGCX079) {
  const std::string head = "G17 G90 G0 X0 Y-10\nG41 G1 X0 Y0 D1 F100\nX100\n";
  EXPECT_EQ(runNct(head + "G39 I1 K1\n", compSetup(5)).errors, V{"4:8 GCX079"});
  EXPECT_EQ(runNct(head + "G39 I0 J0\n", compSetup(5)).errors, V{"4:1 GCX079"});
}

TEST(CompNctSpec_3_17_5, G39VectorWithoutAnElementBeforeGCX079) {
  ProgramRun r = runNct("G17 G90 G0 X0 Y-10\nG41 D1\nG39 I1\n", compSetup(5));
  EXPECT_EQ(r.errors, V{"3:1 GCX079"}) << r.rendered;
}

} // namespace
} // namespace gcx::test
