// The interpreter's side of cutter radius compensation (docs/compensation.md): which side, which
// radius, start-up and cancel checks, look-ahead breakers. The path itself is the stage's
// (compensation.h).
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"
#include "emit/number.h"
#include "machine/interpreter.h"
#include "machine/settings.h"
#include "motion/geometry.h"

namespace gcx::machine {

namespace {

// A block without plane words moves in the plane only as an arc with a centre word there (a full
// circle). Blocks of statements only never reach the machine.
bool movesInPlane(const BlockWords& w, const motion::PlaneAxes& ax, bool arcMode, bool planeWords) {
  return planeWords || (arcMode && (w.ijk[ax.first] || w.ijk[ax.second]));
}

} // namespace

std::optional<double> Interpreter::compensationRadius(const BlockWords& w) {
  double d = 0;
  if (state_.lastD != 0) {
    const auto it = setup_.tools.find(state_.lastD);
    if (it == setup_.tools.end()) {
      fail(diag::code::CompNoRegister, w.d ? w.d->range : blockRange_,
           fmt::format("D{}: the setup's tool table has no radius register {}", state_.lastD,
                       state_.lastD));
      return std::nullopt;
    }
    d = it->second.radius;
  }
  if (!profile_.machine.toolSelectsOffsets) return d; // a negative D swaps the side
  // the nose radius Rt of the selected tool plus corrector D, never below 0 (wl4.md §4.1)
  const auto t = setup_.tools.find(state_.selectedTool);
  const double rt = state_.selectedTool == 0 || t == setup_.tools.end() ? 0 : t->second.noseRadius;
  if (rt + d < 0) {
    fail(diag::code::CompNegativeRadius, w.d ? w.d->range : blockRange_,
         fmt::format("the compensation radius Rt + D = {:g} + {:g} of tool {} and register D{} is "
                     "negative: Rt + D must be >= 0",
                     rt, d, state_.selectedTool, state_.lastD));
    return std::nullopt;
  }
  return rt + d;
}

CompensationStage::Options Interpreter::compensationOptions() const {
  CompensationStage::Options o;
  o.lookAheadBlocks = 2 + static_cast<int>(setting(profile_, setup_, Setting::CompLookAhead));
  o.interferenceCheck = setting(profile_, setup_, Setting::CompInterference, 1) == 1;
  o.mergeDistance = setting(profile_, setup_, Setting::CompMergeDistance);
  const CompensationRules& rules = profile_.machine.compensation;
  if (rules.lookAheadBlocks > 0) o.lookAheadBlocks = rules.lookAheadBlocks;
  if (rules.outerCornerArcs) o.outer = comp::OuterCorner::Arc;
  o.arcGapLimit = rules.arcGapLimit;
  o.startUpPerpendicular = rules.startUpPerpendicular;
  o.cancelPerpendicular = rules.cancelPerpendicular;
  return o;
}

bool Interpreter::compensationFailed(const CompensationFailure& f) {
  diag::Diagnostic d{diag::Severity::Error, f.code, f.message, SourceRange{f.at.at, 1}, {}};
  for (auto it = f.at.chain.rbegin(); it != f.at.chain.rend(); ++it)
    d.notes.push_back({SourceRange{it->call, 1}, "in " + it->what});
  diags_.report(std::move(d));
  return false;
}

bool Interpreter::radiusCompensation(const BlockWords& w, const ModalState& before) {
  const bool on = state_.radiusComp != GAction::RadiusCompOff;
  for (GAction a : {GAction::CornerArc, GAction::VectorHold})
    if (const ir::Word* g = w.findAction(a); g && (!on || keepCompensation_))
      return fail(diag::code::CompOnlyCode, g->range,
                  fmt::format("G{} acts only while radius compensation (G41/G42) is on",
                              emit::formatNumber(g->number)));
  if (!on && !comp_.engaged() && keptSide_ == 0) return true;
  if (!comp_.beginBlock(*sink_)) return compensationFailed(*comp_.failure());
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  const bool arcMode = state_.motion == GAction::ArcCW || state_.motion == GAction::ArcCCW;
  const bool planeWords = axisGiven(w, ax.first) || axisGiven(w, ax.second);
  const ir::Word* startWord = w.findAction(GAction::RadiusCompLeft);
  if (!startWord) startWord = w.findAction(GAction::RadiusCompRight);
  const ir::Word* cancelWord = w.findAction(GAction::RadiusCompOff);
  if (before.radiusComp != GAction::RadiusCompOff &&
      (state_.plane != before.plane || state_.planeAxes != before.planeAxes)) {
    const ir::Word* g = w.findAction(GAction::PlaneXY);
    if (!g) g = w.findAction(GAction::PlaneZX);
    if (!g) g = w.findAction(GAction::PlaneYZ);
    return fail(diag::code::CompPlaneChange, g ? g->range : blockRange_,
                "the plane changes while radius compensation is on: cancel it (G40) first");
  }
  if (startWord && before.radiusComp == GAction::RadiusCompOff && arcMode && planeWords)
    return fail(diag::code::CompStartInArc, startWord->range,
                "radius compensation starts only in a G0 or G1 block, not in an arc "
                "(nct.md §3.17.2)");
  if (cancelWord && before.radiusComp != GAction::RadiusCompOff && arcMode && planeWords)
    return fail(diag::code::CompCancelInArc, cancelWord->range,
                "radius compensation is cancelled only in a G0 or G1 block, not in an arc "
                "(nct.md §3.17.3)");
  int side = 0;
  double radius = 0;
  if (on) {
    side = state_.radiusComp == GAction::RadiusCompLeft ? 1 : -1;
    const auto r = compensationRadius(w);
    if (!r) return false;
    radius = *r;
    if (radius < 0) side = -side, radius = -radius; // a negative radius swaps the side
    // an odd number of mirrored plane axes swaps G41 and G42 (nct.md §3.15)
    const Eigen::Matrix3d m = transforms_.matrix().linear();
    const double det = m(ax.first, ax.first) * m(ax.second, ax.second) -
                       m(ax.first, ax.second) * m(ax.second, ax.first);
    if (det < 0) side = -side;
  }
  if (on && profile_.machine.compensation.warnWithoutPlaneMotion &&
      !movesInPlane(w, ax, arcMode, planeWords))
    diags_.warning(diag::code::CompWithoutPlaneMotion, blockRange_,
                   "a block without motion in the plane while radius compensation is on: a "
                   "control that reads only the next block may cut the corner across it wrongly");
  if (keepCompensation_) { // the target compensates: tell it, keep the programmed path
    if (side != keptSide_ || radius != keptRadius_) {
      motion::Event e;
      e.kind = motion::Kind::RadiusComp;
      e.start = e.end = machine_;
      e.extraStart = e.extraEnd = extra_;
      e.value = side;
      e.startRadius = radius;
      e.plane = state_.plane;
      emit(std::move(e));
      keptSide_ = side, keptRadius_ = radius;
    }
    return true;
  }
  // a start-up's or cancel's I J K: the direction of a virtual element (nct.md §3.17.2-3)
  std::optional<comp::Vec2> direction;
  if ((startWord || cancelWord) && !arcMode && (w.ijk[ax.first] || w.ijk[ax.second])) {
    Vec3 v = Vec3::Zero();
    for (int a : {ax.first, ax.second})
      if (w.ijk[a]) v[a] = mm(w.ijk[a]->number);
    v = transforms_.matrix().linear() * v;
    direction = comp::Vec2(v[ax.first], v[ax.second]);
  }
  const CompensationRules& rules = profile_.machine.compensation;
  bool breaks = w.h && rules.lengthWordBreaks;
  for (const GCodeSpec* g : w.gCodes)
    breaks = breaks || (g && std::ranges::find(rules.breakers, g->action) != rules.breakers.end());
  for (const ir::Word* mw : w.m) {
    const MCodeSpec* spec = profile_.machine.mcode(static_cast<int>(mw->number));
    breaks = breaks || (spec && std::ranges::find(rules.breakerMCodes, spec->action) !=
                                    rules.breakerMCodes.end());
  }
  // a canned cycle's holes and passes are not compensated (cycles.md Q-20): a breaker too
  breaks = breaks || (state_.cycle == GAction::DrillCycle && !deferCycles_) || pendingTurning_ ||
           state_.motion == GAction::TurningCycle;
  // a T that moves the zero changes the frame the waiting element was offset in
  breaks = breaks || (w.t && profile_.machine.toolSelectsOffsets);
  if (breaks) comp_.breakLookAhead(*sink_);
  // G39 corner arc, G38 vector hold (nct.md §3.17.5)
  for (GAction a : {GAction::CornerArc, GAction::VectorHold}) {
    const ir::Word* g = w.findAction(a);
    if (!g) continue;
    if (a == GAction::VectorHold) {
      comp_.holdVector();
    } else if (w.hasAxisWord()) {
      return fail(diag::code::CornerArcBlock, g->range,
                  "G39 stands in a block of its own, without axis words (nct.md §3.17.5)");
    } else if (w.ijk[0] || w.ijk[1] || w.ijk[2]) {
      if (!cornerArcTowards(w, *g)) return false;
    } else {
      comp_.cornerArc();
    }
  }
  if (comp_.failure()) return compensationFailed(*comp_.failure());
  comp_.setMode(state_.plane, side, radius, direction);
  // in-plane words without in-plane displacement (nct.md §3.17.1, 000:7625-7641)
  if (on && planeWords && !arcMode && !startWord) {
    const Vec3 to = target(w, true);
    if (to[ax.first] == program_[ax.first] && to[ax.second] == program_[ax.second])
      comp_.zeroPlaneMove();
  }
  return true;
}

// G39 I J K (nct.md §3.17.5, 000:8176-8192): the arc about the corner ends on the perpendicular
// of the vector I J K, which mirror and rotation turn and scaling does not (only its direction
// counts).
bool Interpreter::cornerArcTowards(const BlockWords& w, const ir::Word& g39) {
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  if (w.ijk[ax.normal])
    return fail(diag::code::CornerArcBlock, w.ijk[ax.normal]->range,
                fmt::format("{} is outside the selected plane (nct.md §3.17.5)",
                            w.ijk[ax.normal]->address));
  Vec3 v = Vec3::Zero();
  for (int a : {ax.first, ax.second})
    if (w.ijk[a]) v[a] = w.ijk[a]->number;
  v = transforms_.matrix().linear() * v;
  const comp::Vec2 direction(v[ax.first], v[ax.second]);
  if (direction.norm() < 1e-12)
    return fail(diag::code::CornerArcBlock, g39.range, "G39 with I J K of length zero");
  if (!comp_.cornerArcTowards(direction, *sink_)) {
    if (comp_.failure()) return compensationFailed(*comp_.failure());
    return fail(diag::code::CornerArcBlock, g39.range,
                "G39 I J K ends the element before it on an arc, and there is none in the plane "
                "waiting (nct.md §3.17.5)");
  }
  return true;
}

} // namespace gcx::machine
