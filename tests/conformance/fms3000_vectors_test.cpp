// The test vectors of fms3000.md §8 that gcx executes today, one test each, asserting the exact
// motion (machine coordinates, 4 decimals) or the located error. Harness state S0: machine =
// work = (0,0,0), N3021=0, N3031=0, fixed point 1 at X10 Y20 Z300. Programs run as `gcx run`
// runs them: the control-flow engine, then the machine.
#include <gtest/gtest.h>

#include "support/fms3000_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

machine::Setup s0() {
  machine::Setup s;
  s.parameters = {{"N7001", 10}, {"N7101", 20}, {"N7201", 300}};
  return s;
}

machine::Setup withParameter(const char* key, double value) {
  machine::Setup s = s0();
  s.parameters[key] = value;
  return s;
}

V run(const std::string& spec, const machine::Setup& setup = s0()) {
  const MacroRun r = runFms(specBlocks(spec), setup);
  EXPECT_EQ(r.errors, V{}) << r.rendered;
  V m = r.motion();
  if (!m.empty() && m.back() == "END") m.pop_back();
  return m;
}

V errorsOf(const std::string& spec) {
  return runFms(specBlocks(spec), s0()).errors;
}

const V kT1{"R 200,40,0", "CCW 140,100,0 C140,40 r60 θ90", "CW 120,60,0 C90,100 r50 θ53.1301"};

TEST(Fms3000Vectors_8, T1_ArcsIncrementalCentreUnderG90) {
  EXPECT_EQ(run("G0X200Y40 · G90G17G03X140Y100I-60F300 · G02X120Y60I-50 · M30"), kT1);
}

TEST(Fms3000Vectors_8, T2_ArcsIncrementalCentreUnderG91) {
  EXPECT_EQ(run("G0X200Y40 · G91G17G03X-60Y60I-60F300 · G02X-20Y-40I-50 · M30"), kT1);
}

TEST(Fms3000Vectors_8, T3_N3021AbsoluteCentreUnderG91) {
  EXPECT_EQ(run("G0X200Y40 · G91G17G03X-60Y60I140J40F300 · G02X-20Y-40I90J100 · M30",
                withParameter("N3021", 1)),
            kT1);
}

TEST(Fms3000Vectors_8, T4_N3021CentreFollowsG90G91) {
  EXPECT_EQ(run("G0X200Y40 · G90G17G03X140Y100I140J40F300 · G91G02X-20Y-40I-50 · M30",
                withParameter("N3021", 2)),
            kT1);
  // the same program under N3021=0 reads I140 J40 from the start point: another circle
  EXPECT_EQ(errorsOf("G0X200Y40 · G90G17G03X140Y100I140J40F300 · M30"), V{"main.fms:2:1 2012"});
}

TEST(Fms3000Vectors_8, T5_FullCircleByIjkAndArcsByR) {
  EXPECT_EQ(run("G0X10Y0 · G2I-10F100 · G0X0Y0 · G2X10Y10R10 · G0X0Y0 · G2X10Y10R-10 · G0X0Y0 "
                "· G3X20R-10 · M30"),
            (V{"R 10,0,0", "CW 10,0,0 C0,0 r10 θ360", "R 0,0,0", "CW 10,10,0 C10,0 r10 θ90",
               "R 0,0,0", "CW 10,10,0 C0,10 r10 θ270", "R 0,0,0", "CCW 20,0,0 C10,0 r10 θ180"}));
}

TEST(Fms3000Vectors_8, T6_NumbersWithoutAPointAreMillimetres) {
  EXPECT_EQ(run("X10 G90 G1 F200 Y5.5 · Z-.5 · G91 X-10. Y+0 · M30"),
            (V{"L 10,5.5,0 F200", "L 10,5.5,-0.5 F200", "L 0,5.5,-0.5 F200"}));
}

TEST(Fms3000Vectors_8, T7_DwellInTenthsOfASecondAfterTheMotion) {
  EXPECT_EQ(run("G1X10F100G04E25 · G04E5 · M30"), (V{"L 10,0,0 F100", "DW 2.5s", "DW 0.5s"}));
}

TEST(Fms3000Vectors_8, T8_HelixByPitchQuarterTurn) {
  // the manual's example with Y-50 (E17 corrected): 40 mm at 160 per turn is a quarter turn
  EXPECT_EQ(run("G91G2G10X-50Y-50I-50Z40K160F100 · M30"), V{"CW -50,-50,40 C-50,0 r50 θ90"});
}

