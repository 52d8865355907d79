// The internal contour cycles G76, G77 P Q and G78 P Q (wl4.md §5.6, 002:2871-3476) on the lathe
// profile: X words are diameters, the motion holds radii. Every expected path is worked by hand
// from the spec's reference algorithm [D] (the manual's figures are lost): its worked example
// (`G77 P200 Q202 G1 X30 Z0 I0 K0 E2.5 F0.25` from A = X50 Z2 -> passes X45, 40, 35, 30), and
// the same rules for the finishing pass, the transverse cycle, the approach cycle, the linear and
// the equidistant allowances. A G77/G78 block without P is the open cycle of %1 (§5.5).
#include <gtest/gtest.h>

#include "support/wl4_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

// A at X50 Z2; the block of the cycle on line 3; the contour after M2 (002:3244-3250): from
// P = X30 Z0 along Z to Z-20, a taper to X40 Z-30, a face up to X50
MacroRun contourRun(const std::string& cycle, const machine::Setup& s = wl4Lathe()) {
  return runWl4(
      "%P\nG18 G90 G0 X50 Z2\n" + cycle + "\nM2\nN200 G1 Z-20\nN201 X40 Z-30\nN202 X50\n%\n", s);
}

TEST(Wl4ContourCycles_5_6, TheSpecsWorkedG77Example) {
  MacroRun r = contourRun("G77 P200 Q202 G1 X30 Z0 I0 K0 E2.5 F0.25");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // passes X45, 40, 35, 30: in from the last pass's X at Z2, along Z to the contour, out along
  // it to the last pass's X, back to Z2; then to A
  EXPECT_EQ(r.motion(), (V{"R 25,0,2",
                           // X45: the contour is met on the face N202
                           "L 22.5,0,2 F0.25", "L 22.5,0,-30 F0.25", "L 25,0,-30 F0.25", "R 25,0,2",
                           // X40: at the taper's end, out along the face
                           "L 20,0,2 F0.25", "L 20,0,-30 F0.25", "L 22.5,0,-30 F0.25", "R 22.5,0,2",
                           // X35: on the taper, out along it
                           "L 17.5,0,2 F0.25", "L 17.5,0,-25 F0.25", "L 20,0,-30 F0.25", "R 20,0,2",
                           // X30: from Z2 along the cylinder N200 in one cut, out on the taper
                           "L 15,0,2 F0.25", "L 15,0,-20 F0.25", "L 17.5,0,-25 F0.25", "R 17.5,0,2",
                           "R 25,0,2", "END"}));
}

TEST(Wl4ContourCycles_5_6, G77WithoutPIsStillTheOpenCycleOfPercent1) {
  // TV16 in the same program shape: #1 #2 #3 and no P
  MacroRun r = contourRun("G77 X40 Z-30 F0.3 #1=4 #2=2.5 #3=0.1");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 25,0,2", "R 23,0,2", "L 23,0,-29 F0.3", "R 25,0,-25", "R 25,0,2",
                           "R 21,0,2", "L 21,0,-28 F0.3", "R 23,0,-24", "R 23,0,2", "R 20,0,2",
                           "L 20,0,-27.5 F0.1", "L 25,0,-30 F0.1", "R 25,0,2", "END"}));
}

TEST(Wl4ContourCycles_5_6, ALastLevelIsClippedToTheContoursDeepestPoint) {
  // E3 (6 on the diameter): X44, 38, 32, then 26 is past the contour's X30: clipped to it
  MacroRun r = contourRun("G77 P200 Q202 G0 X30 Z0 E3 F0.25");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 25,0,2",         "R 22,0,2", "L 22,0,-30 F0.25", "L 25,0,-30 F0.25",
                           "R 25,0,2",         "R 19,0,2", "L 19,0,-28 F0.25", "L 20,0,-30 F0.25",
                           "L 22,0,-30 F0.25", "R 22,0,2", "R 16,0,2",         "L 16,0,-22 F0.25",
                           "L 19,0,-28 F0.25", "R 19,0,2", "R 15,0,2",         "L 15,0,-20 F0.25",
                           "L 16,0,-22 F0.25", "R 16,0,2", "R 25,0,2",         "END"}));
}

