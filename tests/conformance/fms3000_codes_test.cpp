// The one-block codes of fms3000.md §3.8, §3.15 and §3.17 that move or change nothing the
// way their Fanuc namesakes do: G27 homing, G32 skip, G34 sync, LIMS under G96, G45; and the
// program rules of §1.1 / §2.2: the end of the file without M02/M30. One test per rule, the
// exact motion in machine coordinates or the located error.
#include <gtest/gtest.h>

#include "support/fms3000_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

MacroRun runBlocks(const std::string& spec, const machine::Setup& setup = {}) {
  return runFms(specBlocks(spec), setup);
}

V motionOf(const MacroRun& r) {
  EXPECT_EQ(r.errors, V{}) << r.rendered;
  V m = r.motion();
  if (!m.empty() && m.back() == "END") m.pop_back();
  return m;
}

// G55 of the manual's example E22, and fixed point 1 of §8's S0 (where G30 would go)
machine::Setup g55() {
  machine::Setup s;
  s.workOffsets["G55"] = {500, 200, 100};
  s.parameters = {{"N7001", 10}, {"N7101", 20}, {"N7201", 300}};
  return s;
}

// The manual leaves M codes other than its own to the machine (001:3720-3721); the machines
// follow the ГОСТ 20999-83 table (book-reference.md §2.2): M08 coolant on before the block's
// motion, M09 off after it, M06 changes to the tool T selected. T alone only selects (§3.15).
TEST(Fms3000Spec_3_15, GostCoolantAndToolChangeCodes) {
  EXPECT_EQ(motionOf(runBlocks("N1 T7 · N2 X10 M08 · N3 X20 M09 · N4 M06 · M30")),
            (V{"EV M8", "R 10,0,0", "R 20,0,0", "EV M9", "EV T7 M6"}));
}

// 001:1549-1558: "NG27X0Y0Z20B0" homes the named axes; the values are ignored, offsets too
TEST(Fms3000Spec_3_8, G27HomesTheListedAxesToMachineZero) {
  const MacroRun r = runBlocks("G90G55G0X10Y10Z10 · G27X5Z20 · G0X1 · M30", g55());
  EXPECT_EQ(motionOf(r), (V{"R 510,210,110", "R 0,210,0", "R 501,210,0"}));
  EXPECT_EQ(r.warnings, V{});
}

TEST(Fms3000Spec_3_8, G27WithoutAxesOrWithACentreWordIsALocatedError) {
  EXPECT_EQ(runBlocks("G0X10 · G27 · M30").errors, V{"main.fms:2:1 FMSX06"});
  EXPECT_EQ(runBlocks("G0X10 · G27X0J1 · M30").errors, V{"main.fms:2:6 FMSX06"});
  // G27 is one of the codes that exclude each other (001:3849-3870)
  EXPECT_EQ(runBlocks("G27X0G28Y0 · M30").errors, V{"main.fms:1:6 GCX012"});
}

// 001:1594-1611: no touch signal in a model without a probe: the whole move, and a warning
TEST(Fms3000Spec_3_17, G32RunsTheWholeMoveWithoutATouchSignal) {
  const MacroRun r = runBlocks("G1X10F100 · G32G1X50Y20 · X60 · M30");
  EXPECT_EQ(motionOf(r), (V{"L 10,0,0 F100", "L 50,20,0 F100", "L 60,20,0 F100"}));
  EXPECT_EQ(r.warnings, V{"main.fms:2:1 GCXW06"});
}

// 001:3801: "G32 при введенной коррекции на радиус"
TEST(Fms3000Spec_3_17, G32UnderRadiusCompensationIsALocatedError) {
  machine::Setup s;
  s.tools[1].radius = 5;
  EXPECT_EQ(runBlocks("G0X-10Y-10 · G1G41D1X0Y0F100 · Y20G32 · G40X-10Y-10 · M30", s).errors,
            V{"main.fms:3:4 GCX039"});
}

// 001:1586-1592: G34 only times the start of the block's contour on the encoder's zero mark
TEST(Fms3000Spec_3_17, G34ChangesNoPath) {
  const MacroRun r = runBlocks("G34G1X10Y5F100 · G34G0X0 · M30");
  EXPECT_EQ(motionOf(r), (V{"L 10,5,0 F100", "R 0,5,0"}));
  EXPECT_EQ(r.warnings, V{});
}

// E19 (001:1527-1530): "N100G91G1Z-10G33F1.6" threads 10 mm along -Z at 1.6 mm per revolution;
// G33 acts for its block only, the next block is an ordinary G1 again
TEST(Fms3000Spec_3_17, G33ThreadsOneG1BlockAtTheLeadF) {
  const MacroRun r = runBlocks("M3S200 · G1X5F100 · N100G91G1Z-10G33F1.6 · Z-5 · M30");
  EXPECT_EQ(motionOf(r), (V{"EV S200 M3", "L 5,0,0 F100", "L 5,0,-10 F1.6", "L 5,0,-15 F1.6"}));
  std::vector<double> leads;
  for (const motion::Event& e : r.events)
    if (e.kind == motion::Kind::Feed) leads.push_back(e.lead);
  EXPECT_EQ(leads, (std::vector<double>{0, 1.6, 0}));
}

