#include "dialects/wl4/machine_rules.h"

namespace gcx::wl4 {

namespace {

std::vector<MCodeSpec> mcodes() {
  using A = MAction;
  using T = MTiming;
  // Table 4 (wl4.md §2.3); its timing columns were lost, the timing is the spec's [D]
  return {
      {0, A::Stop, T::AfterMotion},
      {1, A::OptionalStop, T::AfterMotion},
      {2, A::End, T::AfterMotion},
      {30, A::EndRewind, T::AfterMotion},
      {3, A::SpindleCW, T::BeforeMotion},
      {4, A::SpindleCCW, T::BeforeMotion},
      {5, A::SpindleStop, T::AfterMotion},
      {19, A::SpindleOrient, T::BeforeMotion},
      {6, A::ToolChange, T::BeforeMotion},
      {7, A::Coolant, T::BeforeMotion},
      {8, A::Coolant, T::BeforeMotion},
      {9, A::Coolant, T::AfterMotion},
      {99, A::Subprogram, T::AfterMotion},
      // gear ranges: #117 reports the last one (§2.2), %87 and %88 restore it
      {40, A::GearRange, T::BeforeMotion},
      {41, A::GearRange, T::BeforeMotion},
      {42, A::GearRange, T::BeforeMotion},
      {43, A::GearRange, T::BeforeMotion},
      {44, A::GearRange, T::BeforeMotion},
      {45, A::GearRange, T::BeforeMotion},
      {46, A::GearRange, T::BeforeMotion},
      {47, A::GearRange, T::BeforeMotion},
      {48, A::GearRange, T::BeforeMotion},
  };
}

} // namespace

MachineRules machineRules() {
  MachineRules r;
  r.settings = {{Setting::ArcRadiusTolerance, "arc_tolerance", nullptr, 0.002,
                 "arc end-point tolerance"}, // wl4.md §0.2
                // machine.kind = lathe (§0.2): X and U are diameters, I a radius (002:659)
                {Setting::DiameterX, "lathe", nullptr, 0, "lathe: X is a diameter"},
                // #117 before the first M41-M48 (§2.2): the machine's, 41 unless set [D]
                {Setting::PowerOnGearRange, "gear_range", nullptr, 41, "power-on gear range"}};
  // no numbered parameters: the manual gives none (§0.2); arc_tolerance is gcx's setting
  r.mcodes = mcodes();
  r.speedTiming = r.toolTiming = MTiming::BeforeMotion;
  // T moves the zero by its working point's offsets and brings its nose radius Rt, which adds
  // to corrector D (§4.1, 002:1268-1328, 1547-1577)
  r.toolSelectsOffsets = true;
  // "switching G97 to G96 or back without a new S in the same block is not allowed" (§2.4,
  // 002:1265-1267, 1534-1536); a G32 sequence ends with G9 and G0-G3 (§3.6, 002:789-793)
  r.surfaceSpeedSwitchNeedsS = true;
  r.threadSequenceEnds = true;
  r.skipSense = SkipSense::RunWhenOn; // `/` blocks run only with the flag set (§1.7)
  // G4 E<seconds> (002:979); the cycle texts write G4 X (§10 item 5): both read as seconds
  r.dwell = {'E', 1, "G4 without E (seconds)", 0, "", 'X'};
  // no rotation or scaling to combine with mirroring (wl4.md §9); the canned cycles are modal
  // calls of %81-%89 that only G80 cancels (wl4.md §5.1)
  r.transformRules = {false, false, "wl4.md §3.13"};
  r.motionCancelsCycle = false;
  r.arcL = ArcLMeaning::None;          // L is a call, never an arc word
  r.arcWithinToleranceIsCircle = true; // |CE| - |CS| up to 0.002 mm: still the circle (§3.4)
  // G36 goes straight to machine zero on the named axes, whatever their values (§3.7); WL4 has
  // no other reference point, so the key of point n > 0 is never read
  r.directReferencePointKey = "reference_point_{1}_axis_{0}";
  r.workOffsetEndsSetCoordinates = true; // G92 is cancelled by G53-G59 (§3.11)
  r.workOffsetNames = {"G54", "G55", "G56", "G57", "G58", "G59"};
  // radius compensation (wl4.md §4.2): an outer corner whose offsets leave a gap above Delt_L
  // (0.01 mm [D]) is passed on an arc about the corner point, else at their intersection
  r.compensation.outerCornerArcs = true;
  r.compensation.arcGapLimit = 0.01;
  // blocks without motion under compensation are "not recommended" (002:1397-1400): a warning
  r.compensation.warnWithoutPlaneMotion = true;
  // B is a rotary axis, or with the setup's b_chamfer = 1 the automatic chamfer's leg (§3.16)
  r.contour.chamferAxis = 'B';
  r.contour.chamferAxisKey = "b_chamfer";
  // G38 (§3.8): the spec's static reading, the results #1000-#1027 (system_variables.cpp)
  r.probeWithoutTouch = "G38: gcx has no probe model and assumes no touch (wl4.md §3.8): the move "
                        "runs to its end point and back, and #1000-#1027 hold the end point";
  return r;
}

} // namespace gcx::wl4
