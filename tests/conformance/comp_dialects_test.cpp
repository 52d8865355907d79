// Radius compensation of FMS-3000 (fms3000.md §4.2) and WL4 (wl4.md §4.2) through the shared
// compensation stage, with the corner rules of their profiles: exact tool-centre motion (D1 =
// 5), computed by hand from the rules, and T25 of fms3000.md §8.
#include <gtest/gtest.h>

#include "machine/comp_support.h"
#include "support/fms3000_support.h"
#include "support/run_support.h"
#include "support/wl4_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

std::string fmsBlocks(const std::string& spec) { // "a · b" -> one block a line
  std::string out;
  std::size_t from = 0;
  for (std::size_t at; (at = spec.find(" · ", from)) != std::string::npos; from = at + 4)
    out += spec.substr(from, at - from) + "\n";
  return out + spec.substr(from) + "\n";
}

// fms3000.md §8 T25: G14 (power-on) passes the outer corners on arcs of the radius; start-up
// and cancel end on the perpendiculars.
TEST(CompFms3000_4_2, T25OuterCornersOnArcs) {
  MacroRun r = runFms(fmsBlocks("G0X-10Y-10 · G1G41D1X0Y0F100 · Y20 · X20 · Y0 · X0 · "
                                "G0G40X-10Y-10 · M30"),
                      compSetup(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R -10,-10,0", "L -5,0,0 F100", "L -5,20,0 F100", "CW 0,25,0 C0,20 r5 θ90",
               "L 20,25,0 F100", "CW 25,20,0 C20,20 r5 θ90", "L 25,0,0 F100",
               "CW 20,-5,0 C20,0 r5 θ90", "L 0,-5,0 F100", "R -10,-10,0"}));
}

