// The machine model follows the profile's machine rules (docs/machine-model.md): NCT's rules
// give NCT's behaviour, and another dialect's rules change the behaviour with no change to the
// core. The other rules here are FMS-3000's and WL4's as their specs state them (fms3000.md
// §1.4, §3; wl4.md §1.9, §3), on NCT syntax, since those front ends do not exist yet.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <sstream>

#include "dialects/nct/profile.h"
#include "dialects/nct/reader.h"
#include "machine/interpreter.h"
#include "machine/settings.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

class Collect : public motion::Sink {
public:
  std::vector<std::string> out;
  void event(const motion::Event& e) override {
    if (e.kind != motion::Kind::PlaneChange && e.kind != motion::Kind::UnitsChange &&
        e.kind != motion::Kind::FeedModeChange)
      out.push_back(describe(e));
  }
};

/// The motion of `text` (NCT syntax) under `profile`; errors as "line:col CODE".
std::vector<std::string> run(const Profile& profile, const std::string& text,
                             const machine::Setup& setup = {}) {
  SourceManager sm;
  diag::Engine diags(100);
  const FileId f = sm.addBuffer("test.nct", text);
  std::istringstream in(text);
  nct::Reader reader(in, f, diags);
  Collect sink;
  machine::Interpreter interp(profile, setup, sink, diags);
  ir::Block b;
  while (reader.next(b))
    if (!interp.execute(b, motion::Provenance{b.range.begin, {}})) break;
  if (!diags.hasErrors()) interp.finish();
  for (const diag::Diagnostic& d : diags.all())
    if (d.severity == diag::Severity::Error)
      sink.out.push_back(fmt::format("{}:{} {}", d.range.begin.line, d.range.begin.col, d.code));
  return sink.out;
}

using Lines = std::vector<std::string>;

Profile nctWith(void (*change)(MachineRules&)) {
  Profile p = nct::profile();
  change(p.machine);
  p.index();
  return p;
}

TEST(MachineRules, NctSettingsAreReadUnderNctParameterKeys) {
  const Profile& nct = nct::profile();
  machine::Setup s;
  EXPECT_EQ(machine::setting(nct, s, Setting::ArcRadiusTolerance), 0.01); // NCT's fallback
  EXPECT_EQ(machine::setting(nct, s, Setting::RolloverAmount), 360);
  EXPECT_EQ(machine::setting(nct, s, Setting::SpindleOrientable), 1);
  s.parameters = {{"N1339", 0.5}, {"N0607.1", 0}, {"N0108", 180}};
  EXPECT_EQ(machine::setting(nct, s, Setting::ArcRadiusTolerance), 0.5);
  EXPECT_EQ(machine::setting(nct, s, Setting::SpindleOrientable), 0); // the bit by number
  EXPECT_EQ(machine::setting(nct, s, Setting::RolloverAmount), 180);
  s.parameters["N0607.ORI"] = 1; // the bit by name wins over the bit by number
  EXPECT_EQ(machine::setting(nct, s, Setting::SpindleOrientable), 1);
  EXPECT_STREQ(machine::settingLabel(nct, Setting::ArcRadiusTolerance), "N1339 Radius Diff");
  // a setting the dialect does not have: the caller's value
  EXPECT_EQ(machine::setting(nct, s, Setting::ArcCentreAbsolute, 7), 7);
  Profile none = nct::profile();
  none.machine.settings.clear();
  EXPECT_EQ(machine::setting(none, s, Setting::ArcRadiusTolerance, 7), 7);
  EXPECT_STREQ(machine::settingLabel(none, Setting::ArcRadiusTolerance), "");
}

TEST(MachineRules, SettingKeyDecidesWhichSetupEntryCounts) {
  // another dialect's key for the same meaning: the NCT key no longer counts
  const Profile other = nctWith([](MachineRules& r) {
    for (SettingSpec& s : r.settings)
      if (s.setting == Setting::ArcRadiusTolerance) s.key = "P0042";
  });
  machine::Setup s;
  s.parameters = {{"N1339", 0.5}};
  const std::string spiral = "G17 G90 G0 X10 Y0\nG3 X0 Y10.3 I-10 F100\n";
  EXPECT_EQ(run(nct::profile(), spiral, s),
            (Lines{"R 10,0,0", "CCW 0,10.3,0 C0,0 r10->10.3 θ90", "END"}));
  EXPECT_EQ(run(other, spiral, s), (Lines{"R 10,0,0", "2:1 2012"}));
}

