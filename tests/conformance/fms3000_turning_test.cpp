// The FMS-3000 turning cycles of fms3000.md §5.3 beyond the §8 vectors, one test per cycle
// named after its table: the exact motion (machine coordinates, 4 decimals) of each
// reconstructed [R] sequence, and located errors for bad parameters. Lathe work under G18 with
// X in slot 0; a diameter-programmed X (N7006 = 1) shows as its radius.
#include <gtest/gtest.h>

#include "support/fms3000_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

machine::Setup radiusX() {
  return {};
}

machine::Setup diameterX() {
  machine::Setup s;
  s.parameters["N7006"] = 1;
  return s;
}

V run(const std::string& program, const machine::Setup& setup = radiusX()) {
  const MacroRun r = runFms(program, setup);
  EXPECT_EQ(r.errors, V{}) << r.rendered;
  V m = r.motion();
  if (!m.empty() && m.back() == "END") m.pop_back();
  return m;
}

V errorsOf(const std::string& program) {
  return runFms(program, radiusX()).errors;
}

TEST(Fms3000Turning_5_3, G151SinglePassFacingWithACone_Table20) {
  const V cone{"R 30,0,2",     "L 30,0,0 F100", "L 10,0,0 F100",
               "L 0,0,1 F100", "L 0,0,2 F100",  "R 30,0,2"};
  EXPECT_EQ(run("G18 G90 G0 X30 Z2\nG151 X0 Z0 P1 Q10 F100\nM30\n"), cone);
  // Q is an X-type value: a diameter under N7006 = 1
  EXPECT_EQ(run("G18 G90 G0 X60 Z2\nG151 X0 Z0 P1 Q20 F100\nM30\n", diameterX()), cone);
}

TEST(Fms3000Turning_5_3, G151WithoutAConeRapidFlagAndG91_Table20) {
  EXPECT_EQ(run("G18 G90 G0 X30 Z2\nG91 G151 X-30 Z-2 F100 G0\nM30\n"),
            (V{"R 30,0,2", "R 30,0,0", "L 0,0,0 F100", "L 0,0,2 F100", "R 30,0,2"}));
}

const V kG155{"R 30,0,-10",     "R 22,0,-10",     "L 18,0,-10 F50", "R 22,0,-10",
              "R 19,0,-10",     "L 14,0,-10 F50", "R 22,0,-10",     "R 15,0,-10",
              "L 10,0,-10 F50", "R 22,0,-10",     "R 22,0,5"};

TEST(Fms3000Turning_5_3, G155PeckGroovingAlongX_Table24) {
  EXPECT_EQ(run("G18 G0 X30 Z-10\nG155 U22 X10 V4 W1 F50 Z5\nM30\n"), kG155);
  // every length along X follows N7006
  EXPECT_EQ(run("G18 G0 X60 Z-10\nG155 U44 X20 V8 W2 F50 Z5\nM30\n", diameterX()), kG155);
  // G91: U from И.Т., X from U, Z a shift from И.Т.
  EXPECT_EQ(run("G18 G0 X30 Z-10\nG91 G155 U-8 X-12 V4 W1 F50 Z15\nM30\n"), kG155);
}

TEST(Fms3000Turning_5_3, G156DeepDrillingWithADecreasingStep_Table25) {
  // steps 8, 4, then 2 < Q: 3 to the end
  EXPECT_EQ(run("G18 G0 X0 Z5\nG156 U1 Z-20 V8 W1 P0.5 Q3 F50 X10\nM30\n"),
            (V{"R 0,0,5", "R 0,0,1", "L 0,0,-7 F50", "R 0,0,1", "R 0,0,-6", "L 0,0,-11 F50",
               "R 0,0,1", "R 0,0,-10", "L 0,0,-14 F50", "R 0,0,1", "R 0,0,-13", "L 0,0,-17 F50",
               "R 0,0,1", "R 0,0,-16", "L 0,0,-20 F50", "R 0,0,1", "R 10,0,1"}));
}

TEST(Fms3000Turning_5_3, G157PeckGroovingWithAGrowingStep_Table26) {
  // P > 1: steps 2, 4, 8 without a limit, the last one cut short at X
  EXPECT_EQ(run("G18 G0 X30 Z-10\nG157 U22 X10 V2 W1 P2 Q0.5 F50\nM30\n"),
            (V{"R 30,0,-10", "R 22,0,-10", "L 20,0,-10 F50", "R 22,0,-10", "R 21,0,-10",
               "L 16,0,-10 F50", "R 22,0,-10", "R 17,0,-10", "L 10,0,-10 F50", "R 22,0,-10"}));
}