// 001:1971-1975: the start-up ends perpendicular to the next move even at an outer corner (NCT
// would go to the offsets' intersection (-5,5)); the cancel's corner is not processed: the
// last element ends on its own perpendicular (fms3000.md §4.2).
TEST(CompFms3000_4_2, StartUpAndCancelOnThePerpendiculars) {
  MacroRun r = runFms("G0X0Y-10\nG1G41D1X0Y0F100\nX30\nG0G40X30Y-10\nM30\n", compSetup(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R 0,-10,0", "L 0,5,0 F100", "L 30,5,0 F100", "R 30,-10,0"}));
}

// 001:1938-1940: up to 10 blocks without motion in the plane; the 11th stops the run.
TEST(CompFms3000_4_2, TenBlocksWithoutPlaneMotion) {
  std::string ten;
  for (int i = 0; i < 10; ++i)
    ten += "G4E1\n";
  MacroRun ok = runFms("G0X0Y-10\nG1G41D1X0Y0F100\nY30\n" + ten + "X30\nM30\n", compSetup(5));
  ASSERT_TRUE(ok.errors.empty()) << ok.rendered;
  EXPECT_EQ(compMotion(ok.motion()).at(2), "L -5,30,0 F100");
  MacroRun stop =
      runFms("G0X0Y-10\nG1G41D1X0Y0F100\nY30\n" + ten + "G4E1\nX30\nM30\n", compSetup(5));
  EXPECT_EQ(stop.errors, V{"main.fms:3:1 2090"}) << stop.rendered;
}

// fms3000.md §3.7: a G47 line (+10 on both axes) is compensated like any line: start-up and
// cancel on its perpendiculars, 5 * (-0.7071, 0.7071) from its ends.
TEST(CompFms3000_4_2, ImplicitCoordinateG47Compensated) {
  MacroRun r = runFms("G0X0Y-10\nG1G41D1X0Y0F100\nG91X10G47\nG90G0G40X20Y0\nM30\n", compSetup(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R 0,-10,0", "L -3.5355,3.5355,0 F100", "L 6.4645,13.5355,0 F100", "R 20,0,0"}));
}

// wl4.md §4.2: an outer corner whose offsets leave a gap above Delt_L is passed on an arc
// about the corner point (the same square as T25).
TEST(CompWl4_4_2, OuterCornersOnArcs) {
  MacroRun r = runWl4("%T\nG0 X-10 Y-10\nG1 G41 D1 X0 Y0 F100\nY20\nX20\nY0\nX0\n"
                      "G0 G40 X-10 Y-10\nM2\n%\n",
                      compSetup(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R -10,-10,0", "L -5,0,0 F100", "L -5,20,0 F100", "CW 0,25,0 C0,20 r5 θ90",
               "L 20,25,0 F100", "CW 25,20,0 C20,20 r5 θ90", "L 25,0,0 F100",
               "CW 20,-5,0 C20,0 r5 θ90", "L 0,-5,0 F100", "R -10,-10,0"}));
}

// 002:1400-1411: a gap dL = 2r sin(turn/2) = 0.005 mm, not above Delt_L = 0.01: the offsets'
// intersection (100.0025,-5), no arc.
TEST(CompWl4_4_2, NearlySmoothCornerAtTheIntersection) {
  MacroRun r = runWl4("%T\nG0 X-10 Y0\nG1 G42 D1 X0 Y0 F100\nX100\nX200 Y0.1\n"
                      "G0 G40 X300 Y0.2\nM2\n%\n",
                      compSetup(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()), (V{"R -10,0,0", "L 0,-5,0 F100", "L 100.0025,-5,0 F100",
                                       "L 200.005,-4.9,0 F100", "R 300,0.2,0"}));
}

// Inner corners: the offsets' intersection, as in NCT ([F], wl4.md §4.2).
TEST(CompWl4_4_2, InnerCornersAtTheIntersection) {
  MacroRun r = runWl4("%T\nG0 X-10 Y0\nG1 G41 D1 X0 Y0 F100\nX20\nY20\nX0\nY0\n"
                      "G0 G40 X0 Y-10\nM2\n%\n",
                      compSetup(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R -10,0,0", "L 0,5,0 F100", "L 15,5,0 F100", "L 15,15,0 F100", "L 5,15,0 F100",
               "L 5,0,0 F100", "R 0,-10,0"}));
}

// 002:1397-1400: blocks without motion under compensation are "not recommended" (the control
// reads one block ahead, so it cannot process the corner across them): each one warns at its
// block; the blocks that move in the plane, the cancel and a block of statements only do not.
TEST(CompWl4_4_2, BlocksWithoutPlaneMotionWarn) {
  MacroRun r = runWl4("%T\nG0 X-10 Y0\nG1 G41 D1 X0 Y0 F100\nX20\nM8\n#1=1\nY20\nZ-1\nX0\n"
                      "G0 G40 X-10 Y30\nM2\n%\n",
                      compSetup(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  V at;
  for (const std::string& w : r.warnings)
    at.push_back(w.substr(w.find(':') + 1, w.find(' ') - w.find(':') - 1) + w.substr(w.find(' ')));
  EXPECT_EQ(at, (V{"5:1 GCXW25", "8:1 GCXW25"})) << r.rendered; // not the statement's block
  // the corners are processed across them all the same (gcx's look-ahead)
  EXPECT_EQ(compMotion(r.motion()), (V{"R -10,0,0", "L 0,5,0 F100", "L 15,5,0 F100", "EV M8",
                                       "L 15,15,0 F100", "L 15,15,-1 F100", "L 0,15,-1 F100",
                                       "CW -3.5355,16.4645,-1 C0,20 r5 θ45", "R -10,30,-1"}))
      << r.rendered;
}

TEST(CompWl4_4_2, AFullCircleByItsCentreMovesInThePlane) {
  // G2 with I alone has no plane word, yet it moves: no warning
  MacroRun r = runWl4("%T\nG0 X-10 Y0\nG1 G41 D1 X0 Y0 F100\nG2 I10 J0\nG0 G40 X-10 Y0\nM2\n%\n",
                      compSetup(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_TRUE(r.warnings.empty()) << r.rendered;
  // G41 on a clockwise circle: outside it, at 10 + 5
  EXPECT_EQ(compMotion(r.motion()),
            (V{"R -10,0,0", "L -5,0,0 F100", "CW -5,0,0 C10,0 r15 θ360", "R -10,0,0"}))
      << r.rendered;
}

TEST(CompWl4_4_2, AContourThatMovesInEveryBlockDoesNotWarn) {
  MacroRun r = runWl4("%T\nG0 X-10 Y-10\nG1 G41 D1 X0 Y0 F100\nY20\nX20\nY0\nX0\n"
                      "G0 G40 X-10 Y-10\nM2\n%\n",
                      compSetup(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_TRUE(r.warnings.empty()) << r.rendered;
}

} // namespace
} // namespace gcx::test