TEST(Fms3000Vectors_8, T9_HelixOfThreeTurnsEndingAboveItsStart) {
  EXPECT_EQ(run("G0X10 · G3G10X10Y0I-10Z-6K-2F100 · M30"),
            (V{"R 10,0,0", "CCW 10,0,-6 C0,0 r10 θ1080"}));
}

TEST(Fms3000Vectors_8, T10_TheManualsLiteralHelixIsInconsistent) {
  // Y50: 270 degrees in the plane against a quarter turn of travel
  EXPECT_EQ(errorsOf("G91G2G10X-50Y50I-50Z40K160F100"), V{"main.fms:1:23 2015"});
}

TEST(Fms3000Vectors_8, HelixWithoutPitchOrTravel) {
  EXPECT_EQ(errorsOf("G91G2G10X-50Y-50I-50Z40F100"), V{"main.fms:1:6 2015"});       // 001:3840
  EXPECT_EQ(errorsOf("G91G2G10X-50Y-50I-50K160F100"), V{"main.fms:1:1 2015"});      // 001:3844
  EXPECT_EQ(errorsOf("G91G2G10X-50Y-50I-50Z-40K160F100"), V{"main.fms:1:25 2015"}); // sign
}

TEST(Fms3000Helix_3_6, AHelixAlongAnotherFreeAxisIsNotImplementedYet) {
  // the linear axis may be any free axis (001:1433-1436), but no pitch letter is named for one
  // outside X Y Z (fms3000.md §10 Q4): a located GCX030, not "no travel" nor a guessed letter
  EXPECT_EQ(errorsOf("G0X10 · G2G10X10Y0I-10W5K2F100"), V{"main.fms:2:1 GCX030"});
  EXPECT_EQ(errorsOf("G0X10 · G3G10X10Y0I-10A90K90F100"), V{"main.fms:2:1 GCX030"});
}

TEST(Fms3000Vectors_8, T11_ImplicitCoordinateLinesAndQuarterCircles) {
  EXPECT_EQ(run("G1G91X10G47F100 · G1G91X10G48 · G2G91X-10G48 · G2G91Y10G48 · M30"),
            (V{"L 10,10,0 F100", "L 20,0,0 F100", "CW 10,-10,0 C10,0 r10 θ90",
               "CW 0,0,0 C10,0 r10 θ90"}));
}

TEST(Fms3000Vectors_8, T11_TheManualsEquivalentForms) {
  // 001:1470-1508: G1 X10 G48 = G1 Y-10 G47; G2 X-10 G47 = G2 Y10 G48
  EXPECT_EQ(run("G1G91X10G48F100 · M30"), run("G1G91Y-10G47F100 · M30"));
  EXPECT_EQ(run("G2G91X-10G47F100 · M30"), V{"CW -10,10,0 C0,10 r10 θ90"});
  EXPECT_EQ(run("G2G91Y10G48F100 · M30"), V{"CW -10,10,0 C0,10 r10 θ90"});
  EXPECT_EQ(errorsOf("G1G91X10Y5G47F100"), V{"main.fms:1:11 2015"});
}

TEST(Fms3000Vectors_8, T12_FourHolesWithRememberedParameters) {
  // E32: the words before G81 run first; Z and F are remembered from N2
  EXPECT_EQ(run("N1 G54 G0 G90 X10 Z10 · N2 G81 U0.5 Z-15.5 F100 · N3 X30 G81 U-9.5 I-4. · "
                "N4 X45 G81 U-4.5 I0.5 · N5 X65 G81 U0.5 Z-10 I10 · N6 G80 · M30"),
            (V{"R 10,0,10", "R 10,0,0.5", "L 10,0,-15.5 F100", "R 10,0,0.5", "R 30,0,0.5",
               "R 30,0,-9.5", "L 30,0,-15.5 F100", "R 30,0,-9.5", "R 30,0,-4", "R 45,0,-4",
               "R 45,0,-4.5", "L 45,0,-15.5 F100", "R 45,0,-4.5", "R 45,0,0.5", "R 65,0,0.5",
               "L 65,0,-10 F100", "R 65,0,0.5", "R 65,0,10"}));
}