TEST(Wl4ContourCycles_5_6, FinishingPassThenTheFeedBeforeTheCycle) {
  MacroRun r = runWl4("%P\nG18 G90 G0 X50 Z2 F0.3\nG77 P200 Q202 G1 X30 Z0 I0.5 K0.2 F0.1\n"
                      "G1 Z1\nM2\nN200 G1 Z-20\nN201 X40 Z-30\nN202 X50\n%\n",
                      wl4Lathe());
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(),
            (V{"R 25,0,2", "L 15.5,0,0.2 F0.1", "L 15.5,0,-19.8 F0.1", "L 20.5,0,-29.8 F0.1",
               "L 25.5,0,-29.8 F0.1", "R 25,0,-29.8", "R 25,0,2", "L 25,0,1 F0.3", "END"}));
}

TEST(Wl4ContourCycles_5_6, EquidistantAllowanceOnTheRightOfTravel) {
  // G42 R0.5: the contour X30 -> Z-20 -> X50 offset 0.5 to the right of its travel (+X along
  // -Z, +Z along +X); the inner corner at the offsets' intersection Z-19.5 X31
  MacroRun r = runWl4("%P\nG18 G90 G0 X50 Z2\nG77 P200 Q201 G42 G1 X30 Z0 R0.5 F0.1\nM2\n"
                      "N200 G1 Z-20\nN201 X50\n%\n",
                      wl4Lathe());
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 25,0,2", "L 15.5,0,0 F0.1", "L 15.5,0,-19.5 F0.1",
                           "L 25,0,-19.5 F0.1", "R 25,0,2", "END"}));
}

TEST(Wl4ContourCycles_5_6, EquidistantAllowanceGoesRoundAnOuterCornerOnAnArc) {
  // G41 R0.5: 0.5 to the left of travel (-X along -Z, -Z along +X); the corner Z-20 X30 is
  // outer on that side: an arc of 0.5 about it, clockwise as the contour turns
  MacroRun r = runWl4("%P\nG18 G90 G0 X50 Z2\nG77 P200 Q201 G41 G1 X30 Z0 R0.5 F0.1\nM2\n"
                      "N200 G1 Z-20\nN201 X50\n%\n",
                      wl4Lathe());
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(),
            (V{"R 25,0,2", "L 14.5,0,0 F0.1", "L 14.5,0,-20 F0.1", "CW 15,0,-20.5 C-20,15 r0.5 θ90",
               "L 25,0,-20.5 F0.1", "R 25,0,2", "END"}));
}

TEST(Wl4ContourCycles_5_6, AClosedZoneIsCutLevelByLevelBetweenItsWalls) {
  // the contour dips into a groove after P (X30 Z0): down to X20 at Z-10, along to Z-16, up to
  // X40, on to Z-20, up to X50. Levels X45, 40, 35, 30 (P's) reach the contour from A; X25 and
  // X20 (the groove's floor) lie in the groove only: from A's level down onto its near wall at
  // the previous level, along the wall, across, up the far wall, back up to A's level [D]
  MacroRun r = runWl4("%P\nG18 G90 G0 X50 Z2\nG77 P200 Q205 G1 X30 Z0 E2.5 F0.2\nM2\n"
                      "N200 G1 Z-10\nN201 X20\nN202 Z-16\nN203 X40\nN204 Z-20\nN205 X50\n%\n",
                      wl4Lathe());
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(),
            (V{"R 25,0,2", "L 22.5,0,2 F0.2", "L 22.5,0,-20 F0.2", "L 25,0,-20 F0.2", "R 25,0,2",
               "L 20,0,2 F0.2", "L 20,0,-20 F0.2", "L 22.5,0,-20 F0.2", "R 22.5,0,2",
               "L 17.5,0,2 F0.2", "L 17.5,0,-16 F0.2", "L 20,0,-16 F0.2", "R 20,0,2",
               // X30: across the groove's top
               "L 15,0,2 F0.2", "L 15,0,-16 F0.2", "L 17.5,0,-16 F0.2", "R 17.5,0,2",
               // X25: in the groove
               "R 25,0,2", "R 25,0,-10", "R 15,0,-10", "L 12.5,0,-10 F0.2", "L 12.5,0,-16 F0.2",
               "L 15,0,-16 F0.2", "R 25,0,-16",
               // X20: the groove's floor
               "R 25,0,-10", "R 12.5,0,-10", "L 10,0,-10 F0.2", "L 10,0,-16 F0.2",
               "L 12.5,0,-16 F0.2", "R 25,0,-16", "R 25,0,2", "END"}));
}