// 001:3855: "Ошибка программирования G33" under G0; with an arc gcx has no synchronised arc
TEST(Fms3000Spec_3_17, G33UnderG0IsALocatedError) {
  EXPECT_EQ(runBlocks("G0X10 · G33Z-5F1.5 · M30").errors, V{"main.fms:2:1 GCX048"});
  EXPECT_EQ(runBlocks("G0G33Z-5F1.5 · M30").errors, V{"main.fms:1:3 GCX048"});
  EXPECT_EQ(runBlocks("G1X10F100 · G2G33X20I5F1.5 · M30").errors, V{"main.fms:2:3 GCX030"});
}

machine::Setup diameterX() {
  machine::Setup s;
  s.parameters["N7006"] = 1;
  return s;
}

// E39 (001:3569-3621), the program "with diameter programming": X50 is a radius of 25 mm, so
// S150 m/min turns 150 / (0.025 · 2π) = 954.93 rpm, and X25 doubles it. (The G96 block first
// repeats the spindle's state, S100, before the motion: a spindle event, not a change.)
TEST(Fms3000Spec_3_15, E39ConstantSurfaceSpeedOnTheDiameter) {
  EXPECT_EQ(motionOf(runBlocks("N1M3S100 · N2X50 · N3G96S150 · N4X25 · N5G97 · M30", diameterX())),
            (V{"EV S100 M3", "R 25,0,0", "EV S100 M3", "EV S954.9297 M3", "R 12.5,0,0",
               "EV S1909.8593 M3"}));
}

// E39's last program: G96 without S holds the surface speed the spindle has, 100 rpm at 25 mm
// = 100 · 0.05 · π = 15.7 m/min, so X25 turns 200 rpm (001:3608-3621)
TEST(Fms3000Spec_3_15, E39G96WithoutSHoldsTheCurrentSurfaceSpeed) {
  EXPECT_EQ(motionOf(runBlocks("N1M3S100 · N2X50 · N3G96 · N4X25 · N5G97 · M30", diameterX())),
            (V{"EV S100 M3", "R 25,0,0", "R 12.5,0,0", "EV S200 M3"}));
}

// LIMS1100 stops the rise of the rpm (at d = 150 / (1100 π) = 43 mm): at X25 the spindle
// turns 1100 rpm, not 1909.86; the ceiling holds until another LIMS (001:3597-3607)
TEST(Fms3000Spec_3_15, LimsCapsTheRpmOfTheConstantSurfaceSpeed) {
  EXPECT_EQ(motionOf(runBlocks("N1M3S100 · N2X50 · N3 G96 S150 LIMS1100 · N4X25 · N5X20 · "
                               "N6X10LIMS3000 · N7G97 · M30",
                               diameterX())),
            (V{"EV S100 M3", "R 25,0,0", "EV S100 M3", "EV S954.9297 M3", "R 12.5,0,0",
               "EV S1100 M3", "R 10,0,0", "R 5,0,0", "EV S3000 M3"}));
}

// §10 Q25: dependent axes are not modelled; G45 warns and the axes move as programmed
TEST(Fms3000Spec_2_1, G45WarnsThatDependentAxesAreNotModelled) {
  const MacroRun r = runBlocks("G45 · G1X10Y5F100 · G46 · M30");
  EXPECT_EQ(motionOf(r), (V{"L 10,5,0 F100"}));
  EXPECT_EQ(r.warnings, V{"main.fms:1:1 GCXW12"});
}

// 001:3880: "Программа без M2, M30": the end of the file reached without a program end
TEST(Fms3000Spec_1_1, TheEndOfTheFileWithoutM02OrM30IsALocatedError) {
  EXPECT_EQ(runBlocks("G1X10F100 · X20").errors, V{"main.fms:2:1 GCX038"});
  EXPECT_EQ(runBlocks("G1X10F100 · M2").errors, V{});
  EXPECT_EQ(runBlocks("G1X10F100 · M98").errors, V{});
  EXPECT_EQ(runBlocks("G1X10F100 · M99").errors, V{}); // standalone M99 acts as M02 (§2.2)
  // a called program ends with M99; the caller's file still needs its end
  const MacroRun r =
      runFms({{"main.fms", "P19\r\nG1X1F100\r\n"}, {"19.fms", "G1Y1F100\r\nM99\r\n"}});
  EXPECT_EQ(r.errors, V{"main.fms:2:1 GCX038"});
}

// 001:3717, 001:3897: M00 M01 M02 M30 M98 M99 exclude each other; 001:3768: no P with M99;
// 001:3815: one call per block
TEST(Fms3000Spec_2_2, EndCodesExcludeEachOtherAndM99TakesNoCall) {
  EXPECT_EQ(runBlocks("G1X10F100 · M1M2").errors, V{"main.fms:2:3 FMSX07"});
  EXPECT_EQ(runBlocks("G1X10F100 · M30 M98").errors, V{"main.fms:2:5 FMSX07"});
  EXPECT_EQ(runBlocks("M99P7").errors, V{"main.fms:1:4 FMSX07"});
  EXPECT_EQ(runBlocks("X1P7G81U1Z-1 · M30").errors, V{"main.fms:1:5 FMSX07"});
  // M03 with an end code is no conflict; nor is a cycle's P parameter
  EXPECT_EQ(runBlocks("G1X10F100M3S100 · M5M30").errors, V{});
}

} // namespace
} // namespace gcx::test