TEST(MachineRules, Nct_1_6_BlockSkipLeavesTheBlockOutWhenTheSwitchIsOn) {
  machine::Setup on;
  on.blockSkip = {1};
  const std::string text = "/1 G0 X10\nG0 X20\n";
  EXPECT_EQ(run(nct::profile(), text), (Lines{"R 10,0,0", "R 20,0,0", "END"}));
  EXPECT_EQ(run(nct::profile(), text, on), (Lines{"R 20,0,0", "END"}));
}

TEST(MachineRules, Wl4_BlockSkipRunsTheBlockOnlyWhenTheFlagIsOn) {
  const Profile wl4 = nctWith([](MachineRules& r) { r.skipSense = SkipSense::RunWhenOn; });
  machine::Setup on;
  on.blockSkip = {1};
  const std::string text = "/1 G0 X10\nG0 X20\n";
  EXPECT_EQ(run(wl4, text), (Lines{"R 20,0,0", "END"}));
  EXPECT_EQ(run(wl4, text, on), (Lines{"R 10,0,0", "R 20,0,0", "END"}));
}

TEST(MachineRules, DwellWordAndUnitComeFromTheProfile) {
  EXPECT_EQ(run(nct::profile(), "G4 P2.5\n"), (Lines{"DW 2.5s", "END"}));
  EXPECT_EQ(run(nct::profile(), "G4 X2\n"), (Lines{"1:4 GCX035"}));
  // FMS-3000: G04 E in tenths of a second
  const Profile fms = nctWith([](MachineRules& r) { r.dwell = {'E', 0.1, "G04 without E"}; });
  EXPECT_EQ(run(fms, "G4 E25\n"), (Lines{"DW 2.5s", "END"}));
  EXPECT_EQ(run(fms, "G4 P25\n"), (Lines{"1:1 2004"}));
  // WL4: G4 X is a dwell word, not an error
  const Profile wl4 = nctWith([](MachineRules& r) { r.dwell = {'X', 1, "G4 without X"}; });
  EXPECT_EQ(run(wl4, "G4 X2\n"), (Lines{"DW 2s", "END"}));
}

TEST(MachineRules, MCodesActByTheirTableEntryAndTiming) {
  const std::string text = "G0 X10 M8\nM98\n";
  EXPECT_EQ(run(nct::profile(), "G0 X10 M8\n"), (Lines{"R 10,0,0", "EV M8", "END"}));
  const Profile fms = nctWith([](MachineRules& r) {
    for (MCodeSpec& m : r.mcodes) {
      if (m.code == 8) m.timing = MTiming::BeforeMotion; // coolant on before the move
      if (m.code == 98) m.action = MAction::End;         // FMS: M98 ends a program
    }
  });
  EXPECT_EQ(run(fms, text + "G0 X30\n"), (Lines{"EV M8", "R 10,0,0", "END"}));
  const Profile noCoolant = nctWith([](MachineRules& r) {
    std::erase_if(r.mcodes, [](const MCodeSpec& m) { return m.code == 8; });
  });
  EXPECT_EQ(run(noCoolant, "G0 X10 M8\n"), (Lines{"R 10,0,0", "END"})); // a warning only
}

TEST(MachineRules, SpeedToolAndSpindleCodesBeforeTheMotion) {
  const std::string text = "G1 X10 F100 S500 M3 T2\nM6\n";
  EXPECT_EQ(run(nct::profile(), text), (Lines{"L 10,0,0 F100", "EV S500 M3", "EV T2 M6", "END"}));
  // FMS-3000 (fms3000.md §1.4): S, T and M03/M04 before the motion, M05 after it
  const Profile fms = nctWith([](MachineRules& r) {
    r.speedTiming = r.toolTiming = MTiming::BeforeMotion;
    for (MCodeSpec& m : r.mcodes)
      if (m.code == 3 || m.code == 4) m.timing = MTiming::BeforeMotion;
  });
  EXPECT_EQ(run(fms, text), (Lines{"EV S500 M3", "L 10,0,0 F100", "EV T2 M6", "END"}));
  // the speed before the move, the stop after it
  EXPECT_EQ(run(fms, "G1 X10 F100 S500 M5\n"),
            (Lines{"EV S500 M5", "L 10,0,0 F100", "EV S500 M5", "END"}));
}