TEST(Fms3000Turning_5_3, G158CylindricalGrooves_Table27) {
  // grooves every 5 from z0, the last one at Z
  EXPECT_EQ(run("G18 G0 X30 Z0\nG158 X20 Z-12 Q5 F100\nM30\n"),
            (V{"R 30,0,0", "L 20,0,0 F100", "R 30,0,0", "L 30,0,-5 F100", "L 20,0,-5 F100",
               "R 30,0,-5", "L 30,0,-10 F100", "L 20,0,-10 F100", "R 30,0,-10", "L 30,0,-12 F100",
               "L 20,0,-12 F100", "R 30,0,-12"}));
}

TEST(Fms3000Turning_5_3, G159FaceGroovesWithTheRapidFlag_Table28) {
  // X and Q in diameter; the grooves are 5 apart in radius
  EXPECT_EQ(run("G18 G0 X40 Z2\nG159 Z-3 X20 Q10 F100 G0\nM30\n", diameterX()),
            (V{"R 20,0,2", "L 20,0,-3 F100", "R 20,0,2", "R 15,0,2", "L 15,0,-3 F100", "R 15,0,2",
               "R 10,0,2", "L 10,0,-3 F100", "R 10,0,2"}));
}

TEST(Fms3000Turning_5_3, G161ChipBreakingGroovingAlongX_Table30) {
  EXPECT_EQ(run("G18 G0 X30 Z-10\nG161 U22 X10 V4 W1 I26 F50\nM30\n"),
            (V{"R 30,0,-10", "R 22,0,-10", "L 18,0,-10 F50", "R 19,0,-10", "L 14,0,-10 F50",
               "R 15,0,-10", "L 10,0,-10 F50", "R 22,0,-10", "R 26,0,-10"}));
}

TEST(Fms3000Turning_5_3, G163TapOrDie_Table32) {
  const MacroRun r = runFms("G18 G0 X0 Z5\nM3 S500\nG163 Z-20 F1.5 X10\nM30\n");
  ASSERT_EQ(r.errors, V{}) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 0,0,5", "EV S500 M3", "L 0,0,-20 F1.5", "EV S500 M4", "L 0,0,5 F1.5",
                           "EV S500 M3", "R 10,0,5", "END"}));
  int synchronised = 0; // both Z moves follow the spindle at 1.5 mm per revolution
  for (const motion::Event& e : r.events)
    synchronised += e.kind == motion::Kind::Feed && e.lead == 1.5;
  EXPECT_EQ(synchronised, 2);
  // M5: a stop before each reverse; G91: Z from И.Т.; I (sync) moves nothing
  EXPECT_EQ(run("G18 G0 X0 Z5\nM4 S300\nG91 G163 Z-10 F2 M5 I1\nM30\n"),
            (V{"R 0,0,5", "EV S300 M4", "L 0,0,-5 F2", "EV S300 M5", "EV S300 M3", "L 0,0,5 F2",
               "EV S300 M5", "EV S300 M4"}));
  EXPECT_EQ(errorsOf("G18\nG163 Z-20 F1.5\n"), V{"main.fms:2:1 FMSX02"});           // spindle off
  EXPECT_EQ(errorsOf("G18\nM3 S100\nG163 Z-20 F1 M3\n"), V{"main.fms:3:1 FMSX02"}); // M3
}

TEST(Fms3000Turning_5_3_1, G164ChipBreakingThenTheFinishingPass_Table33) {
  // levels at F without the G0 flag; V6 W1 cut each level as G86 steps; without P the
  // finishing pass runs the approach block and the profile, then rapid X and Z back to И.Т.
  EXPECT_EQ(run("G18 G90 G0 X20 Z2\nG164 Q4 V6 W1 F100\nG1 Z-20\nX12 Z-10\nX8 Z0\nendcont\nM30\n"),
            (V{"R 20,0,2", "L 16,0,2 F100", "L 16,0,-4 F100", "R 16,0,-3", "L 16,0,-10 F100",
               "R 16,0,-9", "L 16,0,-15 F100", "R 16,0,2", "L 12,0,2 F100", "L 12,0,-4 F100",
               "R 12,0,-3", "L 12,0,-10 F100", "R 12,0,2", "R 20,0,2", "L 20,0,-20 F100",
               "L 12,0,-10 F100", "L 8,0,0 F100", "R 20,0,0", "R 20,0,2"}));
}

