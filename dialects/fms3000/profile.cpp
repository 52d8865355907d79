#include "dialects/fms3000/profile.h"

#include "cycles/level_cycle.h"
#include "dialects/fms3000/control_flow.h"
#include "dialects/fms3000/machine_rules.h"

namespace gcx::fms3000 {

namespace {

using L = cycles::LevelCycle;
// the level cycles bound by meaning (fms3000.md §5); GCodeSpec::arg carries the cycle
constexpr int level(L cycle) {
  return static_cast<int>(cycle);
}

std::vector<AddressSpec> addresses() {
  const double big = 1e16; // ±1E16 mm (Table 3, 001:298-300)
  auto coord = [&](const char* a, const char* meaning) {
    return AddressSpec{a, true, true, false, -big, big, false, meaning};
  };
  auto integer = [](const char* a, double lo, double hi, const char* meaning) {
    return AddressSpec{a, false, false, false, lo, hi, false, meaning};
  };
  // Table 3 (001:295-313), fms3000.md §1.2; numbers are millimetres with or without a point
  return {
      AddressSpec{"G", false, false, false, 0, 255, true, "preparatory function"},
      AddressSpec{"GG", false, false, false, 0, 255, true, "built-in G function"},
      coord("X", "linear axis 1"),
      coord("Y", "linear axis 2"),
      coord("Z", "linear axis 3, cycle point 2"),
      coord("U", "linear axis parallel to X, cycle point 1"),
      coord("V", "linear axis parallel to Y, cycle parameter"),
      coord("W", "linear axis parallel to Z, cycle parameter"),
      coord("A", "rotary axis about X; G36/G37/G162 angle"),
      coord("B", "rotary axis about Y"),
      coord("C", "rotary axis about Z"),
      coord("I", "arc centre axis 1, helix pitch, polar radius, cycle point 4"),
      coord("J", "arc centre axis 2, helix pitch"),
      coord("K", "arc centre axis 3, helix pitch"),
      coord("R", "arc radius, chamfer or fillet size"),
      coord("Q", "cycle parameter"),
      coord("P", "subprogram call, cycle parameter"),
      coord("DX", "surface normal X (G143/G144)"),
      coord("DY", "surface normal Y (G143/G144)"),
      coord("DZ", "surface normal Z (G143/G144)"),
      AddressSpec{"F", true, false, false, 0, 1.7e38, false, "feed"},
      AddressSpec{"S", true, false, false, 0, 9999, false, "spindle speed"},
      AddressSpec{"LIMS", true, false, false, 0, 9999, false, "spindle speed ceiling (G96)"},
      AddressSpec{"M", false, false, false, 0, 99, true, "auxiliary function"},
      integer("T", 0, 9999, "tool number"),
      AddressSpec{"H", true, false, false, 0, 1.7e38, false, "length offset number, G82 feed"},
      coord("D", "radius offset number, turning-cycle retract"),
      integer("DR", 0, 255, "corner radius offset number (G143/G144)"),
      integer("E", 0, 65535, "dwell in tenths of a second, cycle dwell"),
      integer("L", 1, 1e9, "repeat count of G25"),
  };
}

std::vector<GCodeSpec> gcodes() {
  using A = GAction;
  // Table 6 (001:927-1073), fms3000.md §2.1. Codes whose FMS-3000 meaning the machine model
  // does not execute yet are Unsupported: a located error, never the NCT meaning of the number.
  return {
      {0, 1, "rapid positioning", A::Rapid},
      {10, 1, "linear interpolation", A::Linear},
      {20, 1, "circular interpolation CW", A::ArcCW},
      {30, 1, "circular interpolation CCW", A::ArcCCW},
      {40, 0, "dwell (E, tenths of a second)", A::Dwell},
      {90, 0, "decelerate at the end of the block", A::ExactStopOnce},
      {100, 0, "helical interpolation (with G02/G03)", A::HelicalQualifier},
      {140, 2, "corner transition by arcs", A::Modeless},
      {150, 2, "corner transition by straight segments", A::Modeless},
      {170, 3, "plane 1-2 (XY)", A::PlaneXY},
      {180, 3, "plane 3-1 (ZX)", A::PlaneZX},
      {190, 3, "plane 2-3 (YZ)", A::PlaneYZ},
      {200, 3, "arbitrary plane"},
      {210, 4, "feed override enabled", A::Modeless},
      {220, 4, "feed override disabled", A::Modeless},
      {230, 5, "spindle override enabled", A::Modeless},
      {240, 5, "spindle override disabled", A::Modeless},
      {250, 0, "start of a repeated fragment"},
      // G27 homes the named axes through their limit switches (001:1549-1558): for the path
      // a rapid to machine zero on those axes, like G28 (fms3000.md §3.8)
      {270, 0, "home via the limit switches", A::ReferenceReturn, 0},
      {280, 0, "rapid to machine zero", A::ReferenceReturn, 0},
      {300, 0, "rapid to fixed point 1", A::ReferenceReturn, 1},
      {310, 0, "rapid to fixed point 2", A::ReferenceReturn, 2},
      // without a probe model the touch never comes: the full move (§3.17, 001:1594-1611)
      {320, 0, "end the motion on the touch signal", A::SkipMove},
      // one block: its G1 move synchronised with the spindle, F the lead in mm per revolution;
      // an error under G0 (001:1517-1530, 001:3855)
      {330, 0, "thread cutting", A::ThreadOnce},
      // the contour starts on the encoder's zero mark: timing only (001:1586-1592)
      {340, 0, "synchronise with the encoder zero mark", A::Modeless},
      // G35 ends group 06: polar mode and the G37 rotation (§10 Q19)
      {350, 6, "Cartesian coordinates", A::RotateOff},
      {360, 6, "polar coordinates", A::PolePolar},
      {370, 6, "rotation of the coordinate system", A::RotateOn},
      {380, 0, "no single-block stop", A::Modeless},
      {390, 0, "Stop button inhibited", A::Modeless},
      {400, 7, "radius compensation off", A::RadiusCompOff},
      {410, 7, "radius compensation left", A::RadiusCompLeft},
      {420, 7, "radius compensation right", A::RadiusCompRight},
      {1430, 7, "spatial compensation"},
      {1440, 7, "mirrored spatial compensation"},
      {430, 8, "length compensation +", A::LengthPlus},
      {440, 8, "length compensation -", A::LengthMinus},
      {490, 8, "length compensation off", A::LengthCancel},
      // dependent axes (N5018-N5418) are not modelled: G45 warns and acts as G46 (§10 Q25)
      {450, 9, "dependent axes on", A::Modeless},
      {460, 9, "dependent axes off", A::Modeless},
      {470, 0, "implicit coordinate +", A::ImplicitPlus},
      {480, 0, "implicit coordinate -", A::ImplicitMinus},
      {500, 11, "geometric feed regulation", A::Modeless},
      // G53 is modal (001:1823-1828): a work system whose offset is zero
      {530, 10, "machine coordinate system (modal)", A::WorkOffset, 0},
      {540, 10, "work coordinate system 1", A::WorkOffset, 1},
      {550, 10, "work coordinate system 2", A::WorkOffset, 2},
      {560, 10, "work coordinate system 3", A::WorkOffset, 3},
      {570, 10, "work coordinate system 4", A::WorkOffset, 4},
      {580, 10, "work coordinate system 5", A::WorkOffset, 5},
      {590, 10, "work coordinate system 6", A::WorkOffset, 6},
      {600, 0, "one-sided positioning", A::OneSidedPositioning},
      {610, 11, "exact stop at every block", A::ExactStopMode},
      {620, 11, "cancel G50/G61/G63", A::ContinuousMode},
      {630, 11, "decelerate every block to the N3000 feed", A::Modeless},
      {640, 0, "decelerate at the end of the block to the N3000 feed", A::Modeless},
      {650, 12, "arc feed recalculation on", A::Modeless},
      {660, 12, "arc feed recalculation off", A::Modeless},
      {670, 0, "mirror on", A::MirrorOn},
      {680, 0, "mirror off", A::MirrorOff},
      {690, 0, "scale factors", A::ScaleOn},
      {800, 13, "cycle cancel", A::CycleCancel},
      {810, 13, "drilling cycle", A::LevelDrillCycle, level(L::Drill)},
      {820, 13, "boring cycle, feed exit", A::LevelDrillCycle, level(L::BoreFeedExit)},
      {830, 13, "deep drilling cycle", A::LevelDrillCycle, level(L::DeepDrill)},
      {840, 13, "tapping cycle", A::LevelDrillCycle, level(L::Tap)},
      {850, 13, "boring cycle, spindle stop", A::LevelDrillCycle, level(L::BoreSpindleStop)},
      {860, 13, "chip-breaking drilling cycle", A::LevelDrillCycle, level(L::ChipBreakDrill)},
      {870, 13, "interrupted drilling cycle with dwells", A::LevelDrillCycle,
       level(L::InterruptedDrill)},
      {880, 13, "boring cycle, oriented stop", A::LevelDrillCycle, level(L::BoreOrientedStop)},
      {1500, 13, "single-pass longitudinal turning", A::LevelDrillCycle,
       level(L::LongitudinalPass)},
      {1510, 13, "single-pass facing", A::LevelDrillCycle, level(L::FacingPass)},
      {1520, 13, "multi-pass longitudinal turning", A::LevelDrillCycle,
       level(L::LongitudinalMultiPass)},
      {1530, 13, "multi-pass facing", A::LevelDrillCycle, level(L::FacingMultiPass)},
      {1540, 13, "deep drilling along Z", A::LevelDrillCycle, level(L::DeepDrillZ)},
      {1550, 13, "peck grooving along X", A::LevelDrillCycle, level(L::PeckGrooveX)},
      {1560, 13, "deep drilling along Z, decreasing step", A::LevelDrillCycle,
       level(L::DeepDrillZDecreasing)},
      {1570, 13, "peck grooving along X, decreasing step", A::LevelDrillCycle,
       level(L::PeckGrooveXDecreasing)},
      {1580, 13, "cylindrical grooves", A::LevelDrillCycle, level(L::CylindricalGrooves)},
      {1590, 13, "face grooves", A::LevelDrillCycle, level(L::FaceGrooves)},
      {1600, 13, "chip-breaking drilling along Z", A::LevelDrillCycle, level(L::ChipBreakDrillZ)},
      {1610, 13, "chip-breaking grooving along X", A::LevelDrillCycle, level(L::ChipBreakGrooveX)},
      {1620, 13, "multi-pass thread", A::LevelDrillCycle, level(L::MultiPassThread)},
      {1630, 13, "tap or die", A::LevelDrillCycle, level(L::TapOrDie)},
      {1640, 13, "longitudinal roughing to a profile", A::LevelDrillCycle,
       level(L::LongitudinalRoughing)},
      {1650, 13, "facing roughing to a profile", A::LevelDrillCycle, level(L::FacingRoughing)},
      {1660, 0, "chamfer", A::LevelDrillCycle, level(L::Chamfer)},
      {1670, 0, "fillet", A::LevelDrillCycle, level(L::Fillet)},
      {900, 14, "absolute", A::Absolute},
      {910, 14, "incremental", A::Incremental},
      {920, 10, "set the work system (N3031)", A::SetCoordinates},
      {940, 15, "feed per minute", A::FeedPerMinute},
      {950, 15, "feed per revolution", A::FeedPerRevolution},
      {960, 16, "constant surface speed", A::SurfaceSpeedOn},
      {970, 16, "spindle speed in rpm", A::SurfaceSpeedOff},
  };
}

Profile build() {
  Profile p;
  p.name = "fms3000";
  p.addresses = addresses();
  p.gcodes = gcodes();
  // the test state S0 (fms3000.md §8): G00 G17 G90 G94 G97 G54 G40 G49 G80 G35 G62 G21 G23
  // G46 G14 G66
  p.powerOnGCodes10 = {0,   170, 900, 940, 970, 540, 400, 490,
                       800, 350, 620, 210, 230, 460, 140, 660};
  p.maxMCodesPerBlock = 20;      // 001:3715
  p.exclusiveMCodes = {3, 4, 5}; // one spindle command per block
  p.lastOfModalGroupWins = true; // several codes of one group: the last wins (001:1083-1087)
  p.minSequenceNumber = 0;       // N0-N9999999 (001:344-356)
  p.maxSequenceNumber = 9999999;
  p.maxSkipLevel = 0; // no block skip (§1.1)
  p.documentedSkipLevel = 0;
  p.machine = machineRules();
  p.controlFlow = &controlFlow();
  p.index();
  return p;
}

} // namespace

const Profile& profile() {
  static const Profile p = build();
  return p;
}

} // namespace gcx::fms3000
