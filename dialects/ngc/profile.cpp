#include "dialects/ngc/profile.h"

#include "cycles/drilling_state.h"
#include "dialect/control_flow.h"

namespace gcx::ngc {

namespace {

const ControlFlow& controlFlow() {
  static const ControlFlow flow = [] {
    ControlFlow f;
    // #1-#30 are a subroutine's own (its call's arguments, 0 otherwise), #31-#5000 the user's
    // parameters every level shares; no parameter is ever vacant
    f.variables = VariableSpace{1, 30, 31, 5000};
    f.variables.vacant = false;
    f.callFrame = LocalFrame::Arguments;
    return f;
  }();
  return flow;
}

MachineRules machineRules() {
  MachineRules r;
  using A = MAction;
  // LinuxCNC's order of execution: spindle, tool change and coolant before the motion, stops
  // and the program end after it
  r.mcodes = {{0, A::Stop},
              {1, A::OptionalStop},
              {2, A::End},
              {30, A::EndRewind},
              {3, A::SpindleCW, MTiming::BeforeMotion},
              {4, A::SpindleCCW, MTiming::BeforeMotion},
              {5, A::SpindleStop, MTiming::BeforeMotion},
              {6, A::ToolChange, MTiming::BeforeMotion},
              {7, A::Coolant, MTiming::BeforeMotion},
              {8, A::Coolant, MTiming::BeforeMotion},
              {9, A::Coolant, MTiming::BeforeMotion}};
  r.speedTiming = r.toolTiming = MTiming::BeforeMotion;
  r.dwell = {'P', 1, "G4 without P", 0, ""};
  r.motionCancelsCycle = true; // G0-G3 and G80-G89 share modal group 1
  r.arcL = ArcLMeaning::None;  // the turns of an arc are P
  r.endOfFileError = "a LinuxCNC program ends with M2 or M30";
  r.workOffsetNames = {"G54", "G55", "G56", "G57", "G58", "G59"};
  return r;
}

Profile build() {
  Profile p;
  p.name = "ngc";
  p.controlFlow = &controlFlow();
  const auto number = [](const char* a, const char* meaning) {
    return AddressSpec{a, true, true, false, -1e300, 1e300, false, meaning};
  };
  p.addresses = {
      number("X", "axis"),
      number("Y", "axis"),
      number("Z", "axis"),
      number("A", "axis"),
      number("B", "axis"),
      number("C", "axis"),
      number("I", "arc centre"),
      number("J", "arc centre"),
      number("K", "arc centre"),
      number("R", "arc radius, cycle R level"),
      AddressSpec{"F", true, false, false, 0, 1e300, false, "feed"},
      AddressSpec{"S", true, false, false, 0, 1e300, false, "spindle speed"},
      AddressSpec{"T", false, false, false, 0, 99999, false, "tool"},
      AddressSpec{"H", false, false, false, 0, 99999, false, "length offset"},
      AddressSpec{"D", false, false, false, 0, 99999, false, "radius offset"},
      AddressSpec{"P", true, false, false, 0, 1e300, false, "dwell"},
      AddressSpec{"Q", true, false, false, 0, 1e300, false, "peck"},
      AddressSpec{"N", false, false, false, 0, 99999, false, "line number"},
      AddressSpec{"G", true, false, false, 0, 99.9, true, "G code"},
      AddressSpec{"M", false, false, false, 0, 199, true, "M code"},
  };
  using A = GAction;
  using D = cycles::DrillCycle;
  const auto drill = [](D c) { return static_cast<int>(c); };
  p.gcodes = {
      {0, 1, "rapid", A::Rapid},
      {10, 1, "feed", A::Linear},
      {20, 1, "arc clockwise", A::ArcCW},
      {30, 1, "arc counterclockwise", A::ArcCCW},
      {40, 0, "dwell", A::Dwell},
      {170, 2, "plane XY", A::PlaneXY},
      {180, 2, "plane XZ", A::PlaneZX},
      {190, 2, "plane YZ", A::PlaneYZ},
      {200, 6, "inch", A::Inch},
      {210, 6, "millimetre", A::Metric},
      {280, 0, "go to the G28 position", A::ReferenceReturn},
      {430, 8, "tool length offset", A::LengthPlus},
      {490, 8, "tool length offset off", A::LengthCancel},
      {540, 12, "work offset 1", A::WorkOffset, 1},
      {550, 12, "work offset 2", A::WorkOffset, 2},
      {560, 12, "work offset 3", A::WorkOffset, 3},
      {570, 12, "work offset 4", A::WorkOffset, 4},
      {580, 12, "work offset 5", A::WorkOffset, 5},
      {590, 12, "work offset 6", A::WorkOffset, 6},
      {610, 13, "exact path", A::ExactStopMode},
      {640, 13, "path blending", A::ContinuousMode},
      {730, 1, "drilling with chip breaking", A::DrillCycle, drill(D::HighSpeedPeck)},
      {800, 1, "cycle off", A::CycleCancel},
      {810, 1, "drilling", A::DrillCycle, drill(D::Drill)},
      {820, 1, "drilling with dwell", A::DrillCycle, drill(D::DrillDwell)},
      {830, 1, "peck drilling", A::DrillCycle, drill(D::PeckDrill)},
      {850, 1, "boring, feed out", A::DrillCycle, drill(D::BoreFeedOut)},
      {900, 3, "absolute", A::Absolute},
      {910, 3, "incremental", A::Incremental},
      {940, 5, "units per minute", A::FeedPerMinute},
      {950, 5, "units per revolution", A::FeedPerRevolution},
      {980, 10, "retract to the old level", A::ReturnInitial},
      {990, 10, "retract to R", A::ReturnR},
  };
  p.minSequenceNumber = 0;
  p.maxSequenceNumber = 99999;
  p.machine = machineRules();
  p.index();
  return p;
}

} // namespace

const Profile& profile() {
  static const Profile p = build();
  return p;
}

} // namespace gcx::ngc