// E38 under N3023 = {81} (bit 0), from Z20: each later block with an axis word runs, then the
// hole with the remembered parameters; G80 ends the repetition, not N3023
TEST(Fms3000Vectors_8, T13_ModalCycleUnderN3023) {
  machine::Setup s = withParameter("N3023", 1);
  s.initialPosition = {0, 0, 20};
  EXPECT_EQ(
      run("G90X100G81U5Z-10I10F50 · X150 · X200 · G80 · X250G81U5Z-10F50 · X300 · X350 · "
          "X400 · G80 · M30",
          s),
      (V{"R 100,0,20",      "R 100,0,5",       "L 100,0,-10 F50", "R 100,0,5",       "R 100,0,10",
         "R 150,0,10",      "R 150,0,5",       "L 150,0,-10 F50", "R 150,0,5",       "R 150,0,10",
         "R 200,0,10",      "R 200,0,5",       "L 200,0,-10 F50", "R 200,0,5",       "R 200,0,10",
         "R 250,0,10",      "R 250,0,5",       "L 250,0,-10 F50", "R 250,0,5",       "R 300,0,5",
         "L 300,0,-10 F50", "R 300,0,5",       "R 350,0,5",       "L 350,0,-10 F50", "R 350,0,5",
         "R 400,0,5",       "L 400,0,-10 F50", "R 400,0,5"}));
}

TEST(Fms3000Cycles_5_1, N3023NamesTheCyclesThatRepeat) {
  machine::Setup s = s0();
  s.initialPosition = {0, 0, 10};
  const std::string program = "G81 U2 Z-5 F100 · X20 · M30";
  const V once{"R 0,0,2", "L 0,0,-5 F100", "R 0,0,2", "R 20,0,2"};
  EXPECT_EQ(run(program, s), once); // N3023 empty: one-shot
  s.parameters["N3023"] = 2;        // bit 1: G82 only
  EXPECT_EQ(run(program, s), once);
  s.parameters["N3023"] = 1 + 4; // G81 and G83
  EXPECT_EQ(run(program, s),
            (V{"R 0,0,2", "L 0,0,-5 F100", "R 0,0,2", "R 20,0,2", "L 20,0,-5 F100", "R 20,0,2"}));
  // a block without an axis word does not drill (§5.1, the open question of §10)
  EXPECT_EQ(run("G81 U2 Z-5 F100 · F50 · G80 X20 · M30", s),
            (V{"R 0,0,2", "L 0,0,-5 F100", "R 0,0,2", "R 20,0,2"}));
}

TEST(Fms3000Vectors_8, T14_DeepDrillingAndTapping) {
  EXPECT_EQ(
      run("G0Z10 · M3S500 · G83U2Z-10V4W1F100 · G80 · G84U5Z-20F300E5 · G80 · M30"),
      (V{"R 0,0,10", "EV S500 M3", "R 0,0,2", "L 0,0,-2 F100", "R 0,0,2", "R 0,0,-1",
         "L 0,0,-6 F100", "R 0,0,2", "R 0,0,-5", "L 0,0,-10 F100", "R 0,0,2", "R 0,0,5",
         "L 0,0,-20 F300", "EV S500 M4", "DW 0.5s", "L 0,0,5 F300", "DW 0.5s", "EV S500 M3"}));
}

TEST(Fms3000Vectors_8, T15_TheCycleAxisFollowsThePlane) {
  EXPECT_EQ(run("G19G0X50Y10Z10 · G81U5Z-10F100 · M30"),
            (V{"R 50,10,10", "R 5,10,10", "L -10,10,10 F100", "R 5,10,10"}));
}