TEST(Wl4ContourCycles_5_6, G78LevelsAlongZCutsAlongX) {
  // A = X60 Z2, P = X60 Z-6; the contour faces in to X30, tapers to X20 Z-1 and runs up to Z2.
  // Levels Z-0.5, -3, -5.5 and -6 (E2.5, the last clipped), infeed at rapid (G0)
  MacroRun r = runWl4("%P\nG18 G90 G0 X60 Z2\nG78 P300 Q302 G0 X60 Z-6 E2.5 F0.2\nM2\n"
                      "N300 G1 X30\nN301 X20 Z-1\nN302 Z2\n%\n",
                      wl4Lathe());
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(),
            (V{"R 30,0,2",           "R 30,0,-0.5", "L 10,0,-0.5 F0.2", "L 10,0,2 F0.2",
               "R 30,0,2",           "R 30,0,-3",   "L 12,0,-3 F0.2",   "L 10,0,-1 F0.2",
               "L 10,0,-0.5 F0.2",   "R 30,0,-0.5", "R 30,0,-5.5",      "L 14.5,0,-5.5 F0.2",
               "L 12,0,-3 F0.2",     "R 30,0,-3",   "R 30,0,-6",        "L 15,0,-6 F0.2",
               "L 14.5,0,-5.5 F0.2", "R 30,0,-5.5", "R 30,0,2",         "END"}));
}

TEST(Wl4ContourCycles_5_6, G76PassesApproachTheContourByTheInitialAllowance) {
  // U2 W0 E1: N = 2 passes, shifted by U·(N-i)/N on X (radius): +1, then 0 (I K are 0); each
  // G1 A -> P_i, along the contour, G0 back to A
  MacroRun r = contourRun("G76 G1 X30 Z0 P200 Q202 I0 K0 U2 W0 E1 F0.2");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 25,0,2", "L 16,0,0 F0.2", "L 16,0,-20 F0.2", "L 21,0,-30 F0.2",
                           "L 26,0,-30 F0.2", "R 25,0,2", "L 15,0,0 F0.2", "L 15,0,-20 F0.2",
                           "L 20,0,-30 F0.2", "L 25,0,-30 F0.2", "R 25,0,2", "END"}));
}

TEST(Wl4ContourCycles_5_6, TheCycleBlockGivesItsStartPointTo130To135) {
  // #130 #131: X of P and its increment from A, diameters; G76's U is an allowance, no move
  MacroRun r = runWl4("%P\nG18 G90 G0 X50 Z2\nG76 G1 X30 Z0 P200 Q202 U2 E2 F0.2\n"
                      "#1=#130 #2=#131 #3=#134 #4=#135\nG0 X#1 Z#2\nG0 X#3 Z#4\nM2\n"
                      "N200 G1 Z-20\nN201 X40 Z-30\nN202 X50\n%\n",
                      wl4Lathe());
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  const V m = r.motion();
  ASSERT_GE(m.size(), 3u);
  // X30 (radius 15) Z-20; then X0 (#134 = 0) Z-2 (#135 = 0 - 2)
  EXPECT_EQ(V(m.end() - 3, m.end()), (V{"R 15,0,-20", "R 0,0,-2", "END"}));
}

TEST(Wl4ContourCycles_5_6, G76FinishingWithTheToolsNoseRadiusUnderG42) {
  // no E: one pass; G42 with tool 1's nose radius 0.4 and corrector D2 = 0.1: the nose centre
  // runs 0.5 right of the contour X30 -> Z-20 -> X50 (as the R0.5 test above)
  machine::Setup s = wl4Lathe();
  s.tools[1].noseRadius = 0.4;
  s.tools[2].radius = 0.1;
  MacroRun r = runWl4("%P\nG18 G90 T1 D2 G0 X50 Z2\nG76 G42 G1 X30 Z0 P200 Q201 F0.1\nM2\n"
                      "N200 G1 Z-20\nN201 X50\n%\n",
                      s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 25,0,2", "L 15.5,0,0 F0.1", "L 15.5,0,-19.5 F0.1",
                           "L 25,0,-19.5 F0.1", "R 25,0,2", "END"}));
}

