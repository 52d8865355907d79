// NCT drilling cycles beyond the §8 vectors: the other planes (§2.2), the block rules of §2.3-
// §2.5, rigid-tap variants (§3.2, §3.9), transformations (§2.7), the machine parameters (§2.8),
// and every error and warning of §7 with its location.
#include <gtest/gtest.h>

#include "cycles/cycle_harness.h"
#include "cycles/drilling.h"
#include "diag/codes.h"
#include "dialects/nct/profile.h"
#include "machine/settings.h"
#include "machine/setup.h"

namespace gcx::test {
namespace {

using cycles::DrillCycle;
using cycles::OpKind;

// One G81-style request at X0 Y0 Z10 with r = 2, z = -7, F80.
cycles::DrillRequest request(DrillCycle c) {
  cycles::DrillRequest req;
  req.cycle = c;
  req.position = cycles::Vec3(0, 0, 10);
  req.hole = cycles::Vec3(0, 0, 0);
  req.initial = 10;
  req.vars.r = val(2);
  req.vars.z = val(-7);
  req.feed = 80;
  req.spindleSpeed = 1000;
  return req;
}

std::string expand(const cycles::DrillRequest& req, const cycles::DrillConfig& cfg = {}) {
  diag::Engine diags;
  const auto res = cycles::expandHole(req, {}, cfg, diags);
  EXPECT_TRUE(res) << (diags.all().empty() ? "" : diags.all()[0].message);
  return res ? cycles::opsText(req.position, res->ops) : "";
}

// --- §2.2 planes ------------------------------------------------------------------------

TEST(CyclesSpec_2_2, G18DrillsAlongY) {
  const auto h = run("N1 G18 G90 G0 X0 Y20 Z0\n"
                     "N2 G81 Z10 X5 Y-5 R2 F100\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X5 Z10 | G0 Y2 | G1 Y-5 F100 | G0 Y20");
}

TEST(CyclesSpec_2_2, G19DrillsAlongXUnderG99) {
  const auto h = run("N1 G19 G90 G0 X30 Y0 Z0\n"
                     "N2 G99 G82 Y5 Z6 X-4 R1 P0.5 F60\n");
  EXPECT_EQ(h.out.at("N2"), "G0 Y5 Z6 | G0 X1 | G1 X-4 F60 | G4 P0.5 | G0 X1");
}

TEST(CyclesSpec_2_2, G18ShiftIsKOnZAndIOnX) { // 000:9550-9552
  const auto h = run("N1 G18 G90 G0 X0 Y50 Z0 S800 M3\n"
                     "N2 G76 Z10 X5 Y-5 R2 K0.5 I-0.2 F100\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X5 Z10 | G0 Y2 | G1 Y-5 F100 | M19 | G0 X4.8 Z10.5 | G0 Y50 | "
                            "G0 X5 Z10 | M3");
}

// --- §2.3-§2.5 levels and block rules -------------------------------------------------------

TEST(CyclesSpec_2_3, G98IsRestoredWhenCycleModeEnds) {
  const auto h = run("N1 G17 G90 G0 X0 Y0 Z30\n"
                     "N2 G99 G81 X10 Z-5 R2 F100\n"
                     "N3 G80\n"
                     "N4 G81 X20 Z-5 R1\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X10 | G0 Z2 | G1 Z-5 F100 | G0 Z2");
  EXPECT_EQ(h.out.at("N4"), "G0 X20 | G0 Z1 | G1 Z-5 F100 | G0 Z2"); // ini 2: where N4 starts
}

TEST(CyclesSpec_2_3, BottomAboveRDrillsUpward) {
  // s = sign(z - r) = +1: the pecks L_k = r + s*min(kQ, D) climb from R-10 to Z10 (D 20, Q 8,
  // n = 3), each G73 retract d = 0.5 (N1500) goes back down; G98 returns to ini -20
  const auto h = run("N1 G17 G90 G0 X0 Y0 Z-20\n"
                     "N2 G73 X5 Y0 Z10 R-10 Q8 F100\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X5 | G0 Z-10 | G1 Z-2 F100 | G0 Z-2.5 | G1 Z6 F100 | G0 Z5.5 | "
                            "G1 Z10 F100 | G0 Z-20");
}

TEST(CyclesSpec_3_2, DepthThatIsAMultipleOfQNeedsNoExtraPeck) {
  // G18 drills along Y: D = 12, Q = 4, n = ceil(12/4) = 3 pecks to -2, -6, -10; G83 goes back
  // to R after each but the last and returns to c = 1 (N1501) above the previous level
  const auto h = run("N1 G18 G90 G0 X0 Y20 Z0\n"
                     "N2 G83 Z5 X5 Y-10 R2 Q4 F100\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X5 Z5 | G0 Y2 | G1 Y-2 F100 | G0 Y2 | G0 Y-1 | G1 Y-6 F100 | "
                            "G0 Y2 | G0 Y-5 | G1 Y-10 F100 | G0 Y20");
}

TEST(CyclesSpec_2_3, IncrementalZFollowsTheStoredR) { // Z kept as programmed, resolved per hole
  const auto h = run("N1 G17 G90 G0 X0 Y0 Z30\n"
                     "N2 G99 G81 X10 ZI-5 R2 F100\n"
                     "N3 X20 R4\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X10 | G0 Z2 | G1 Z-3 F100 | G0 Z2");
  EXPECT_EQ(h.out.at("N3"), "G0 X20 | G0 Z4 | G1 Z-1 F100 | G0 Z4");
}

TEST(CyclesSpec_2_5, ROnlyIsStoredQAndPOnlyInDrillingBlocks) { // Q-4, 000:10338-10358
  const auto h = run("N1 G17 G90 G0 X0 Y0 Z30\n"
                     "N2 G82 X10 Z-5 R2 P1 F100\n"
                     "N3 R3\n"
                     "N4 P4\n"
                     "N5 X20\n");
  EXPECT_EQ(h.out.count("N3"), 0u);
  EXPECT_EQ(h.out.count("N4"), 0u);
  EXPECT_EQ(h.out.at("N5"), "G0 X20 | G0 Z3 | G1 Z-5 F100 | G4 P1 | G0 Z30");
}

// A G10 record in cycle mode writes its register; its R is not the cycle's R (§2.5).
TEST(CyclesSpec_2_5, WordsOfG10AreNotCycleData) {
  const auto h = run("G17 G90 G0 Z20\n"
                     "G81 X5 Z-5 R2 F100\n"
                     "G10 L10 P1 R50\n"
                     "X10\n");
  EXPECT_EQ(h.out.at("#4"), "G0 X10 | G0 Z2 | G1 Z-5 F100 | G0 Z20");
}

TEST(CyclesSpec_2_5, DrillingAxisWordAloneDrillsInPlace) {
  const auto h = run("N1 G17 G90 G0 X0 Y0 Z30\n"
                     "N2 G99 G81 X10 Z-5 R2 F100\n"
                     "N3 Z-8\n");
  EXPECT_EQ(h.out.at("N3"), "G1 Z-8 F100 | G0 Z2");
}

TEST(CyclesSpec_2_6, BlockFunctionsRunAfterOp1OfTheFirstRepetitionOnly) {
  const auto h = run("N1 G17 G90 G0 X0 Y0 Z30\n"
                     "N2 G91 G81 X10 Z-5 R-28 F100 L2 M8\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X10 | M8 | G0 Z2 | G1 Z-3 F100 | G0 Z30 | "
                            "G0 X20 | G0 Z2 | G1 Z-3 F100 | G0 Z30");
}

TEST(CyclesSpec_2_9, OpsCarryTheManualsStepNumbers) {
  cycles::DrillRequest req = request(DrillCycle::FineBoring);
  req.hole = cycles::Vec3(5, 0, 0);
  req.vars.i = val(0.5);
  req.vars.p = val(1);
  diag::Engine diags;
  const auto res = cycles::expandHole(req, {}, {}, diags);
  ASSERT_TRUE(res);
  std::vector<int> steps;
  for (const cycles::DrillOp& o : res->ops)
    steps.push_back(o.step);
  EXPECT_EQ(steps, (std::vector<int>{1, 3, 5, 6, 6, 6, 9, 10, 10}));
  EXPECT_EQ(res->auxAt, 1u);
  EXPECT_EQ(res->end, cycles::Vec3(5, 0, 10));
  EXPECT_EQ(res->r, 2);
  EXPECT_EQ(res->z, -7);
}

// --- §3 op variants ------------------------------------------------------------------------

TEST(CyclesSpec_3_1, G87VariantBIgnoresG99) { // 000:10236-10244
  cycles::DrillRequest req = request(DrillCycle::BackBore);
  req.ret = cycles::DrillReturn::RLevel;
  req.vars.r = val(-9);
  req.vars.z = val(-2);
  req.vars.j = val(0.4);
  EXPECT_EQ(expand(req), "M19 | G0 Y0.4 | G0 Z-9 | G0 Y0 | M3 | G1 Z-2 F80 | M19 | G0 Y0.4 | "
                         "G0 Z10 | G0 Y0 | M3");
}

TEST(CyclesSpec_3_9, G84_3TurnsCCWIntoTheHoleAndOrientsWithTSC) {
  cycles::DrillConfig cfg;
  cfg.tapOrient = true;
  EXPECT_EQ(expand(request(DrillCycle::RigidTapLeft), cfg),
            "G0 Z2 | M19 | RTAP Z-7 F80 S1000 DIR=CCW | RTAP Z2 F80 S1000 DIR=CW | G0 Z10");
}

TEST(CyclesSpec_3_9, RetractOverrideOnlyWithEOE) { // 000:10012-10020, Q-24
  cycles::DrillRequest req = request(DrillCycle::RigidTapRight);
  req.vars.overridePercent = val(150); // I as written; updateModal stores it with the shift I
  req.vars.p = val(0.3);
  EXPECT_EQ(expand(req), "G0 Z2 | M24 | RTAP Z-7 F80 S1000 DIR=CW | G4 P0.3 | "
                         "RTAP Z2 F80 S1000 DIR=CCW | G0 Z10");
  cycles::DrillConfig eoe;
  eoe.extractionEnabled = true;
  EXPECT_EQ(expand(req, eoe), "G0 Z2 | M24 | RTAP Z-7 F80 S1000 DIR=CW | G4 P0.3 | "
                              "RTAP Z2 F80 S1000 DIR=CCW OVR=150% | G0 Z10");
  req.vars.overridePercent.reset();
  eoe.tapExtraction = 120; // N1506
  EXPECT_EQ(expand(req, eoe), "G0 Z2 | M24 | RTAP Z-7 F80 S1000 DIR=CW | G4 P0.3 | "
                              "RTAP Z2 F80 S1000 DIR=CCW OVR=120% | G0 Z10");
}

TEST(CyclesSpec_3_2, RigidTapNormalPecksReturnToR) { // PTC=1, c = N1505, ROE -> N1507
  cycles::DrillRequest req = request(DrillCycle::RigidTapRight);
  req.position = cycles::Vec3(0, 0, 20);
  req.initial = 20;
  req.vars.r = val(3);
  req.vars.z = val(-10);
  req.vars.q = val(5);
  cycles::DrillConfig cfg;
  cfg.tapNormalPeck = true;
  cfg.returnEnabled = true;
  cfg.tapReturnOverride = 80;
  EXPECT_EQ(expand(req, cfg), "G0 Z3 | M24 | RTAP Z-2 F80 S1000 DIR=CW | "
                              "RTAP Z3 F80 S1000 DIR=CCW OVR=80% | RTAP Z-1 F80 S1000 DIR=CW | "
                              "RTAP Z-7 F80 S1000 DIR=CW | RTAP Z3 F80 S1000 DIR=CCW OVR=80% | "
                              "RTAP Z-6 F80 S1000 DIR=CW | RTAP Z-10 F80 S1000 DIR=CW | "
                              "RTAP Z3 F80 S1000 DIR=CCW | G0 Z20");
}

TEST(CyclesSpec_3_2, RigidTapQ0DoesNotPeck) { // G80 leaves Q = 0 (000:9793)
  cycles::DrillRequest req = request(DrillCycle::RigidTapRight);
  req.vars.q = val(0);
  EXPECT_EQ(expand(req),
            "G0 Z2 | M24 | RTAP Z-7 F80 S1000 DIR=CW | RTAP Z2 F80 S1000 DIR=CCW | G0 Z10");
}

TEST(CyclesSpec_3_2, LastPeckClippedAndNotAccumulated) {
  cycles::DrillRequest req = request(DrillCycle::HighSpeedPeck);
  req.vars.z = val(-0.7); // D = 2.7 = 3 * 0.9: exactly three pecks despite rounding
  req.vars.q = val(0.9);
  req.vars.e = val(0.1);
  EXPECT_EQ(expand(req), "G0 Z2 | G1 Z1.1 F80 | G0 Z1.2 | G1 Z0.2 F80 | G0 Z0.3 | "
                         "G1 Z-0.7 F80 | G0 Z10");
}

// --- §2.7 transformations -----------------------------------------------------------------

TEST(CyclesSpec_2_7, PecksKeepTheirSizeUnderScaling) {
  cycles::DrillRequest req = request(DrillCycle::HighSpeedPeck);
  req.vars.z = val(-1);
  req.vars.q = val(3);
  req.vars.e = val(0.4);
  req.drillScale = 2; // program-space peck 1.5, retract 0.2
  EXPECT_EQ(expand(req), "G0 Z2 | G1 Z0.5 F80 | G0 Z0.7 | G1 Z-1 F80 | G0 Z10");
}

TEST(CyclesSpec_2_7, ShiftGoesThroughTheInverseInPlaneTransform) {
  cycles::DrillRequest req = request(DrillCycle::FineBoring);
  req.vars.i = val(1);
  req.shiftMap << 0, 1, -1, 0; // inverse of a +90° rotation
  EXPECT_EQ(expand(req), "G0 Z2 | G1 Z-7 F80 | M19 | G0 Y-1 | G0 Z10 | G0 Y0 | M3");
}

// --- §7 errors and warnings -----------------------------------------------------------------

TEST(CyclesSpec_7, NegativeQIsReportedAtTheQWord) {
  EXPECT_EQ(failing("G17 G90 G0 Z10\nG83 X1 Z-5 R2 Q-2 F100\n"), "#2 CYC-Q-NEGATIVE 2:15");
}

TEST(CyclesSpec_7, NegativeEIsReportedAtTheEWord) {
  EXPECT_EQ(failing("G17 G90 G0 Z10\nG73 X1 Z-5 R2 Q2 E-1 F100\n"), "#2 CYC-Q-NEGATIVE 2:18");
}

TEST(CyclesSpec_7, Q0IsMissingForPeckCycles) {
  EXPECT_EQ(failing("G17 G90 G0 Z10\nG73 X1 Z-5 R2 Q0 F100\n"), "#2 CYC-Q-MISSING 2:15");
}

TEST(CyclesSpec_7, ZeroFeedIsMissingData) {
  EXPECT_EQ(failing("G17 G90 G0 Z10\nG81 X1 Z-5 R2\n"), "#2 2004 2:1");
}

// Not in §7: an R point beyond the bottom makes the rapid to R cut through the hole.
TEST(CyclesSpec_7, RBeyondTheBottomIsRefusedAtTheRWord) {
  EXPECT_EQ(failing("G17 G90 G0 Z10\nG81 X1 Z-5 R-8 F100\n"), "#2 CYC-R-BEYOND-BOTTOM 2:12");
  EXPECT_EQ(failing("G17 G91 G0 Z10\nG81 X1 Z3 R-8 F100\n"), "#2 CYC-R-BEYOND-BOTTOM 2:11");
}

TEST(CyclesSpec_7, BackBoringNeedsRBeyondTheBottom) { // 000:10246-10248
  EXPECT_EQ(failing("G17 G90 G0 Z50 S700 M3\nG87 X10 Z-5 R2 I-0.5 F40\n"),
            "#2 CYC-R-BEYOND-BOTTOM 2:13");
}

TEST(CyclesSpec_7, RetractOverrideMustBePositive) {
  EXPECT_EQ(failing("G17 G90 G0 Z10\nG85 X1 Z-5 R2 I0 F100\n"), "#2 2002 2:15");
}

TEST(CyclesSpec_7, RepetitionCountRange) {
  for (double l : {-1.0, 2.5, 100000000.0}) {
    diag::Engine diags;
    cycles::DrillModal modal;
    cycles::DrillWords w;
    w.code = DrillCycle::Drill;
    w.holeWord = true;
    w.vars.z = val(-1);
    w.vars.r = val(1);
    w.l = val(l);
    EXPECT_FALSE(cycles::updateModal(modal, w, diags)) << l;
    ASSERT_EQ(diags.all().size(), 1u);
    EXPECT_EQ(diags.all()[0].code, diag::code::CycleLRange);
  }
}

TEST(CyclesSpec_7, NoErrorOutsideCycleMode) { // Q and L mean other things there
  diag::Engine diags;
  cycles::DrillModal modal;
  cycles::DrillWords w;
  w.holeWord = true;
  w.vars.q = val(-1);
  w.l = val(-3);
  EXPECT_EQ(cycles::updateModal(modal, w, diags), 0);
  EXPECT_FALSE(diags.hasErrors());
}

TEST(CyclesSpec_7, ExpandHoleChecksZAndRItself) {
  cycles::DrillRequest req = request(DrillCycle::Drill);
  req.vars.r.reset();
  diag::Engine diags;
  EXPECT_FALSE(cycles::expandHole(req, {}, {}, diags));
  EXPECT_EQ(diags.all().at(0).code, diag::code::CycleNoData);
}

TEST(CyclesSpec_3_1, WrongSpindleDirectionWarns) {
  const auto h = run("G17 G90 G0 Z30 S500 M4\n"
                     "G84 X1 Z-5 R2 F625\n"
                     "X2\n");
  // hole 1 leaves M3: the second hole is fine
  EXPECT_EQ(h.warnings, std::vector<std::string>{"2:1 CYC-SPINDLE-DIR"});
  EXPECT_EQ(h.out.at("#2"), "G0 X1 | G0 Z2 | G63 | G1 Z-5 F625 | M4 | G1 Z2 F625 | M3 | G64 | "
                            "G0 Z30");
}

TEST(CyclesSpec_9_Q20, RadiusCompensationWarns) {
  cycles::DrillRequest req = request(DrillCycle::Drill);
  req.radiusCompensation = true;
  diag::Engine diags;
  ASSERT_TRUE(cycles::expandHole(req, {}, {}, diags));
  ASSERT_EQ(diags.warningCount(), 1u);
  EXPECT_EQ(diags.all()[0].code, diag::code::CycleRadiusComp);
}

// --- §2.1 codes, §2.8 parameters ------------------------------------------------------------

TEST(CyclesSpec_2_1, NctBindsItsCodesToTheCycles) {
  // the NCT profile names the cycle each code runs (GCodeSpec::arg)
  auto cycleOf = [](double code) {
    const GCodeSpec* g = nct::profile().gcode(code);
    EXPECT_TRUE(g && g->action == GAction::DrillCycle) << code;
    return g ? static_cast<DrillCycle>(g->arg) : DrillCycle::BoreDwellFeedOut;
  };
  EXPECT_EQ(cycleOf(84.2), DrillCycle::RigidTapRight);
  EXPECT_EQ(cycleOf(73), DrillCycle::HighSpeedPeck);
  EXPECT_EQ(cycleOf(81), DrillCycle::Drill);
  EXPECT_EQ(cycleOf(89), DrillCycle::BoreDwellFeedOut);
  EXPECT_EQ(nct::profile().gcode(80)->action, GAction::CycleCancel);
}

TEST(CyclesSpec_2_8, ParametersFromTheSetup) {
  machine::Setup s;
  s.parameters = {
      {"N1500", 0.7}, {"N0607.1", 0}, {"N1503.PTC", 1}, {"N0823", 29}, {"N0607.INX", 0}};
  const cycles::DrillConfig c = machine::drillConfig(nct::profile(), s);
  EXPECT_EQ(c.returnG73, 0.7);
  EXPECT_EQ(c.clearanceG83, 1.0); // not set: the spec's test value
  EXPECT_FALSE(c.orient);
  EXPECT_FALSE(c.indexable);
  EXPECT_TRUE(c.tapNormalPeck);
  EXPECT_FALSE(c.tapOrient);
  EXPECT_EQ(c.closeLoopMCode, 29);
  EXPECT_STREQ(c.orientLabel, "N0607 ORI"); // messages name the setting as NCT does
  EXPECT_STREQ(c.indexLabel, "N0607 INX");
}

} // namespace
} // namespace gcx::test