// the worked examples of §5.2 (start X0 Y0 Z10, G17 G90)
TEST(Fms3000Cycles_5_2, WorkedExamples) {
  const std::string start = "G0Z10 · ";
  EXPECT_EQ(run(start + "G81 U2 Z-10 F100 E5 · M30"),
            (V{"R 0,0,10", "R 0,0,2", "L 0,0,-10 F100", "DW 0.5s", "R 0,0,2"}));
  EXPECT_EQ(run(start + "G82 U2 Z-10 F100 H50 I5 · M30"),
            (V{"R 0,0,10", "R 0,0,2", "L 0,0,-10 F100", "L 0,0,2 F50", "R 0,0,5"}));
  EXPECT_EQ(run(start + "M3 S100 · G85 U2 Z-10 F100 · M30"),
            (V{"R 0,0,10", "EV S100 M3", "R 0,0,2", "L 0,0,-10 F100", "EV S100 M5", "R 0,0,2",
               "EV S100 M3"}));
  EXPECT_EQ(run(start + "G86 U2 Z-10 V4 W1 F100 · M30"),
            (V{"R 0,0,10", "R 0,0,2", "L 0,0,-2 F100", "R 0,0,-1", "L 0,0,-6 F100", "R 0,0,-5",
               "L 0,0,-10 F100", "R 0,0,2"}));
  EXPECT_EQ(run(start + "G87 U2 Z-10 V4 W5 F100 · M30"),
            (V{"R 0,0,10", "R 0,0,2", "L 0,0,-2 F100", "DW 0.5s", "L 0,0,-6 F100", "DW 0.5s",
               "L 0,0,-10 F100", "R 0,0,2"}));
  EXPECT_EQ(run(start + "G91 G81 U-8 Z-12 I20 F100 · M30"),
            (V{"R 0,0,10", "R 0,0,2", "L 0,0,-10 F100", "R 0,0,2", "R 0,0,10"}));
}

TEST(Fms3000Cycles_5_1, MandatoryAndExtraParametersAndG80ForgetsThem) {
  EXPECT_EQ(errorsOf("G81 U2 F100"), V{"main.fms:1:1 2004"});        // no Z
  EXPECT_EQ(errorsOf("G81 U2 Z-5 R1 F100"), V{"main.fms:1:1 2004"}); // R is Fanuc's
  EXPECT_EQ(errorsOf("G81 U2 Z-5 F100 · G80 · G81 U1"), V{"main.fms:3:1 2004"});
  EXPECT_EQ(errorsOf("G81 U2 Z-5 F100 · G82 U1"), V{"main.fms:2:1 2004"}); // another cycle
}

TEST(Fms3000Vectors_8, T16_G55G53ModalG54AndG92) {
  machine::Setup s = s0();
  s.workOffsets["G55"] = {500, 200, 100};
  EXPECT_EQ(
      run("G90G55G00X100Y50Z20 · G53G0X0Y0 · X10 · G54G0X50Y50 · G92X0Y0 · G0X10Y10 · M30", s),
      (V{"R 600,250,120", "R 0,0,120", "R 10,0,120", "R 50,50,120", "R 60,60,120"}));
}

TEST(Fms3000Vectors_8, T16_G53IsTheMachineSystemNotG54) {
  machine::Setup s = s0();
  s.workOffsets["G54"] = {1, 2, 3};
  EXPECT_EQ(run("G0X5Y5Z5 · G53G0X0Y0Z0 · X10 · G54G0X0 · M30", s),
            (V{"R 6,7,8", "R 0,0,0", "R 10,0,0", "R 1,0,0"}));
}

TEST(Fms3000Vectors_8, T17_LengthCompensationAndFixedPoints) {
  machine::Setup s = s0();
  s.tools[1].length = 50;
  EXPECT_EQ(run("G0X30Y40Z100 · G43H1 · G0Z10 · G44H1Z10 · G49Z10 · G28X5Y5 · G30Z0 · M30", s),
            (V{"R 30,40,100", "R 30,40,60", "R 30,40,-40", "R 30,40,10", "R 0,0,10", "R 0,0,300"}));
}

TEST(Fms3000Vectors_8, T18_OneSidedPositioningApproachesFromPlus) {
  EXPECT_EQ(run("G0X10 · G60X5 · G60X8 · G91G60X0 · M30"),
            (V{"R 10,0,0", "R 4,0,0", "R 5,0,0", "R 8,0,0", "R 7,0,0", "R 8,0,0"}));
}

TEST(Fms3000Vectors_8, T18_G60IsARapidForOneBlockPerAxis) {
  // under modal G1: X arrives from -, Y from +; the next block feeds again
  EXPECT_EQ(run("G1X10F100 · G60X5Y3 · X6 · M30"),
            (V{"L 10,0,0 F100", "R 4,3,0", "R 5,3,0", "L 6,3,0 F100"}));
}

TEST(Fms3000Vectors_8, T19_MirrorAboutAPointSwapsTheArcDirection) {
  EXPECT_EQ(run("G0X100Y0 · G67X100 · G90G1F100X110 · X140Y15 · G2X180I20J0 · G68X0 · G0X0Y0 · "
                "M30"),
            (V{"R 100,0,0", "L 90,0,0 F100", "L 60,15,0 F100", "CCW 20,15,0 C40,15 r20 θ180",
               "R 0,0,0"}));
}

