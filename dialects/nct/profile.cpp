#include "dialects/nct/profile.h"

#include "cycles/drilling_state.h"
#include "cycles/pocket.h"
#include "cycles/turning_state.h"
#include "diag/diagnostic.h"
#include "dialects/nct/arguments.h"
#include "dialects/nct/control_flow.h"
#include "dialects/nct/machine_rules.h"

namespace gcx::nct {

namespace {

Profile build() {
  Profile p;
  p.name = "nct";
  const double big = 99999999;
  auto coord = [](const char* a, const char* meaning) {
    return AddressSpec{a, true, true, true, -1e300, 1e300, false, meaning};
  };
  auto aux = [](const char* a, const char* meaning) {
    return AddressSpec{a, true, true, false, -1e300, 1e300, false, meaning};
  };
  auto integer = [](const char* a, double lo, double hi, const char* meaning) {
    return AddressSpec{a, false, false, false, lo, hi, false, meaning};
  };
  // nct.md §1.3, address table 000:33-85; ranges per nct-macro.md §1.2 and §2.6 (0 allowed
  // for M, H, D, L, T: M0, H0/D0, M99 L0 are documented codes).
  p.addresses = {
      integer("O", 0, big, "program number"),
      integer("N", 1, big, "block number"),
      AddressSpec{"G", true, false, false, 0, 9999.9, true, "preparatory function"},
      coord("X", "linear coordinate"),
      coord("Y", "linear coordinate"),
      coord("Z", "linear coordinate"),
      coord("U", "linear coordinate / incremental X"),
      coord("V", "linear coordinate / incremental Y"),
      coord("W", "linear coordinate / incremental Z"),
      coord("A", "angular coordinate"),
      coord("B", "angular coordinate"),
      coord("C", "angular coordinate"),
      coord("R", "arc radius, auxiliary data"),
      aux("I", "arc centre, auxiliary coordinate"),
      aux("J", "arc centre, auxiliary coordinate"),
      aux("K", "arc centre, auxiliary coordinate"),
      aux("E", "auxiliary coordinate"),
      AddressSpec{"F", true, false, false, 0, 1e300, false, "feed"},
      AddressSpec{"S", true, false, false, 0, big, false, "spindle speed"},
      AddressSpec{"M", false, false, false, 0, big, true, "miscellaneous function"},
      integer("T", 0, big, "tool number"),
      integer("H", 0, 999, "length offset number"),
      integer("D", 0, 999, "radius offset number"),
      integer("L", 0, big, "repetition count"),
      aux("P", "auxiliary data, dwell, program number"),
      aux("Q", "auxiliary data"),
      aux(",C", "chamfer"),
      aux(",R", "corner rounding radius"),
      aux(",A", "line direction angle"),
      AddressSpec{"AX", true, true, true, -1e300, 1e300, true, "axis given by its number"},
      AddressSpec{"<>", false, false, false, 0, 0, false, "program file of M98 / G65"},
  };
  // nct.md §2.1 (000:490-905) with the groups of nct-macro.md §2.9.4 (000:12690-12800). A
  // cycle code's arg names the cycle of the cycles library it runs (cycles.md §2.1, §4).
  using A = GAction;
  using D = cycles::DrillCycle;
  using T = cycles::TurningCycle;
  auto drill = [](D c) { return static_cast<int>(c); };
  auto turning = [](T c) { return static_cast<int>(c); };
  p.gcodes = {
      {0, 1, "rapid positioning", A::Rapid},
      {10, 1, "linear interpolation", A::Linear},
      {20, 1, "circular interpolation CW", A::ArcCW},
      {30, 1, "circular interpolation CCW", A::ArcCCW},
      {330, 1, "thread cutting"},
      {40, 0, "dwell", A::Dwell},
      {51, 0, "smoothing"},
      {71, 0, "cylindrical interpolation"},
      {90, 0, "exact stop", A::ExactStopOnce},
      {100, 0, "data input", A::DataInput},
      {109, 0, "radius/diameter switch", A::DiameterMode},
      {110, 0, "end of data input", A::DataInputEnd},
      {121, 21, "polar interpolation on"},
      {131, 21, "polar interpolation off", A::Modeless},
      {150, 17, "polar coordinates off", A::PolarOff},
      {160, 17, "polar coordinates on", A::PolarOn},
      {170, 2, "plane XY", A::PlaneXY},
      {180, 2, "plane ZX", A::PlaneZX},
      {190, 2, "plane YZ", A::PlaneYZ},
      {200, 6, "inch", A::Inch},
      {210, 6, "metric", A::Metric},
      {220, 4, "stroke limit on", A::StrokeLimitOn},
      {230, 4, "stroke limit off", A::StrokeLimitOff},
      {280, 0, "reference return", A::ReferenceReturn},
      {300, 0, "2nd/3rd/4th reference return", A::OtherReferenceReturn},
      {310, 0, "skip"},
      {370, 0, "tool length measurement"},
      {380, 0, "keep compensation vector", A::VectorHold}, // nct.md §3.17.5
      {390, 0, "corner arc", A::CornerArc},
      {400, 7, "radius compensation off", A::RadiusCompOff},
      {410, 7, "radius compensation left", A::RadiusCompLeft},
      {420, 7, "radius compensation right", A::RadiusCompRight},
      {430, 8, "length compensation +", A::LengthPlus},
      {440, 8, "length compensation -", A::LengthMinus},
      {431, 8, "length compensation along tool axis"},
      {434, 8, "TCP type 1"},
      {435, 8, "TCP type 2"},
      {437, 8, "turning offsets", A::TurningOffsets},
      {438, 8, "turning point control"},
      {439, 8, "turning point control"},
      {490, 8, "length compensation off", A::LengthCancel},
      {500, 11, "scaling off", A::ScaleOff},
      {510, 11, "scaling on", A::ScaleOn},
      {501, 22, "mirror off", A::MirrorOff},
      {511, 22, "mirror on", A::MirrorOn},
      {502, 31, "polygon turning off", A::Modeless},
      {512, 31, "polygon turning on"},
      {520, 0, "local coordinate system", A::LocalCoordinates},
      {530, 0, "machine coordinates", A::MachineCoordinates},
      {531, 0, "tool axis direction"},
      {536, 0, "tool axis direction"},
      {540, 14, "work offset 1", A::WorkOffset, 1},
      {541, 14, "extended work offset", A::ExtendedWorkOffset},
      {542, 14, "dynamic work offset"},
      {550, 14, "work offset 2", A::WorkOffset, 2},
      {560, 14, "work offset 3", A::WorkOffset, 3},
      {570, 14, "work offset 4", A::WorkOffset, 4},
      {580, 14, "work offset 5", A::WorkOffset, 5},
      {590, 14, "work offset 6", A::WorkOffset, 6},
      {610, 15, "exact stop mode", A::ExactStopMode},
      {620, 15, "inner corner override", A::CornerOverride},
      {630, 15, "tapping mode", A::TappingMode},
      {640, 15, "continuous mode", A::ContinuousMode},
      {650, 0, "macro call", A::MacroCall},
      {660, 12, "modal macro call", A::ModalMacroCall},
      {661, 12, "modal macro call, every block", A::ModalMacroCallEveryBlock},
      {670, 12, "modal macro call off", A::ModalMacroCancel},
      {680, 16, "rotation on", A::RotateOn},
      {690, 16, "rotation off", A::RotateOff},
      {681, 18, "3-D rotation"},
      {682, 18, "tilted working plane"},
      {691, 18, "3-D rotation off", A::Modeless},
      {707, 0, "finishing cycle", A::TurningCycle, turning(T::Finishing)},
      {717, 0, "stock removal in turning", A::TurningCycle, turning(T::RoughTurning)},
      {727, 0, "stock removal in facing", A::TurningCycle, turning(T::RoughFacing)},
      {737, 0, "pattern repeating", A::TurningCycle, turning(T::PatternRepeat)},
      {747, 0, "end face peck drilling", A::TurningCycle, turning(T::FaceGrooving)},
      {757, 0, "outer/inner diameter drilling", A::TurningCycle, turning(T::Grooving)},
      {767, 0, "multiple thread cutting", A::TurningCycle, turning(T::MultipleThread)},
      {777, 1, "turning cycle", A::TurningCycle, turning(T::TurningPass)},
      {787, 1, "thread cutting cycle", A::TurningCycle, turning(T::ThreadPass)},
      {797, 1, "facing cycle", A::TurningCycle, turning(T::FacingPass)},
      {730, 9, "peck drilling", A::DrillCycle, drill(D::HighSpeedPeck)},
      {740, 9, "counter tapping", A::DrillCycle, drill(D::LeftTapFloating)},
      {760, 9, "fine boring", A::DrillCycle, drill(D::FineBoring)},
      {800, 9, "cycle cancel", A::CycleCancel},
      {810, 9, "drilling", A::DrillCycle, drill(D::Drill)},
      {820, 9, "counter boring", A::DrillCycle, drill(D::DrillDwell)},
      {830, 9, "peck drilling", A::DrillCycle, drill(D::PeckDrill)},
      {840, 9, "tapping", A::DrillCycle, drill(D::RightTapFloating)},
      {842, 9, "rigid tapping", A::DrillCycle, drill(D::RigidTapRight)},
      {843, 9, "rigid counter tapping", A::DrillCycle, drill(D::RigidTapLeft)},
      {850, 9, "boring", A::DrillCycle, drill(D::BoreFeedOut)},
      {860, 9, "boring", A::DrillCycle, drill(D::BoreSpindleStop)},
      {870, 9, "back boring", A::DrillCycle, drill(D::BackBore)},
      {880, 9, "boring", A::DrillCycle, drill(D::BoreDwellManual)},
      {890, 9, "boring", A::DrillCycle, drill(D::BoreDwellFeedOut)},
      {808, 34, "electronic gear box off", A::Modeless},
      {818, 34, "electronic gear box on"},
      {900, 3, "absolute", A::Absolute},
      {910, 3, "incremental", A::Incremental},
      {920, 0, "set work coordinates", A::SetCoordinates},
      {940, 5, "feed per minute", A::FeedPerMinute},
      {950, 5, "feed per revolution", A::FeedPerRevolution},
      {960, 13, "constant surface speed", A::SurfaceSpeedOn},
      {970, 13, "constant surface speed off", A::SurfaceSpeedOff},
      {980, 10, "return to initial level", A::ReturnInitial},
      {990, 10, "return to R level", A::ReturnR},
  };
  // nct.md §0.2 reference profile and §2.1 defaults (N1300/N1301 all 0, Q12 for G23)
  p.powerOnGCodes10 = {0,   170, 210, 900, 940, 400, 490, 540, 670, 800,
                       640, 980, 150, 500, 501, 690, 970, 131, 230};
  p.uvwIncremental = true; // nct.md §1.4
  p.machine = machineRules();
  p.exclusiveMCodes = {3, 4, 5, 19};   // one spindle command per block (000:4278-4280)
  p.dataModeLCodes = {52, 75, 76, 77}; // G10 L52 parameters, L75-77 tool tables (nct.md §1.10)
  p.dataEntries = {{2, DataEntry::WorkOffset}, // G10 L2 P0-P6 (nct.md §3.14)
                   {20, DataEntry::ExtendedWorkOffset},
                   {10, DataEntry::ToolLength}, // gcx keeps geometry + wear per register
                   {11, DataEntry::ToolLengthWear}};
  // G10 L52 records N<id> [P<i>] [Q<bit>] R<value> (nct-macro.md §9.1)
  p.dataRecord = {9999, 'R', 'Q', 7, "PQGL", "G10 L52 record"};
  p.macroCallGCodes10 = {650, 660, 661};
  p.checkCallArguments = [](const ir::Block& b, diag::Engine& diags) {
    // statically only literal values are known; a variable may be vacant and skip its slot
    auto runtime = [](const ir::Word& w) { return !w.isLiteral(); };
    auto vacant = [](const ir::Word&) { return false; };
    ArgumentResult r = bindArguments(b, vacant, runtime);
    if (!r.ok()) diags.error(r.code, r.offending->range, r.message);
  };
  p.cycleMacros = {cycles::pocketCycleMacro()}; // G65 P9999 (cycles.md §5)
  p.controlFlow = &controlFlow(p.cycleMacros);
  p.index();
  return p;
}

} // namespace

const Profile& profile() {
  static const Profile p = build();
  return p;
}

} // namespace gcx::nct
