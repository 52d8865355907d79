#include "dialects/fms3000/machine_rules.h"

#include "dialect/profile.h"

namespace gcx::fms3000 {

namespace {

std::vector<SettingSpec> settings() {
  using S = Setting;
  // The machine parameters of fms3000.md §0, under the manual's own names; the fallbacks are
  // the test state S0 of §8.
  return {
      // N3020 is named with the "radii at start and end differ" alarm (001:3892-3893) [D]
      {S::ArcRadiusTolerance, "N3020", nullptr, 0.001, "N3020"},
      // N3021: I/J/K incremental (0), absolute (1), or following G90/G91 (2) (001:1336-1400)
      {S::ArcCentreAbsolute, "N3021", nullptr, 0, "N3021"},
      // N3031: what G92's words mean (001:1789-1800): 0 the tool's position, 1 the origin in
      // machine coordinates, 2 a shift of the current origin that adds up
      {S::SetCoordinatesMode, "N3031", nullptr, 0, "N3031"},
      // N3023: the cycles that repeat modally until G80 (001:3516-3519); the setup writes the
      // set as bits, bit 0 = G81 ... bit 7 = G88 (N3023 = 1 is {81})
      {S::ModalLevelCycles, "N3023", nullptr, 0, "N3023"},
      // N7006: X in the turning cycles as radius (0) or diameter (1) (001:2758)
      {S::DiameterX, "N7006", nullptr, 0, "N7006"},
  };
}

std::vector<MCodeSpec> mcodes() {
  using A = MAction;
  using T = MTiming;
  // fms3000.md §2.2; timing per §1.4: M03/M04 before the motion, M05 and the stops after it
  return {
      {0, A::Stop, T::AfterMotion},
      {1, A::OptionalStop, T::AfterMotion},
      {2, A::End, T::AfterMotion},
      {30, A::EndRewind, T::AfterMotion},
      {3, A::SpindleCW, T::BeforeMotion},
      {4, A::SpindleCCW, T::BeforeMotion},
      {5, A::SpindleStop, T::AfterMotion},
      {25, A::Subprogram, T::AfterMotion},
      {98, A::Subprogram, T::AfterMotion},
      {99, A::Subprogram, T::AfterMotion},
      // The manual leaves every other M code to the machine's automation (001:3720-3721); the
      // machines follow the ГОСТ 20999-83 table it starts from (book-reference.md §2.2): M06
      // tool change, M07 coolant 2 (mist), M08 coolant 1 (flood), M09 coolant off. Coolant on
      // with the motion, off and the change after it, as M03/M05.
      {6, A::ToolChange, T::AfterMotion},
      {7, A::Coolant, T::BeforeMotion},
      {8, A::Coolant, T::BeforeMotion},
      {9, A::Coolant, T::AfterMotion},
  };
}

} // namespace

MachineRules machineRules() {
  MachineRules r;
  r.settings = settings();
  r.parameterKeyPrefix = "N";
  r.parameterKeyDigits = 4;
  r.mcodes = mcodes();
  // S and T before the motion (§1.4 step 1, §10 Q16)
  r.speedTiming = r.toolTiming = MTiming::BeforeMotion;
  r.skipSense = SkipSense::SkipWhenOn; // no block skip in FMS-3000; the reader rejects `/`
  // `G04 E<n>`: n tenths of a second (001:1616-1620); `G04 P500` is the Fanuc habit (§9)
  r.dwell = {'E', 0.1, "G04 without E (the dwell in tenths of a second, fms3000.md §3.9)", 'P',
             "G04 takes E in tenths of a second; P is the Fanuc dwell word and in FMS-3000 a "
             "subprogram call (fms3000.md §9)"};
  // G37 X Y A: rotation by A degrees (§3.12); G69 X Y Z: per-axis factors (§3.13)
  r.transform = {'A', 0, "XYZ", "G37 without A (fms3000.md §3.12)",
                 "G69 without factors (fms3000.md §3.13)"};
  // the transformations act in one order, polar -> rotation -> scale -> mirror (fms3000.md Q6):
  // mirroring, the outermost, goes with rotation and scaling, and they end in any order
  r.transformRules = {false, false, "fms3000.md §3.12-§3.14"};
  // a cycle and its parameters hold until G80 or another cycle (001:3514-3546, §5.1)
  r.motionCancelsCycle = false;
  r.arcL = ArcLMeaning::None;     // L is only G25's repeat count (§6.2)
  r.dwellAfterMotion = true;      // "after the motion and technological commands" (001:1623-1626)
  r.strictArcRadius = true;       // R0, chord > 2R, full circle by R: errors (001:1407-1427)
  r.centreWordsOnlyOnArcs = true; // I J K in a G0/G1 block: error (001:3793)
  // G30/G31: fixed points 1 and 2 at N7001-N7401 / N7002-N7402, one parameter per axis
  // (001:1573); G28: machine zero (001:1560-1568)
  r.directReferencePointKey = "N7{0}0{1}";
  // G60: approach from + with an overshoot of 1 mm. The manual sets both by a machine
  // parameter it does not number (001:1203-1231); these are the spec's test values (§0).
  r.oneSidedOvershoot = 1.0;
  // G43/G44 act along axis 3, 2 or 1 under G17, G18, G19 (001:1889-1931)
  r.lengthAlongPlaneNormal = true;
  r.surfaceSpeedAxis = 0;                  // the N1030 axis: X (§3.15)
  r.setCoordinatesSIsSpindleLimit = false; // the ceiling is LIMS (001:3597-3607)
  r.spindleLimitAddress = "LIMS";
  // G96 without S holds the surface speed of the current rpm and radius (001:3608-3621)
  r.surfaceSpeedHoldsCurrent = true;
  // "Программа без M2, M30": the end of the file reached without M2 or M30 (001:3880); M98 and
  // a standalone M99 end a program too (§2.2)
  r.endOfFileError = "the program reaches the end of its file without M02 or M30 (\"Программа "
                     "без M2, M30\", 001:3880; M98 or M99 end it too)";
  // the parameters gcx models in part (§0): the manual names N3022's two settings in words
  // (001:1137-1145), gcx reads 1 as "G0 with linear interpolation"; N3035 (001:2176-2190) is
  // the removal of radius compensation, modelled as 1, the spec's S0
  r.modelledValues = {
      {"N3022",
       {1},
       "only 1, \"G0 with linear interpolation\" (a straight rapid), is modelled; \"G0 without "
       "interpolation\" (each axis at its own rate, a dog-leg path, 001:1137-1145) is not"},
      {"N3035",
       {1},
       "only 1 (the cancel removes the offset on both plane axes when a plane axis moves) is "
       "modelled; 0 (only on the moved axis) and 2 (even without a move) are not "
       "(001:2176-2190)"},
  };
  r.workOffsetNames = {"G54", "G55", "G56", "G57", "G58", "G59"};
  // radius compensation (fms3000.md §4.2): outer corners on arcs (G14, the power-on state),
  // start-up and cancel on the perpendiculars, up to 10 blocks without plane motion
  r.compensation.outerCornerArcs = true;
  r.compensation.startUpPerpendicular = r.compensation.cancelPerpendicular = true;
  r.compensation.lookAheadBlocks = 11;
  // G164/G165 profile blocks (001:3287-3291): only N, X, Z, G1, G2, G3, G90, G91, I, J, R, F,
  // each with a number; the approach block may be a rapid (the manual's example approaches
  // with G1). K is the centre word of Z under G18 (§3.5).
  using A = GAction;
  r.profileBlock = {{A::Linear, A::ArcCW, A::ArcCCW, A::Absolute, A::Incremental},
                    {A::Rapid},
                    "NXZIJKRF",
                    "N X Z G1 G2 G3 G90 G91 I J K R F (001:3287-3291, 001:3903-3909)"};
  return r;
}

} // namespace gcx::fms3000