TEST(Fms3000Vectors_8, T20_RotationByG37AndItsCancelByA0) {
  EXPECT_EQ(run("G37X0Y0A90 · G1X10Y0F100 · X10Y10 · G37A0 · G0X0Y0 · M30"),
            (V{"L 0,10,0 F100", "L -10,10,0 F100", "R 0,0,0"}));
}

TEST(Fms3000Vectors_8, T20_G35EndsTheRotation) {
  // G35 and G37 share group 06 (§10 Q19)
  EXPECT_EQ(run("G37X0Y0A90 · G1X10Y0F100 · G35 · X10Y10 · M30"),
            (V{"L 0,10,0 F100", "L 10,10,0 F100"}));
}

TEST(Fms3000Vectors_8, T21_ScaleFactorsPerAxisAboutTheWorkOrigin) {
  EXPECT_EQ(run("G69X2Y2 · G1X10Y5F100 · G69X1Y1 · G1X10Y5 · M30"),
            (V{"L 20,10,0 F100", "L 10,5,0 F100"}));
}

TEST(Fms3000Vectors_8, T22_PolarCoordinatesAboutAPole) {
  EXPECT_EQ(run("G36X10Y10 · G1I20A30F100 · I20A90 · G3I20A180R20 · G35 · M30"),
            (V{"L 27.3205,20,0 F100", "L 10,30,0 F100", "CCW -10,10,0 C10,10 r20 θ90"}));
}

TEST(Fms3000Polar_3_11, TheRadiusOrTheAngleAloneKeepsTheOther) {
  // G91 has no effect on polar words or the pole; A alone keeps the distance, I alone the angle
  EXPECT_EQ(run("G91 · G36X0Y0 · G1I10A0F100 · A90 · I5 · G35 · X1 · M30"),
            (V{"L 10,0,0 F100", "L 0,10,0 F100", "L 0,5,0 F100", "L 1,5,0 F100"}));
}

TEST(Fms3000Polar_3_11, ThePlaneNamesThePoleAndTheAngleStartsOnItsFirstAxis) {
  // G18: the plane is Z-X, A is measured from Z
  EXPECT_EQ(run("G18 · G36Z0X0 · G1I10A90F100 · I10A0 · G35 · M30"),
            (V{"L 10,0,0 F100", "L 0,0,10 F100"}));
}

TEST(Fms3000Polar_3_11, G37EndsPolarCoordinatesLikeG35) {
  EXPECT_EQ(run("G36X0Y0 · G1I10A90F100 · G37X0Y0A0 · X5 · M30"),
            (V{"L 0,10,0 F100", "L 5,10,0 F100"}));
}

TEST(Fms3000Polar_3_11, BrokenPolarRulesAreLocatedErrors) {
  EXPECT_EQ(errorsOf("G36X10"), V{"main.fms:1:1 FMSX04"});       // no pole on Y
  EXPECT_EQ(errorsOf("G36X10Y10Z5"), V{"main.fms:1:10 FMSX04"}); // pole not in the plane
  EXPECT_EQ(errorsOf("G36X0Y0 · G1I20A30Z5F100"), V{"main.fms:2:9 FMSX04"}); // planar only
  EXPECT_EQ(errorsOf("G36X0Y0 · G1X5F100"), V{"main.fms:2:3 FMSX04"});    // X Y are not polar words
  EXPECT_EQ(errorsOf("G36X0Y0 · G1I-5A0F100"), V{"main.fms:2:3 FMSX04"}); // a negative radius
  EXPECT_EQ(errorsOf("G36X0Y0 · G18"), V{"main.fms:2:1 FMSX04"});         // plane change (001:3859)
}

TEST(Fms3000Vectors_8, T23_RepeatedFragmentThenACall) {
  // L counts the runs of the fragment (§10 Q2); the G25 block itself runs once
  const MacroRun r = runFms({{"main.fms", "G91G25L3\r\nG1X10F100\r\nM25\r\nG90X0P19\r\nM30\r\n"},
                             {"19.fms", "G91G1Y5F100\r\nM99\r\n"}},
                            s0());
  ASSERT_EQ(r.errors, V{}) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L 10,0,0 F100", "L 20,0,0 F100", "L 30,0,0 F100", "L 0,0,0 F100",
                           "L 0,5,0 F100", "END"}));
}