TEST(Wl4ContourCycles_5_6, FSTAndMInsideTheContourAreIgnored) {
  MacroRun r = runWl4("%P\nG18 G90 G0 X50 Z2\nG77 P200 Q201 G1 X30 Z0 F0.1\nM2\n"
                      "N200 G1 Z-20 F5 S900 M8\nN201 X50 T3\n%\n",
                      wl4Lathe());
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 25,0,2", "L 15,0,0 F0.1", "L 15,0,-20 F0.1", "L 25,0,-20 F0.1",
                           "R 25,0,2", "END"}));
}

TEST(Wl4ContourCycles_5_6, CompensationIsOffAfterTheCycle) {
  // the cycle's G42 acts inside it only (002:3006-3008): the next moves are the programmed path;
  // #102 reads G40 again, #108 the cycle (§2.2)
  machine::Setup s = wl4Lathe();
  s.tools[2].radius = 1;
  MacroRun r =
      runWl4("%P\nG18 G90 D2 G0 X50 Z2\nG77 P200 Q201 G42 G1 X30 Z0 F0.1\n"
             "G1 X60 Z5 F0.2\n#1=#102 #2=#108\nG0 X#1 Z#2\nM2\nN200 G1 Z-20\nN201 X50\n%\n",
             s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 25,0,2", "L 16,0,0 F0.1", "L 16,0,-19 F0.1", "L 25,0,-19 F0.1",
                           "R 25,0,2", "L 30,0,5 F0.2", "R 20,0,77", "END"}));
}

TEST(Wl4ContourCycles_5_6, TheContourOfTheManualsExample21Runs) {
  // §7 example 21 (002:3114-3125): A = X10 Z40 lies inside the contour's Z range (§10.10), and
  // the G2 arc N121 dips below P's X2 (a closed zone); it runs from A back to A
  MacroRun r = runWl4("%TEST_G77_1\nG18 G95\nN9 G0 X10 Z40\n"
                      "N10 G77 G0 X2 Z45 P120 Q124 I0.5 K0.5 E2 F0.7 S500 M3\nM2\n"
                      "N120 G1 Z35 F0.3\nN121 G2 X5 Z25 R10\nN122 G3 X7 Z20 R8\n"
                      "N123 G1 X8.5 Z18\nN124 Z5\n%\n",
                      wl4Lathe());
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  const V m = r.motion();
  ASSERT_GE(m.size(), 4u);
  EXPECT_EQ(m[0], "R 5,0,40");
  EXPECT_EQ(m[1], "EV S500 M3");
  EXPECT_EQ(m[m.size() - 2], "R 5,0,40");
  EXPECT_EQ(m.back(), "END");
}

// --- bad input: each error with its code and place --------------------------------------------

std::vector<std::string> errorsOf(const std::string& cycle, const std::string& contour) {
  return errorsAt(
      runWl4("%P\nG18 G90 G0 X50 Z2\n" + cycle + "\nM2\n" + contour + "%\n", wl4Lathe()));
}

const std::string kContour = "N200 G1 Z-20\nN201 X40 Z-30\nN202 X50\n";

TEST(Wl4ContourCycles_5_6, AContourNotMonotonicInZIsAnError) {
  EXPECT_EQ(
      errorsOf("G77 P200 Q202 G1 X30 Z0 E2.5 F0.25", "N200 G1 Z-20\nN201 X40 Z-10\nN202 X50\n"),
      (V{"6:1 CYC-NONMONOTONIC"}));
}

TEST(Wl4ContourCycles_5_6, AG78ContourNotMonotonicInXIsAnError) {
  EXPECT_EQ(errorsAt(runWl4("%P\nG18 G90 G0 X60 Z2\nG78 P300 Q302 G0 X60 Z-6 E2.5 F0.2\nM2\n"
                            "N300 G1 X30\nN301 X40 Z-1\nN302 Z2\n%\n",
                            wl4Lathe())),
            (V{"6:1 CYC-NONMONOTONIC"}));
}

