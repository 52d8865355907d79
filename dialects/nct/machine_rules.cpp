#include "dialects/nct/machine_rules.h"

#include "dialect/profile.h"

namespace gcx::nct {

namespace {

std::vector<SettingSpec> settings() {
  using S = Setting;
  // Parameter keys as the setup file writes them: "N" + 4 digits, a bit by name or number.
  // The drilling defaults are the spec's test values (the seed gives none, cycles.md Q-6).
  return {
      {S::ArcRadiusTolerance, "N1339", nullptr, 0.01, "N1339 Radius Diff"}, // 000:1340
      {S::ParallelAxisU, "N0103.U"},                                        // nct.md §1.4
      {S::ParallelAxisV, "N0103.V"},
      {S::ParallelAxisW, "N0103.W"},
      {S::DiameterX, "N0106.DIAX"}, // nct.md §3.8
      {S::DiameterY, "N0106.DIAY"},
      {S::DiameterZ, "N0106.DIAZ"},
      {S::RolloverOn, "N0107.REN"}, // nct.md §3.10
      {S::RolloverBySign, "N0107.ABS"},
      {S::RolloverShortest, "N0107.ASH"},
      {S::RolloverAmount, "N0108", nullptr, 360},
      {S::DwellSecondsAlways, "N1337.SEC"}, // 000:3427-3442
      {S::PeckReturn, "N1500", nullptr, 0.5},
      {S::PeckClearance, "N1501", nullptr, 1.0},
      {S::BoreExtractionPct, "N1502", nullptr, 100},
      {S::TapReturn, "N1504", nullptr, 0.5},
      {S::TapClearance, "N1505", nullptr, 1.0},
      {S::TapExtractionPct, "N1506", nullptr, 100},
      {S::TapReturnPct, "N1507", nullptr, 100},
      {S::TapOrients, "N1503.TSC"},                                   // 000:9990-9998
      {S::TapPeckToR, "N1503.PTC", "N1503.3"},                        // 000:10057
      {S::TapExtractionEnabled, "N1503.EOE", "N1503.4"},              // 000:10015
      {S::TapReturnEnabled, "N1503.ROE", "N1503.5"},                  // 000:10094
      {S::SpindleOrientable, "N0607.ORI", "N0607.1", 1, "N0607 ORI"}, // 000:10167
      {S::SpindleIndexable, "N0607.INX", "N0607.2", 1, "N0607 INX"},  // 000:4559
      {S::CloseLoopMCode, "N0823", nullptr, 24, "N0823"},             // 000:9993
      {S::CompLookAhead, "N1404", nullptr, 0, "N1404 BK No. Interf"}, // 000:7593-7595
      {S::CompInterference, "N1403.IEN", nullptr, 1, "N1403 IEN"},    // 000:8229
      {S::CompMergeDistance, "N1405", nullptr, 0, "N1405 DELTV"},     // 000:7700-7712
  };
}

std::vector<MCodeSpec> mcodes() {
  using A = MAction;
  // nct.md §2.2: every M code acts after the motion of its block
  return {
      {0, A::Stop},        {1, A::OptionalStop}, {2, A::End},         {30, A::EndRewind},
      {3, A::SpindleCW},   {4, A::SpindleCCW},   {5, A::SpindleStop}, {19, A::SpindleOrient},
      {6, A::ToolChange},  {7, A::Coolant},      {8, A::Coolant},     {9, A::Coolant},
      {98, A::Subprogram}, {99, A::Subprogram},
  };
}

} // namespace

MachineRules machineRules() {
  MachineRules r;
  r.settings = settings();
  r.parameterKeyPrefix = "N"; // G10 L52 records (nct-macro.md §9.1)
  r.parameterKeyDigits = 4;
  r.parameterBits = true; // N1300.3, N0607.ORI (docs/machine-model.md)
  r.mcodes = mcodes();
  r.speedTiming = r.toolTiming = MTiming::AfterMotion; // nct.md §2.2
  r.skipSense = SkipSense::SkipWhenOn;                 // nct.md §1.6
  r.dwell = {'P', 1, "G4 without P", 'X',
             "G4 takes P (seconds, or revolutions in G95); X is not defined in NCT (Q37)"};
  r.transform = {'R', 'P', "IJK", "G68 without R: angle 0 (nct.md Q18)",
                 "G51 without P or I/J/K: scaling factor 1 (nct.md Q18)"}; // nct.md §3.15
  // mirror only in the G50 G69 state; G50 and G69 end scaling and rotation in reverse order
  r.transformRules = {true, true, "nct.md §3.15"};
  r.motionCancelsCycle = true;            // G00-G03 cancel a canned cycle like G80 (000:9479-9480)
  r.arcL = ArcLMeaning::Turns;            // 000:1340
  r.lengthAlongPlaneNormal = false;       // N1416 ZAX=1: along Z (nct.md §3.16)
  r.surfaceSpeedAxis = 0;                 // nct.md §3.18: the radius is |X|
  r.setCoordinatesSIsSpindleLimit = true; // G92 S (nct.md §3.18)
  r.workOffsetNames = {"G54", "G55", "G56", "G57", "G58", "G59"};
  r.extendedWorkOffsetPrefix = "G54.1 P";
  r.extendedWorkOffsets = 99; // G54.1 P1-P99 (nct.md §3.14)
  r.referencePoints = 4;      // G30 P1-P4 (nct.md Q15)
  // look-ahead breakers of radius compensation (nct.md §3.17.7, 000:7745-7768)
  using G = GAction;
  r.compensation.breakers = {G::StrokeLimitOn,      G::StrokeLimitOff,   G::WorkOffset,
                             G::ExtendedWorkOffset, G::LocalCoordinates, G::SetCoordinates,
                             G::MachineCoordinates, G::ReferenceReturn,  G::OtherReferenceReturn,
                             G::LengthPlus,         G::LengthMinus,      G::LengthCancel,
                             G::TurningOffsets};
  r.compensation.breakerMCodes = {MAction::Stop, MAction::OptionalStop, MAction::End,
                                  MAction::EndRewind};
  r.compensation.lengthWordBreaks = true;
  r.contour.chamfer = ",C"; // chapter 17 (nct.md §4)
  r.contour.rounding = ",R";
  r.contour.angle = ",A";
  return r;
}

} // namespace gcx::nct