TEST(Fms3000Vectors_8, T23_RepeatsNestAndTheM25BlockRunsEveryTime) {
  EXPECT_EQ(run("G91G1F100 · G25L2 · X1 · G25L2 · Y1 · Z1M25 · X1M25 · M30"),
            (V{"L 1,0,0 F100", "L 1,1,0 F100", "L 1,1,1 F100", "L 1,2,1 F100", "L 1,2,2 F100",
               "L 2,2,2 F100", "L 3,2,2 F100", "L 3,3,2 F100", "L 3,3,3 F100", "L 3,4,3 F100",
               "L 3,4,4 F100", "L 4,4,4 F100"}));
}

TEST(Fms3000Vectors_8, T23_M25WithoutG25) {
  EXPECT_EQ(errorsOf("G1X1F100 · M25 · M30"), V{"main.fms:2:1 2125"});
}

TEST(Fms3000Vectors_8, T24_P19AndP019AreDifferentPrograms) {
  const MacroRun r = runFms({{"main.fms", "P19\r\nP019\r\nM30\r\n"},
                             {"19.fms", "G91G1X1F100\r\nM99\r\n"},
                             {"019.fms", "G91G1Y1F100\r\nM99\r\n"}},
                            s0());
  ASSERT_EQ(r.errors, V{}) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L 1,0,0 F100", "L 1,1,0 F100", "END"}));
}

TEST(Fms3000Calls_2_2, M99RunStandaloneEndsTheProgram) {
  // a unit written as a subprogram, run on its own: its M99 acts like M02, it does not loop
  const MacroRun r = runFms({{"main.fms", "G91G1X1F100\r\nM99\r\nG1Y1\r\n"}}, s0());
  ASSERT_EQ(r.errors, V{}) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L 1,0,0 F100", "END"}));
}

// The lathe vectors run under G18 with X along slot 0; the motion is in machine coordinates,
// so a diameter-programmed X (N7006 = 1) shows as its radius: X94 is 47.
machine::Setup diameterX() {
  return withParameter("N7006", 1);
}

TEST(Fms3000Vectors_8, T26_ChamfersByG166) {
  EXPECT_EQ(run("G18 G0 X120 Z0 · N1G0Z-170 · N2G1X100F1.2 · N3G166Z-70R-3 · N4G166X50R5 · "
                "N5G166Z0R-2 · M30",
                diameterX()),
            (V{"R 60,0,0", "R 60,0,-170", "L 50,0,-170 F1.2", "L 50,0,-73 F1.2", "L 47,0,-70 F1.2",
               "L 30,0,-70 F1.2", "L 25,0,-65 F1.2", "L 25,0,-2 F1.2", "L 23,0,0 F1.2"}));
}

TEST(Fms3000Vectors_8, T27_FilletsByG167) {
  EXPECT_EQ(run("G18 G0 X120 Z0 · N1G0Z-170 · N2G1X100F1.2 · N3G167Z-70R-4 · N4G167X50R7 · "
                "N5G167Z0R-5 · M30",
                diameterX()),
            (V{"R 60,0,0", "R 60,0,-170", "L 50,0,-170 F1.2", "L 50,0,-74 F1.2",
               "CW 46,0,-70 C-74,46 r4 θ90", "L 32,0,-70 F1.2", "CCW 25,0,-63 C-63,32 r7 θ90",
               "L 25,0,-5 F1.2", "CW 20,0,0 C-5,20 r5 θ90"}));
}

TEST(Fms3000Vectors_8, T28_ProfileRoughingWithoutFinishing) {
  EXPECT_EQ(run("G18G90G0X20Z2 · G164Q4F100G0D0.5P1 · G1Z-20 · G1X12Z-10 · G1X8Z0 · endcont · M30"),
            (V{"R 20,0,2", "R 16,0,2", "L 16,0,-15 F100", "R 16.5,0,-15", "R 16.5,0,2", "R 12,0,2",
               "L 12,0,-10 F100", "R 12.5,0,-10", "R 12.5,0,2", "R 20,0,2"}));
}