TEST(Fms3000Turning_5_3_1, G165FacingRoughing_Table34) {
  // depth levels along Z 1 apart, cuts along X to the profile, D retracts along Z
  EXPECT_EQ(run("G18 G0 X20 Z2\nG165 Q1 F100 G0 D0.5 P1\nG1 X10\nG1 X5 Z-2\nendcont\nM30\n"),
            (V{"R 20,0,2", "R 20,0,1", "L 8.75,0,1 F100", "R 8.75,0,1.5", "R 20,0,1.5", "R 20,0,0",
               "L 7.5,0,0 F100", "R 7.5,0,0.5", "R 20,0,0.5", "R 20,0,-1", "L 6.25,0,-1 F100",
               "R 6.25,0,-0.5", "R 20,0,-0.5", "R 20,0,2"}));
}

TEST(Fms3000Turning_5_3_1, BadProfilesAreLocatedErrors) {
  const std::string head = "G18 G0 X20 Z2\nG164 Q4 F100\n";
  // the approach block must move Z only (001:3916)
  EXPECT_EQ(errorsOf(head + "G1 X18 Z-20\nX8 Z0\nendcont\nM30\n"), V{"main.fms:3:1 FMSX05"});
  // not monotonic along X (001:3975)
  EXPECT_EQ(errorsOf(head + "G1 Z-20\nX12 Z-10\nX14 Z-5\nendcont\nM30\n"),
            V{"main.fms:5:1 FMSX05"});
  // a word the profile may not hold (001:3903-3909)
  EXPECT_EQ(errorsOf(head + "G1 Z-20\nX12 Z-10 M3\nendcont\nM30\n"), V{"main.fms:4:10 FMSX05"});
  EXPECT_EQ(errorsOf(head + "G1 Z-20\nG0 X12 Z-10\nendcont\nM30\n"), V{"main.fms:4:1 FMSX05"});
  // no endcont before the end of the file
  EXPECT_EQ(errorsOf(head + "G1 Z-20\nX12 Z-10\n"), V{"main.fms:2:1 FMSX05"});
  // V without W (001:3950-3953), and the lathe plane
  EXPECT_EQ(errorsOf("G18 G0 X20 Z2\nG164 Q4 V2 F100\nG1 Z-20\nX8 Z0\nendcont\n"),
            V{"main.fms:2:1 FMSX02"});
  EXPECT_EQ(errorsOf("G0 X20 Z2\nG164 Q4 F100\nG1 Z-20\nX8 Z0\nendcont\n"),
            V{"main.fms:2:1 FMSX02"});
}

TEST(Fms3000Turning_5_3, BadParametersOfTheNewCyclesAreLocatedErrors) {
  EXPECT_EQ(errorsOf("G18\nG151 X0 Z0 P1 F100\n"), V{"main.fms:2:1 FMSX02"});  // P without Q
  EXPECT_EQ(errorsOf("G18\nG155 U22 X10 V4 F50\n"), V{"main.fms:2:1 FMSX02"}); // no W
  EXPECT_EQ(errorsOf("G18\nG156 U1 Z-20 V8 W1 P0.5 F50\n"), V{"main.fms:2:1 FMSX02"}); // no Q
  EXPECT_EQ(errorsOf("G18\nG156 U1 Z-20 V8 W1 P0.5 Q0 F50\n"),
            V{"main.fms:2:1 FMSX02"}); // a shrinking step without a minimum
  EXPECT_EQ(errorsOf("G18\nG157 U22 X10 V2 W1 P0 Q1 F50\n"), V{"main.fms:2:1 FMSX02"}); // P 0
  EXPECT_EQ(errorsOf("G18\nG158 X20 Z-12 F100\n"), V{"main.fms:2:1 FMSX02"});           // no Q
  EXPECT_EQ(errorsOf("G18\nG159 Z-3 X20 Q0 F100\n"), V{"main.fms:2:1 FMSX02"});         // pitch 0
  EXPECT_EQ(errorsOf("G18\nG161 U22 X10 V4 W1 R1 F50\n"), V{"main.fms:2:1 FMSX02"});    // R
}

} // namespace
} // namespace gcx::test