TEST(MachineRules, SurfaceSpeedRadiusAxisAndSpindleLimitWord) {
  const std::string text = "G92 S1000\nG96 S100\nG0 X20 Z10 M3\n";
  // NCT: at X0 the limit G92 S1000; at X20 100 m/min / (2 pi 0.02 m) = 795.7747 rpm
  EXPECT_EQ(run(nct::profile(), text),
            (Lines{"EV S1000 M5", "R 20,0,10", "EV S795.7747 M3", "END"}));
  // the radius along Z = 10: 1591.5494 rpm, clamped to the limit 1000
  const Profile alongZ = nctWith([](MachineRules& r) { r.surfaceSpeedAxis = 2; });
  EXPECT_EQ(run(alongZ, text), (Lines{"EV S1000 M5", "R 20,0,10", "EV S1000 M3", "END"}));
  // a dialect whose set-coordinates S is no spindle limit: S1000 is a speed, and G96 at
  // radius 0 has no limit
  const Profile noLimit = nctWith([](MachineRules& r) { r.setCoordinatesSIsSpindleLimit = false; });
  EXPECT_EQ(run(noLimit, text), (Lines{"EV S1000 M5", "2:1 2004"}));
}

TEST(MachineRules, LengthOffsetAlongZOrAlongThePlaneNormal) {
  machine::Setup s;
  s.tools[1].length = 10;
  const std::string text = "G18 G43 H1\nG0 X1 Y2 Z3\n";
  EXPECT_EQ(run(nct::profile(), text, s), (Lines{"R 1,2,13", "END"}));
  const Profile fms = nctWith([](MachineRules& r) { r.lengthAlongPlaneNormal = true; });
  EXPECT_EQ(run(fms, text, s), (Lines{"R 1,12,3", "END"})); // G18: the normal is Y
}

TEST(MachineRules, ArcCentreAbsoluteBySetting) {
  const std::string text = "G17 G90 G0 X10 Y0\nG3 X0 Y10 I0 J0 F100\n";
  // incremental: the centre is the start point, radius 0
  EXPECT_EQ(run(nct::profile(), text), (Lines{"R 10,0,0", "2:1 GCX037"}));
  Profile fms = nct::profile();
  fms.machine.settings.push_back({Setting::ArcCentreAbsolute, "N3021"});
  machine::Setup absolute;
  absolute.parameters = {{"N3021", 1}};
  EXPECT_EQ(run(fms, text, absolute), (Lines{"R 10,0,0", "CCW 0,10,0 C0,0 r10 θ90", "END"}));
}

TEST(MachineRules, ArcLIsTurnsOnlyWhereTheDialectSaysSo) {
  const std::string text = "G17 G90 G0 X10 Y0\nG3 X10 Y0 I-10 L2 F100\n";
  EXPECT_EQ(run(nct::profile(), text), (Lines{"R 10,0,0", "CCW 10,0,0 C0,0 r10 θ720", "END"}));
  const Profile wl4 = nctWith([](MachineRules& r) { r.arcL = ArcLMeaning::None; });
  EXPECT_EQ(run(wl4, text), (Lines{"R 10,0,0", "CCW 10,0,0 C0,0 r10 θ360", "END"}));
}

TEST(MachineRules, TransformWordsComeFromTheProfile) {
  const std::string nctText = "G17 G90 G68 X0 Y0 R90\nG1 X10 F100\nG69\nG51 X0 Y0 P2\nG1 X5 Y1\n";
  EXPECT_EQ(run(nct::profile(), nctText), (Lines{"L 0,10,0 F100", "L 10,2,0 F100", "END"}));
  // FMS-3000 (fms3000.md §3.12, §3.13): the angle is A; the axis words are the factors and the
  // centre is the work system's origin
  const Profile fms = nctWith([](MachineRules& r) {
    r.transform = {'A', 0, "XYZ", "G37 without A", "G69 without factors"};
  });
  const std::string fmsText = "G17 G90 G68 X0 Y0 A90\nG1 X10 F100\nG69\nG51 X2 Y3\nG1 X5 Y1\n";
  EXPECT_EQ(run(fms, fmsText), (Lines{"L 0,10,0 F100", "L 10,3,0 F100", "END"}));
  // under NCT's words the same blocks rotate by 0 (no R) and scale by 1 about X2 Y3
  EXPECT_EQ(run(nct::profile(), fmsText), (Lines{"L 10,0,0 F100", "L 5,1,0 F100", "END"}));
}