TEST(Wl4ContourCycles_5_6, MoreThan200ContourBlocksIsAnError) {
  std::string contour;
  for (int n = 1000; n <= 1200; ++n) // 201 blocks
    contour += "N" + std::to_string(n) + " G1 Z-" + std::to_string(n - 999) + "\n";
  EXPECT_EQ(errorsOf("G77 P1000 Q1200 G1 X30 Z0 E2.5 F0.25", contour), (V{"3:11 CYC-PARAM"}));
  contour.clear();
  for (int n = 1000; n < 1200; ++n) // 200 blocks: allowed
    contour += "N" + std::to_string(n) + " G1 Z-" + std::to_string(n - 999) + "\n";
  EXPECT_TRUE(errorsOf("G77 P1000 Q1199 G1 X30 Z0 E2.5 F0.25", contour).empty());
}

TEST(Wl4ContourCycles_5_6, PAndQMustNameBlocksOfTheProgram) {
  EXPECT_EQ(errorsOf("G77 P500 Q502 G1 X30 Z0 E2.5 F0.25", kContour), (V{"3:5 CYC-PQ-NOTFOUND"}));
  EXPECT_EQ(errorsOf("G76 G1 X30 Z0 P200 E1 U2 F0.2", kContour), (V{"3:1 CYC-PQ-NOTFOUND"}));
}

TEST(Wl4ContourCycles_5_6, AForbiddenGCodeInTheContourIsAnError) {
  // only groups 1 (without G32, G33), 3 and 8 (002:2901-2905)
  EXPECT_EQ(
      errorsOf("G77 P200 Q202 G1 X30 Z0 E2.5 F0.25", "N200 G1 Z-20\nN201 G32 X40 Z-30\nN202 X50\n"),
      (V{"6:6 CYC-CONTOUR-CMD"}));
  EXPECT_EQ(
      errorsOf("G77 P200 Q202 G1 X30 Z0 E2.5 F0.25", "N200 G1 Z-20\nN201 G4 X40 Z-30\nN202 X50\n"),
      (V{"6:6 CYC-CONTOUR-CMD"}));
}

TEST(Wl4ContourCycles_5_6, WrongCycleWordsAreLocatedErrors) {
  EXPECT_EQ(errorsOf("G77 P200 Q202 G1 X30 Z0 E0 F0.25", kContour), (V{"3:25 CYC-PARAM"}));
  EXPECT_EQ(errorsOf("G77 P200 Q202 G1 X30 Z0 R0.5 F0.25", kContour), (V{"3:25 CYC-PARAM"}));
  EXPECT_EQ(errorsOf("G77 P200 Q202 G42 G1 X30 Z0 I0.1 R0.5 F0.25", kContour),
            (V{"3:34 CYC-PARAM"}));
  EXPECT_EQ(errorsOf("G76 G1 X30 Z0 P200 Q202 E1 F0.2", kContour), (V{"3:25 CYC-PARAM"}));
  // A level with the contour's start along X: no infeed direction
  EXPECT_EQ(errorsOf("G77 P200 Q202 G1 X50 Z0 E2.5 F0.25", kContour), (V{"3:1 CYC-PARAM"}));
  // no feed at all
  EXPECT_EQ(errorsOf("G77 P200 Q202 G1 X30 Z0 E2.5", kContour), (V{"3:1 2004"}));
}

TEST(Wl4ContourCycles_5_6, CompensationMustBeOffBeforeTheCycle) {
  EXPECT_EQ(errorsOf("G42 G1 X52 F0.1\nG77 P200 Q202 G1 X30 Z0 E2.5 F0.25", kContour),
            (V{"4:1 CYC-PARAM"}));
}

TEST(Wl4ContourCycles_5_6, AnEquidistantThatDoesNotFitIsAnError) {
  // G41 R3 on the left of a contour with an inner arc of radius 2: the arc cannot shrink by 3
  EXPECT_EQ(errorsAt(runWl4("%P\nG18 G90 G0 X50 Z2\nG77 P200 Q202 G41 G1 X30 Z0 R3 F0.1\nM2\n"
                            "N200 G1 Z-20\nN201 G3 X34 Z-22 R2\nN202 G1 X50\n%\n",
                            wl4Lathe())),
            (V{"6:1 CYC-PARAM"}));
}

} // namespace
} // namespace gcx::test