TEST(Fms3000Vectors_8, T29_ManualE34RoughingThenTheExplicitFinish) {
  // a lathe program: G18 and diameter X; the levels are 1.5 apart in diameter (0.75 in radius),
  // D0.5 is 0.25 in radius
  const V m = run("G18 · N10 G0 Z5 · N20 X100 · N30 G164 Q1.5 F0.5 G0 P1 D0.5 · N40 G1 Z-100 · "
                  "N50 X80 Z-90 · N60 G3 X40 Z-70 R20 · N70 G1 Z-50 · N80 X35 · "
                  "N90 G2 X15 Z-40 R10 · N100 G1 X10 Z0 · endcont · rem finishing pass · "
                  "N110 G0 X10 · N120 G1 Z0 F0.5 · N130 X15 Z-40 · N140 G3 X35 Z-50 R10 · "
                  "N150 G1 X40 · N160 Z-70 · N170 G2 X80 Z-90 R20 · N180 G1 X100 Z-100 · "
                  "N190 G0 Z5 · M30",
                  diameterX());
  ASSERT_EQ(m.size(), 2u + 59 * 4 + 1 + 9);
  EXPECT_EQ(
      V(m.begin(), m.begin() + 10),
      (V{"R 0,0,5", "R 50,0,5", "R 49.25,0,5", "L 49.25,0,-99.25 F0.5", "R 49.5,0,-99.25",
         "R 49.5,0,5", "R 48.5,0,5", "L 48.5,0,-98.5 F0.5", "R 48.75,0,-98.5", "R 48.75,0,5"}));
  // the 59 levels X98.5, X97, ... X11.5 (§8 T29), each reached by the rapid of its pass
  for (int k = 0; k < 59; ++k)
    EXPECT_EQ(m[2 + 4 * k], "R " + n4(49.25 - 0.75 * k) + ",0,5") << "level " << k + 1;
  // level X40 meets N70 along its length: the cut ends at its end nearest z0 (§5.3.1)
  EXPECT_EQ(m[2 + 39 * 4 + 1], "L 20,0,-50 F0.5");
  EXPECT_EQ(
      V(m.end() - 14, m.end()),
      (V{"R 5.75,0,5", "L 5.75,0,-12 F0.5", "R 6,0,-12", "R 6,0,5", "R 50,0,5", "R 5,0,5",
         "L 5,0,0 F0.5", "L 7.5,0,-40 F0.5", "CCW 17.5,0,-50 C-50,7.5 r10 θ90", "L 20,0,-50 F0.5",
         "L 20,0,-70 F0.5", "CW 40,0,-90 C-70,40 r20 θ90", "L 50,0,-100 F0.5", "R 50,0,5"}));
}

TEST(Fms3000Vectors_8, T30_SinglePassTurningWithACone) {
  EXPECT_EQ(run("G18G90G0X30Z2 · G150X20Z-30P10Q25F100 · M30"),
            (V{"R 30,0,2", "L 20,0,2 F100", "L 20,0,-20 F100", "L 25,0,-30 F100", "L 30,0,-30 F100",
               "R 30,0,2"}));
}

TEST(Fms3000Vectors_8, T31_DeepDrillingAlongZThenTheFinalX) {
  EXPECT_EQ(run("G18G90G0X0Z5 · G154U1Z-20V8W1F50X10 · M30"),
            (V{"R 0,0,5", "R 0,0,1", "L 0,0,-7 F50", "R 0,0,1", "R 0,0,-6", "L 0,0,-15 F50",
               "R 0,0,1", "R 0,0,-14", "L 0,0,-20 F50", "R 0,0,1", "R 10,0,1"}));
}

TEST(Fms3000Turning_5_3, G150WithoutAConeAndWithTheRapidFlag) {
  // G0 after the cycle code makes segment 1 a rapid and leaves the modal G1 alone
  EXPECT_EQ(run("G18G90G1X30Z2F100 · G150X20Z-30G0 · X31 · M30"),
            (V{"L 30,0,2 F100", "R 20,0,2", "L 20,0,-30 F100", "L 30,0,-30 F100", "R 30,0,2",
               "L 31,0,2 F100"}));
  // under G91 the positions are distances from the start point
  EXPECT_EQ(run("G18G90G0X30Z2 · G91G150X-10Z-32F100 · M30"),
            (V{"R 30,0,2", "L 20,0,2 F100", "L 20,0,-30 F100", "L 30,0,-30 F100", "R 30,0,2"}));
}

