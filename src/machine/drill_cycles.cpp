// The interpreter's side of the drilling cycles (cycles.md §2-§3): which block drills, where
// its holes are, and how the ops of cycles/drilling.h become motion. What a cycle does
// is the cycles library's; here are only the machine's positions, transforms and events.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "cycles/drilling.h"
#include "diag/codes.h"
#include "emit/number.h"
#include "machine/cycle_state.h"
#include "machine/interpreter.h"
#include "machine/settings.h"
#include "motion/geometry.h"

namespace gcx::machine {

using motion::Kind;

namespace {

constexpr std::size_t kNoAux = std::numeric_limits<std::size_t>::max();

std::optional<cycles::DrillWord> drillWord(const ir::Word* w, double value, bool incremental) {
  if (!w) return std::nullopt;
  return cycles::DrillWord{value, incremental, w->range};
}

} // namespace

void Interpreter::cancelCycleMode() {
  state_.cycle = GAction::CycleCancel;
  state_.returnToR = false;                               // G98 again (000:9456-9459)
  setModalCode(codeOf(profile_, GAction::ReturnInitial)); // the return-level group's code
  cycles::cancel(cycles_->drill);
  levelCycle_.reset(); // and the level cycles' remembered words (fms3000.md §5.1)
  levelWords_.clear();
}

bool Interpreter::drillBlock(const BlockWords& w, bool consumedAxes) {
  // G4, G10, G92, G28... used the block's words for themselves: no hole, nothing stored (their
  // P and R are not the cycle's, 000:10334-10336)
  if (consumedAxes) return afterMotion(w);
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  const int n = ax.normal;
  // A parallel axis (W in G17, a setting) programmed in the block becomes the drilling axis
  // (000:9496-9501); otherwise the axis stays the one cycle mode drills along.
  const ir::Word* parallelWord = (parallelAxes_ >> n) & 1u ? w.extra[3 + n] : nullptr;
  const bool mainWord = w.axis[n] || w.uvw[n];
  int slot = n;
  if (parallelWord)
    slot = 3 + n;
  else if (!mainWord && cycles_->drill.cycle && cycles_->drill.axis == 3 + n)
    slot = 3 + n;
  auto slotValue = [&](int s) { return s >= 3 ? extra_[s] : program_[s]; };

  cycles::DrillWords dw;
  dw.range = blockRange_;
  for (std::size_t i = 0; i < w.gWords.size(); ++i)
    if (w.gCodes[i] && w.gCodes[i]->action == GAction::DrillCycle) {
      dw.code = static_cast<cycles::DrillCycle>(w.gCodes[i]->arg); // the profile's binding
      dw.label = "G" + emit::formatNumber(w.gWords[i]->number);
    }
  dw.axis = slot;
  dw.axisPosition = slotValue(slot);
  dw.holeWord = w.hasAxisWord();
  if (const ir::Word* z = slot >= 3 ? parallelWord : (w.axis[n] ? w.axis[n] : w.uvw[n]))
    dw.vars.z = drillWord(z, mm(z->number), state_.incremental || z->incremental || z == w.uvw[n]);
  dw.vars.r =
      drillWord(w.r, w.r ? mm(w.r->number) : 0, w.r && (state_.incremental || w.r->incremental));
  dw.vars.q = drillWord(w.q, w.q ? mm(w.q->number) : 0, false);
  dw.vars.e = drillWord(w.e, w.e ? mm(w.e->number) : 0, false);
  dw.vars.p = drillWord(w.p, w.p ? w.p->number : 0, false); // G04 units, never converted
  dw.vars.i = drillWord(w.ijk[0], w.ijk[0] ? mm(w.ijk[0]->number) : 0, false);
  dw.vars.j = drillWord(w.ijk[1], w.ijk[1] ? mm(w.ijk[1]->number) : 0, false);
  dw.vars.k = drillWord(w.ijk[2], w.ijk[2] ? mm(w.ijk[2]->number) : 0, false);
  dw.vars.overridePercent = drillWord(w.ijk[0], w.ijk[0] ? w.ijk[0]->number : 0, false);
  dw.l = drillWord(w.l, w.l ? w.l->number : 0, false);

  const std::optional<long> holes = cycles::updateModal(cycles_->drill, dw, diags_);
  if (!holes) return false;
  if (*holes == 0) return afterMotion(w); // data stored; M S T still execute (000:10348-10350)

  const cycles::DrillConfig config = drillConfig(profile_, setup_);
  // §2.7: Q and E keep their size under scaling; the I J K shift is not transformed
  const Eigen::Matrix3d m = transforms_.matrix().linear();
  Eigen::Matrix2d inPlane;
  inPlane << m(ax.first, ax.first), m(ax.first, ax.second), m(ax.second, ax.first),
      m(ax.second, ax.second);
  for (long i = 1; i <= *holes; ++i) {
    cycles::DrillRequest req;
    req.cycle = *cycles_->drill.cycle;
    req.label = cycles_->drill.label;
    req.ret = state_.returnToR ? cycles::DrillReturn::RLevel : cycles::DrillReturn::Initial;
    req.plane = state_.plane;
    req.position = program_;
    req.position[n] = slotValue(slot);
    // each repetition applies the block's increments again from the last hole (000:9647-9660)
    req.hole = target(w, true);
    req.initial = *cycles_->drill.initial;
    req.vars = cycles_->drill.vars;
    req.feed = state_.feed;
    req.spindleSpeed = state_.spindleSpeed;
    req.spindleDirection = state_.spindleDirection;
    req.radiusCompensation = state_.radiusComp != GAction::RadiusCompOff;
    req.drillScale = std::fabs(m(n, n));
    if (std::fabs(inPlane.determinant()) > 1e-12) req.shiftMap = inPlane.inverse();
    if (*holes > 1) // a frame of its own only among repetitions: no text to format for one hole
      from_.chain.push_back({blockRange_.begin, fmt::format("{} hole {}", req.label, i)});
    const auto res = cycles::expandHole(req, blockRange_, config, diags_);
    const bool ok = res && runCycleOps(res->ops, i == 1 ? res->auxAt : kNoAux, w, slot);
    if (*holes > 1) from_.chain.pop_back();
    if (!ok || stopped_) return false;
  }
  return !ended_;
}

bool Interpreter::runCycleOps(const std::vector<cycles::CycleOp>& ops, std::size_t auxAt,
                              const BlockWords& w, int drillSlot, const char* passName) {
  const int n = motion::axesOf(state_.plane).normal;
  const std::size_t depth = from_.chain.size();
  for (std::size_t k = 0; k < ops.size(); ++k) {
    if (k == auxAt && !afterMotion(w)) return false;
    const cycles::CycleOp& op = ops[k];
    if (passName && (k == 0 || op.step != ops[k - 1].step)) { // each pass a frame (provenance)
      from_.chain.resize(depth);
      from_.chain.push_back({blockRange_.begin, fmt::format("{} pass {}", passName, op.step)});
    }
    using cycles::OpKind;
    switch (op.kind) {
    case OpKind::Rapid:
    case OpKind::Feed:
    case OpKind::RigidTap:
    case OpKind::Thread: {
      Vec3 to = op.to;
      motion::Extra extraTo = extra_;
      if (drillSlot >= 3) { // the parallel axis drills: its value rides in the normal slot
        extraTo[drillSlot] = to[n];
        to[n] = program_[n];
      }
      double lead = op.kind == OpKind::Thread ? op.value : 0; // G33: the lead per revolution
      if (op.kind == OpKind::RigidTap) {
        if (op.direction != state_.spindleDirection) {
          state_.spindleDirection = op.direction;
          emitSpindle();
        }
        // the tap feed is pitch x S under G94, the pitch under G95 (000:9716-9726)
        if (!state_.perRevolution && state_.spindleSpeed <= 0)
          return fail(diag::code::MissingData, blockRange_,
                      "rigid tapping with the spindle speed S at 0");
        lead = state_.perRevolution ? op.feed : op.feed / state_.spindleSpeed;
      }
      const Kind kind = op.kind == OpKind::Rapid ? Kind::Rapid : Kind::Feed;
      emitLine(kind, toMachine(to), extraTo, op.feed, lead);
      program_ = to;
      // after its last tap the spindle stays in position control, not turning (000:9969-9971)
      if (op.kind == OpKind::RigidTap &&
          std::none_of(ops.begin() + static_cast<std::ptrdiff_t>(k) + 1, ops.end(),
                       [](const cycles::CycleOp& o) { return o.kind == OpKind::RigidTap; })) {
        state_.spindleDirection = 0;
        emitSpindle();
      }
      break;
    }
    case OpKind::ArcCW:
    case OpKind::ArcCCW:
      if (!arcTo(op.to, op.center, op.kind == OpKind::ArcCW, 1, extra_, op.feed)) return false;
      break;
    case OpKind::Dwell:
      emitDwell(op.value);
      break;
    case OpKind::SpindleCW:
    case OpKind::SpindleCCW:
    case OpKind::SpindleStop:
      state_.spindleDirection = op.kind == OpKind::SpindleCW    ? 1
                                : op.kind == OpKind::SpindleCCW ? -1
                                                                : 0;
      emitSpindle();
      break;
    case OpKind::SpindleOrient:
    case OpKind::ProgramStop: {
      motion::Event e;
      e.kind = op.kind == OpKind::SpindleOrient ? Kind::SpindleOrient : Kind::Stop;
      e.start = e.end = machine_;
      e.extraStart = e.extraEnd = extra_;
      emit(std::move(e));
      break;
    }
    case OpKind::CloseLoop: // the position-loop M code changes no path
      break;
    case OpKind::OverrideLock: // G63 for #4015 until the code before it returns (§1.2)
    case OpKind::OverrideRestore: {
      const bool lock = op.kind == OpKind::OverrideLock;
      const GCodeSpec* tapping = codeOf(profile_, GAction::TappingMode);
      const int group = tapping ? tapping->group : 0;
      if (lock) lockedFrom_ = modalCode(group);
      const GCodeSpec* continuous = codeOf(profile_, GAction::ContinuousMode);
      setModalCode(group, lock          ? (tapping ? tapping->code10 : 0)
                          : lockedFrom_ ? lockedFrom_
                                        : (continuous ? continuous->code10 : 0));
      motion::Event e;
      e.kind = Kind::OverrideLock;
      e.start = e.end = machine_;
      e.extraStart = e.extraEnd = extra_;
      e.value = lock ? 1 : 0;
      emit(std::move(e));
      break;
    }
    }
  }
  if (passName) from_.chain.resize(depth);
  if (auxAt != kNoAux && auxAt >= ops.size()) return afterMotion(w);
  return true;
}

} // namespace gcx::machine