// Whether mirroring goes with a rotation or scaling and whether their switch-offs must nest are
// the dialect's rules (nct.md §3.15; FMS-3000 composes them in one order, fms3000.md Q6).
TEST(MachineRules, TransformRulesComeFromTheProfile) {
  const std::string mirror = "G17 G90 G68 X0 Y0 R90\nG51.1 X50\nG1 X10 Y0 F100\n";
  EXPECT_EQ(run(nct::profile(), mirror), (Lines{"2:1 2001"}));
  const Profile mixed =
      nctWith([](MachineRules& r) { r.transformRules.mirrorOnlyWithoutRotationOrScaling = false; });
  // X10 Y0 turned to X0 Y10, then mirrored about X50: the mirror acts last
  EXPECT_EQ(run(mixed, mirror), (Lines{"L 100,10,0 F100", "END"}));
  const std::string nest = "G17 G90 G51 X0 Y0 P2\nG68 X0 Y0 R90\nG50\nG1 X10 Y0 F100\n";
  EXPECT_EQ(run(nct::profile(), nest), (Lines{"3:1 GCX034"}));
  const Profile anyOrder =
      nctWith([](MachineRules& r) { r.transformRules.switchOffsMustNest = false; });
  EXPECT_EQ(run(anyOrder, nest), (Lines{"L 0,10,0 F100", "END"})); // the rotation stays
}

// NCT: G00-G03 cancel a canned cycle as G80 does (000:9479-9480); where a motion code does not,
// the next block with axis words drills again.
TEST(MachineRules, MotionCodeCancelsTheCycleWhereTheDialectSaysSo) {
  const std::string cycle = "G17 G90 G0 X0 Y0 Z10\nG81 X10 Y0 Z-5 R2 F100\n";
  EXPECT_EQ(run(nct::profile(), cycle + "G1 X20\n"),
            (Lines{"R 0,0,10", "R 10,0,10", "R 10,0,2", "L 10,0,-5 F100", "R 10,0,10",
                   "L 20,0,10 F100", "END"}));
  const Profile kept = nctWith([](MachineRules& r) { r.motionCancelsCycle = false; });
  EXPECT_EQ(run(kept, cycle + "G1 X20\n"), run(nct::profile(), cycle + "X20\n"));
}

TEST(MachineRules, WorkOffsetNamesComeFromTheProfile) {
  machine::Setup s;
  s.workOffsets = {
      {"G55", {1, 2, 3}}, {"W2", {4, 5, 6}}, {"G54.1 P7", {7, 8, 9}}, {"E7", {0, 0, 1}}};
  const std::string text = "G55 G0 X0 Y0 Z0\nG54.1 P7 G0 X0 Y0 Z0\n";
  EXPECT_EQ(run(nct::profile(), text, s), (Lines{"R 1,2,3", "R 7,8,9", "END"}));
  const Profile other = nctWith([](MachineRules& r) {
    r.workOffsetNames = {"W1", "W2"};
    r.extendedWorkOffsetPrefix = "E";
  });
  EXPECT_EQ(run(other, text, s), (Lines{"R 4,5,6", "R 0,0,1", "END"}));
}

// G10's L numbers and the extended work offsets' count are the profile's data (nct.md §3.14).
TEST(MachineRules, DataEntryCodesComeFromTheProfile) {
  const std::string text = "G10 L20 P99 X5\nG54.1 P99 G0 X0 Y0 Z0\nG10 L20 P100 X1\n";
  EXPECT_EQ(run(nct::profile(), text), (Lines{"R 5,0,0", "3:9 2002"}));
  Profile other = nctWith([](MachineRules& r) { r.extendedWorkOffsets = 3; });
  other.dataEntries = {{7, DataEntry::ExtendedWorkOffset}, {2, DataEntry::WorkOffset}};
  EXPECT_EQ(run(other, "G10 L7 P3 X5\nG54.1 P3 G0 X0 Y0 Z0\n"), (Lines{"R 5,0,0", "END"}));
  EXPECT_EQ(run(other, "G54.1 P4 G0 X0\n"), (Lines{"1:1 2004"}));
  EXPECT_EQ(run(other, "G10 L20 P1 X5\n"), (Lines{"1:1 GCX030"})); // L20 is not its code
}

} // namespace
} // namespace gcx::test