TEST(Fms3000Turning_5_3, G160IsTheChipBreakingSequenceAlongZ) {
  EXPECT_EQ(run("G18G90G0X0Z5 · G160U1Z-20V8W1F50 · M30"),
            (V{"R 0,0,5", "R 0,0,1", "L 0,0,-7 F50", "R 0,0,-6", "L 0,0,-15 F50", "R 0,0,-14",
               "L 0,0,-20 F50", "R 0,0,1"}));
}

TEST(Fms3000Turning_5_3, BadTurningCycleWordsAreLocatedErrors) {
  EXPECT_EQ(errorsOf("G18 G0 X10 Z0 · G166Z-2R-3"), V{"main.fms:2:1 FMSX02"});  // travel < R
  EXPECT_EQ(errorsOf("G17 G0 X10 Z0 · G167Z-20R-3"), V{"main.fms:2:1 FMSX02"}); // not in G18
  EXPECT_EQ(errorsOf("G18 · G150X20Z-30P10F100"), V{"main.fms:2:1 FMSX02"});    // P without Q
  EXPECT_EQ(errorsOf("G18 · G150X20F100"), V{"main.fms:2:1 FMSX02"});           // no Z
  EXPECT_EQ(errorsOf("G18 · G154U1Z-20V8F50"), V{"main.fms:2:1 FMSX02"});       // no W
  EXPECT_EQ(errorsOf("G18 · G150X20Z-30R1F100"), V{"main.fms:2:1 FMSX02"}); // R is no word of G150
}

// The negative vectors: each raises a located error (X1E3 a warning).
TEST(Fms3000Vectors_8, NegativeArcByRadiusZero) {
  EXPECT_EQ(errorsOf("G2X10R0"), V{"main.fms:1:6 GCX037"});
}

TEST(Fms3000Vectors_8, NegativeChordLongerThanTwoR) {
  EXPECT_EQ(errorsOf("G2X30Y0R10"), V{"main.fms:1:8 2015"});
}

TEST(Fms3000Vectors_8, NegativeFullCircleByR) {
  EXPECT_EQ(errorsOf("G2R10"), V{"main.fms:1:3 2015"});
}

TEST(Fms3000Vectors_8, NegativeCentreWordWithG1) {
  EXPECT_EQ(errorsOf("G1X10I5F100"), V{"main.fms:1:6 2015"});
}

TEST(Fms3000Vectors_8, NegativeCycleUnderG20) {
  EXPECT_EQ(errorsOf("G20X0Y0G81U1Z-1"), V{"main.fms:1:8 FMSX02"});
}

TEST(Fms3000Vectors_8, NegativeRadiusCompensationStartingOnAnArc) {
  // the shared compensation stage refuses a start-up on an arc (fms3000.md §4.2)
  EXPECT_EQ(errorsOf("G41D1G2X10Y10I5"), V{"main.fms:1:1 GCX072"});
}

TEST(Fms3000Vectors_8, NegativeG28WithG92) {
  EXPECT_EQ(errorsOf("G28X0G92X0"), V{"main.fms:1:6 GCX012"});
}

TEST(Fms3000Vectors_8, NegativeG25WithoutL) {
  EXPECT_EQ(errorsOf("G25 L"), V{"main.fms:1:5 2004"});
}

TEST(Fms3000Vectors_8, NegativeFeedZero) {
  EXPECT_EQ(errorsOf("G1X10F0"), V{"main.fms:1:1 2004"});
}

TEST(Fms3000Vectors_8, NegativeBlockSkip) {
  EXPECT_EQ(errorsOf("/N10X1"), V{"main.fms:1:1 2064"});
}

TEST(Fms3000Vectors_8, NegativeMacroAssignment) {
  EXPECT_EQ(errorsOf("#1=5"), V{"main.fms:1:1 FMSX01"});
}

TEST(Fms3000Vectors_8, NegativeChamferWithBothAxes) {
  EXPECT_EQ(errorsOf("G166X10Z5R1"), V{"main.fms:1:1 FMSX02"});
}

TEST(Fms3000Vectors_8, NegativeX1E3IsX1WithAnUnusedE) {
  const MacroRun r = runFms(specBlocks("G1X1E3F100 · M30"), s0());
  EXPECT_EQ(r.errors, V{});
  EXPECT_EQ(r.warnings, V{"main.fms:1:5 GCXW10"});
  EXPECT_EQ(r.motion(), (V{"L 1,0,0 F100", "END"}));
}

} // namespace
} // namespace gcx::test
