#include "dialects/wl4/profile.h"

#include "cycles/contour_cycles.h"
#include "dialects/wl4/control_flow.h"
#include "dialects/wl4/machine_rules.h"

namespace gcx::wl4 {

namespace {

Profile build() {
  Profile p;
  p.name = "wl4";
  // Table 2 (wl4.md §1.4, minus signs restored); a repeated address: the last one is used and
  // several G and M words are allowed (§1.3), so every address may repeat
  const double coord = 9999.999;
  auto dim = [&](const char* a, const char* meaning) {
    return AddressSpec{a, true, true, false, -coord, coord, true, meaning};
  };
  auto whole = [](const char* a, double hi, const char* meaning) {
    return AddressSpec{a, false, false, false, 0, hi, true, meaning};
  };
  p.addresses = {
      whole("N", 65535, "block number / jump"),
      whole("G", 99, "preparatory function"),
      dim("X", "coordinate"),
      dim("Y", "coordinate"),
      dim("Z", "coordinate"),
      dim("A", "angle"),
      dim("B", "angle / chamfer"),
      dim("C", "angle"),
      dim("U", "incremental X"),
      dim("V", "incremental Y"),
      dim("W", "incremental Z"),
      dim("I", "arc centre X, cycle allowance"),
      dim("J", "arc centre Y"),
      dim("K", "arc centre Z, cycle allowance"),
      AddressSpec{"F", true, false, false, 0, 99999.999, true, "feed, thread lead"},
      whole("D", 127, "radius offset number"),
      whole("H", 127, "length offset number"),
      AddressSpec{"E", true, false, false, 0, 99999.999, true, "dwell, depth of cut"},
      whole("M", 99, "miscellaneous function"),
      AddressSpec{"R", true, false, false, 0, 99999.999, true, "arc radius, allowance"},
      whole("S", 65535, "spindle speed"),
      whole("T", 127, "tool"),
      AddressSpec{"P", true, false, false, 0, 1e300, true, "phase, angle, contour block"},
      AddressSpec{"Q", true, false, false, 0, 1e300, true, "contour block"},
  };
  // Table 3 (wl4.md §2.1); code x10, group, meaning, action. Codes gcx does not execute yet
  // are Unsupported: reported where they run, never ignored.
  using A = GAction;
  using C = cycles::ContourCycle;
  auto contour = [](C c) { return static_cast<int>(c); };
  p.gcodes = {
      {0, 1, "rapid positioning", A::Rapid},
      {10, 1, "linear interpolation", A::Linear},
      {20, 1, "circular interpolation CW", A::ArcCW},
      {30, 1, "circular interpolation CCW", A::ArcCCW},
      {120, 1, "90-degree fillet CW", A::FilletCW},
      {130, 1, "90-degree fillet CCW", A::FilletCCW},
      {320, 1, "thread motion", A::ThreadMotion},
      {330, 1, "reciprocating thread motion", A::ThreadReciprocating},
      {40, 0, "dwell", A::Dwell},
      {90, 0, "exact stop", A::ExactStopOnce},
      {310, 0, "threading cycle (%1)"},
      {700, 0, "longitudinal turning cycle (%1)"},
      {710, 0, "transverse turning cycle (%1)"},
      {720, 0, "deep grooving cycle (%1)"},
      {730, 0, "deep drilling cycle (%1)"},
      {740, 0, "face grooving cycle (%1)"},
      {750, 0, "grooving cycle (%1)"},
      // the internal contour cycles (§5.6): G76, and G77/G78 with P (without P the control-flow
      // engine calls %1 and the machine never sees them)
      {760, 0, "universal approximation cycle", A::ContourCycle, contour(C::Approach)},
      {770, 0, "longitudinal contour cycle", A::ContourCycle, contour(C::Longitudinal)},
      {780, 0, "transverse contour cycle", A::ContourCycle, contour(C::Transverse)},
      {790, 0, "reserved cycle (%1)"},
      {360, 0, "return to machine zero", A::ReferenceReturn}, // values ignored (§3.7)
      {380, 0, "probing move", A::ProbeReturn},               // no touch assumed (§3.8)
      {170, 2, "plane XY", A::PlaneXY},
      {180, 2, "plane ZX", A::PlaneZX},
      {190, 2, "plane YZ", A::PlaneYZ},
      {400, 3, "radius compensation off", A::RadiusCompOff},
      {410, 3, "radius compensation left", A::RadiusCompLeft},
      {420, 3, "radius compensation right", A::RadiusCompRight},
      {430, 4, "length compensation +", A::LengthPlus},
      {440, 4, "length compensation -", A::LengthMinus},
      {490, 4, "length compensation off", A::LengthCancel},
      {500, 11, "mirror off", A::MirrorOff},
      {510, 11, "mirror by axis sign / spindle limit", A::MirrorBySign},
      {530, 5, "machine coordinates", A::WorkOffset, 0}, // modal, the power-on system (§3.12)
      {540, 5, "work offset 1", A::WorkOffset, 1},
      {550, 5, "work offset 2", A::WorkOffset, 2},
      {560, 5, "work offset 3", A::WorkOffset, 3},
      {570, 5, "work offset 4", A::WorkOffset, 4},
      {580, 5, "work offset 5", A::WorkOffset, 5},
      {590, 5, "work offset 6", A::WorkOffset, 6},
      {920, 5, "set coordinate system", A::SetCoordinates}, // ended by G53-G59 (§3.11)
      {600, 6, "exact stop mode", A::ExactStopMode},
      {630, 6, "exact stop mode, feed override 100%", A::TappingMode},
      {640, 6, "continuous mode", A::ContinuousMode},
      // G80-G89: the control-flow engine's modal calls of %81-%89 (control_flow.cpp); the
      // machine only keeps the group
      {800, 7, "cancel canned cycle", A::Modeless},
      {810, 7, "canned cycle %81", A::Modeless},
      {820, 7, "canned cycle %82", A::Modeless},
      {830, 7, "canned cycle %83", A::Modeless},
      {840, 7, "canned cycle %84", A::Modeless},
      {850, 7, "canned cycle %85", A::Modeless},
      {860, 7, "canned cycle %86", A::Modeless},
      {870, 7, "canned cycle %87", A::Modeless},
      {880, 7, "canned cycle %88", A::Modeless},
      {890, 7, "canned cycle %89", A::Modeless},
      {900, 8, "absolute", A::Absolute},
      {910, 8, "incremental", A::Incremental},
      {940, 9, "feed per minute", A::FeedPerMinute},
      {950, 9, "feed per revolution", A::FeedPerRevolution},
      {960, 10, "constant cutting speed", A::SurfaceSpeedOn},
      {970, 10, "spindle rpm", A::SurfaceSpeedOff},
  };
  // power-on and reset (Table 3 defaults, wl4.md §2.1, §0.2)
  p.powerOnGCodes10 = {0, 170, 400, 490, 530, 640, 800, 900, 940, 970};
  p.uvwIncremental = true; // U V W are incremental X Y Z (§3.2)
  p.maxMCodesPerBlock = 6; // three at the start and three at the end of a block (§2.3)
  p.maxSkipLevel = 1;
  p.documentedSkipLevel = 1;
  // a G77/G78 contour has at most 200 blocks; F S T M in it are ignored (§5.6, 002:3069-3075,
  // 3108-3110)
  p.cycleChoices.maxContourBlocks = 200;
  p.cycleChoices.contourIgnoredWords = "FSTM";
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

} // namespace gcx::wl4
