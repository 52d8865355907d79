#include "machine/interpreter.h"
#include "machine/cycle_state.h"
#include "machine/helix.h"
#include "machine/reused_block_words.h"

#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"
#include "emit/number.h"
#include "machine/code_names.h"
#include "machine/settings.h"
#include "motion/geometry.h"
#include "motion/interpolator.h"
#include "motion/plane_similarity.h"

namespace gcx::machine {

using motion::Kind;
using motion::Plane;

namespace {

// to = from, without the vector assignment's work when both chains are empty (a streamed
// program's every block and event)
void setProvenance(motion::Provenance& to, const motion::Provenance& from) {
  to.at = from.at;
  if (!to.chain.empty() || !from.chain.empty()) to.chain = from.chain;
}

/// The i-th of consecutive settings (X Y Z, or U V W).
Setting nth(Setting first, int i) {
  return static_cast<Setting>(static_cast<int>(first) + i);
}

} // namespace

Interpreter::Interpreter(const Profile& profile, const Setup& setup, motion::Sink& sink,
                         diag::Engine& diags)
    : profile_(profile), setup_(setup), sink_(&sink), diags_(diags) {
  cacheSettings();
  const auto& p = setup_.initialPosition;
  machine_ = Vec3(p[0], p[1], p[2]);
  const auto c = setup_.workOffset("common");
  offsets_.common = Vec3(c[0], c[1], c[2]);
  for (int i = 0; i < 3; ++i)
    if (setting(profile_, setup_, nth(Setting::ParallelAxisU, i)) == 1) parallelAxes_ |= 1u << i;
  rollover_.enabled = setting(profile_, setup_, Setting::RolloverOn) == 1;
  rollover_.absoluteBySign = setting(profile_, setup_, Setting::RolloverBySign) == 1;
  rollover_.shortest = setting(profile_, setup_, Setting::RolloverShortest) == 1;
  rollover_.amount = setting(profile_, setup_, Setting::RolloverAmount, 360);
  resetModal();
  reexpress();
  comp_ = CompensationStage(compensationOptions());
}

void Interpreter::cacheSettings() {
  radiusTolerance_ = setting(profile_, setup_, Setting::ArcRadiusTolerance, 0.01);
  arcCentreMode_ = setting(profile_, setup_, Setting::ArcCentreAbsolute);
}

bool Interpreter::fail(const char* code, const SourceRange& where, std::string message) {
  diag::Diagnostic d{diag::Severity::Error, code, std::move(message), where, {}};
  for (auto it = from_.chain.rbegin(); it != from_.chain.rend(); ++it)
    d.notes.push_back({SourceRange{it->call, 1}, "in " + it->what});
  diags_.report(std::move(d));
  return false;
}

void Interpreter::resetModal() {
  const int tool = state_.tool, selected = state_.selectedTool;
  const double speed = state_.spindleSpeed, feed = state_.feed;
  const int direction = state_.spindleDirection;
  state_ = ModalState{};
  cycles::cancel(cycles_->drill);
  state_.tool = tool, state_.selectedTool = selected;
  state_.spindleSpeed = speed, state_.spindleDirection = direction, state_.feed = feed;
  modalCodes_.fill(0);
  for (int code : profile_.powerOnGCodes10)
    for (const GCodeSpec& g : profile_.gcodes)
      if (g.code10 == code) {
        setModal(g);
        if (g.group > 0 && g.group < static_cast<int>(modalCodes_.size()))
          modalCodes_[g.group] = g.code10;
      }
  for (int a = 0; a < 3; ++a)
    if (setting(profile_, setup_, nth(Setting::DiameterX, a)) == 1) state_.diameterAxes |= 1u << a;
  offsets_.g92 = offsets_.g52 = Vec3::Zero();
  offsets_.length = 0;
  offsets_.turning = Vec3::Zero();
  transforms_.clear();
}

int Interpreter::modalCode(int group) const {
  return group > 0 && group < static_cast<int>(modalCodes_.size()) ? modalCodes_[group] : 0;
}

void Interpreter::setWorkOffset(const std::string& key, const Vec3& value) {
  setup_.workOffsets[key] = {value.x(), value.y(), value.z()};
  if (key == "common") offsets_.common = value;
  reexpress();
}

void Interpreter::setToolLength(int reg, double length) {
  setup_.tools[reg].length = length;
}
void Interpreter::setToolRadius(int reg, double radius) {
  setup_.tools[reg].radius = radius;
}

double Interpreter::toolWear(int reg, bool radius) const {
  const auto& wear = radius ? radiusWear_ : wear_;
  auto it = wear.find(reg);
  return it == wear.end() ? 0.0 : it->second;
}

void Interpreter::setToolWear(int reg, bool radius, double wear) {
  ToolData& t = setup_.tools[reg];
  (radius ? t.radius : t.length) += wear - toolWear(reg, radius);
  (radius ? radiusWear_ : wear_)[reg] = wear;
}

double Interpreter::workRotation(const std::string& key, int plane) const {
  auto it = rotations_.find(key);
  return it == rotations_.end() || plane < 1 || plane > 3 ? 0.0 : it->second[plane - 1];
}

void Interpreter::setWorkRotation(const std::string& key, int plane, double degrees) {
  if (plane >= 1 && plane <= 3) rotations_[key][plane - 1] = degrees;
}

std::string Interpreter::workOffsetKey(int offset) const {
  const MachineRules& r = profile_.machine;
  if (offset > 100) return r.extendedWorkOffsetPrefix + std::to_string(offset - 100);
  const auto i = static_cast<std::size_t>(offset - 1);
  return i < r.workOffsetNames.size() ? r.workOffsetNames[i] : std::string();
}

Vec3 Interpreter::currentWorkOffset() const {
  if (setup_.workOffsets.empty()) return Vec3::Zero(); // asked per move: no key to build
  const auto o = setup_.workOffset(workOffsetKey(state_.workOffset));
  return Vec3(o[0], o[1], o[2]);
}

Vec3 Interpreter::workOrigin() const {
  return offsets_.common + currentWorkOffset() + offsets_.g92 + offsets_.g52 + lengthVector() +
         offsets_.turning;
}

Vec3 Interpreter::lengthVector() const {
  Vec3 v = Vec3::Zero();
  v[profile_.machine.lengthAlongPlaneNormal ? motion::axesOf(state_.plane).normal : 2] =
      offsets_.length;
  return v;
}

bool Interpreter::skips(int level) const {
  if (!level) return false;
  const bool on = setup_.blockSkip.count(level) != 0;
  return profile_.machine.skipSense == SkipSense::SkipWhenOn ? on : !on; // nct.md §1.6
}

Vec3 Interpreter::toMachine(const Vec3& program) const {
  return workOrigin() + transforms_.apply(program);
}

void Interpreter::reexpress() {
  program_ = transforms_.applyInverse(machine_ - workOrigin());
}

void Interpreter::emit(motion::Event&& e) {
  if (stopped_) return;
  setProvenance(e.from, from_);
  if ((e.kind == Kind::Rapid || e.kind == Kind::Feed || e.kind == Kind::Arc) && !admitMotion(e)) {
    stopped_ = true;
    return;
  }
  // a dwell time, speed, tool or code of 1e9 or more is no value any output writes in full
  if (!(std::fabs(e.value) < 1e9)) {
    fail(diag::code::ValueOutOfRange, blockRange_,
         fmt::format("the block's value {:g} (dwell time, speed, tool or code) is out of range: "
                     "1e9 or more",
                     e.value));
    stopped_ = true;
    return;
  }
  if (e.kind == Kind::Rapid || e.kind == Kind::Feed || e.kind == Kind::Arc) rememberPlaneMove(e);
  if (probing_ && motion::isMotion(e)) probePath_.push_back(e); // G38 runs back along it
  // chamfers and roundings, then radius compensation, then the sink
  struct ToCompensation : motion::Sink {
    CompensationStage& comp;
    motion::Sink& out;
    bool ok = true;
    ToCompensation(CompensationStage& c, motion::Sink& o) : comp(c), out(o) {}
    void event(const motion::Event& x) override { ok = comp.event(x, out) && ok; }
  } toCompensation(comp_, *sink_);
  if (!corners_.event(e, toCompensation) || !toCompensation.ok) {
    compensationFailed(corners_.failure() ? *corners_.failure() : *comp_.failure());
    stopped_ = true;
    return;
  }
  if (stopCheck_)
    if (auto why = stopCheck_()) {
      fail(diag::code::OutputTooLarge, blockRange_, std::move(*why));
      stopped_ = true;
    }
}

bool Interpreter::admitMotion(const motion::Event& e) {
  // beyond a kilometre-scale machine by far, and below what any output writes in full
  constexpr double kMaxCoordinate = 1e9;
  const auto writable = [&](double v) { return std::fabs(v) < kMaxCoordinate; };
  // the usual move at a glance: every value writable (a NaN fails each comparison), no branch:
  // the tests combined as integers, where `&&` would branch on each
  const auto bit = [&](double v) { return static_cast<unsigned>(writable(v)); };
  const bool usual = (bit(e.end.x()) & bit(e.end.y()) & bit(e.end.z()) & bit(e.center.x()) &
                      bit(e.center.y()) & bit(e.center.z()) & bit(e.feed)) != 0 &&
                     (e.extraEnd.array().abs() < kMaxCoordinate).all() && e.start.allFinite();
  const bool finite = usual || (e.start.allFinite() && e.end.allFinite() && e.center.allFinite() &&
                                e.extraEnd.allFinite() && std::isfinite(e.feed));
  if (!usual && (!finite || !writable(e.end.x()) || !writable(e.end.y()) || !writable(e.end.z()) ||
                 !writable(e.center.x()) || !writable(e.center.y()) || !writable(e.center.z()) ||
                 e.extraEnd.cwiseAbs().maxCoeff() >= kMaxCoordinate || !writable(e.feed)))
    return fail(diag::code::ValueOutOfRange, blockRange_,
                finite ? fmt::format("the move reaches a coordinate or feed of magnitude 1e9 or "
                                     "more (machine frame, mm)")
                       : "the move's position or feed is not a finite number");
  if (e.kind != Kind::Rapid && e.perRevolution && e.lead == 0 && speedProgrammed_ &&
      state_.spindleSpeed == 0)
    return fail(diag::code::FeedPerRevolutionAtS0, blockRange_,
                "feed per revolution (G95) with the spindle speed S0: the move would never end");
  if (e.kind != Kind::Rapid && e.feed > 0 && e.feed < 1e-6)
    return fail(diag::code::ValueOutOfRange, blockRange_,
                fmt::format("feed {:g} is too small to write (below 0.000001)", e.feed));
  // an arc counts its turns; a spiral the lines canonical output writes for it
  std::uint64_t count = 1;
  if (e.kind == Kind::Arc)
    count = std::fabs(e.startRadius - e.endRadius) > 1e-9
                ? static_cast<std::uint64_t>(std::min(
                      motion::arcChordCount(motion::ArcGeometry(e), motion::kDefaultChordTolerance),
                      1e18))
                : 1 + static_cast<std::uint64_t>(std::max(0, e.turns));
  // A block's first move is the program's own; what a block adds beyond it (cycle holes and
  // passes, arc turns, repeats) is amplification, and that is what the limit bounds. A plain
  // program of any length therefore runs; its size bounds its moves.
  moves_ += count - (blockMoves_ == 0 ? 1 : 0);
  blockMoves_ += count;
  if (moves_ > maxMoves_)
    return fail(diag::code::TooManyMoves, blockRange_,
                fmt::format("more than {} moves beyond one a block (cycles, repeats, arc turns): "
                            "exceeded --max-moves {}; raise it with --max-moves N",
                            maxMoves_, maxMoves_));
  return true;
}

void Interpreter::emitLine(Kind kind, const Vec3& to, const motion::Extra& extraTo, double feed,
                           double lead) {
  if (to == machine_ && extraTo == extra_) return; // a zero-length block moves nothing (TV13)
  motion::Event e;
  e.kind = kind;
  e.start = machine_;
  e.end = to;
  e.extraStart = extra_;
  e.extraEnd = extraTo;
  extra_ = extraTo;
  e.feed = lead > 0 ? lead : feed; // a synchronised move feeds its lead per revolution
  e.lead = lead;
  e.perRevolution = lead > 0 || state_.perRevolution;
  machine_ = to;
  emit(std::move(e));
}

bool Interpreter::execute(const ir::Block& block, const motion::Provenance& from) {
  if (ended_ || stopped_) return false;
  if (blockObserver_) blockObserver_(from);
  setProvenance(from_, from);
  blockRange_ = block.range;
  blockMoves_ = 0;
  ++blockSerial_;
  if (pendingProfile_) return profileBlock(block, from) && !stopped_;
  return executeBlock(block) && !stopped_;
}

bool Interpreter::executeBlock(const ir::Block& block) {
  if (block.kind == ir::BlockKind::ProgramStart) return true;
  if (skips(block.skipLevel)) return true;
  if (block.kind == ir::BlockKind::Data) return dataInput(BlockWords{}, block);
  if (!block.stmts.empty())
    return fail(diag::code::NotImplemented, block.stmts.front().range,
                "macro statements need the macro expansion pass, which is not implemented yet");
  if (profile_.defines(GAction::LevelDrillCycle)) // FMS-3000 G81-G88: the words after the code
    for (const ir::Word& g : block.words)         // are its own
      if (g.is('G'))
        if (const GCodeSpec* spec = profile_.gcode(g.number);
            spec && spec->action == GAction::LevelDrillCycle)
          return levelCycleBlock(block, g, *spec);
  if (const auto repeated = levelCycleRepeat(block)) return *repeated;
  if (const auto polar = polePolarBlock(block)) return *polar;
  ReusedBlockWords reused;
  BlockWords& w = reused.words();
  if (const ir::Word* bad = sortWords(block, profile_, w))
    return fail(diag::code::ExpressionNotExpanded, bad->range,
                fmt::format("the value of {} is an expression; expressions are evaluated by the "
                            "macro pass, which is not implemented yet",
                            bad->address));
  if (const ContourWords& c = profile_.machine.contour;
      c.chamferAxis >= 'A' && c.chamferAxis <= 'C' && parameter(c.chamferAxisKey, 0) == 1)
    if (const ir::Word*& axis = w.extra[c.chamferAxis - 'A']) // the chamfer leg, not an axis
      w.chamfer = std::exchange(axis, nullptr);
  const char* limitAddress = profile_.machine.spindleLimitAddress;
  for (const ir::Word* o : w.other)
    if (limitAddress && o->address == limitAddress)
      state_.maxSpindleSpeed = o->number; // the ceiling of the constant surface speed's rpm
    else if (!o->is('N') && !o->is('O'))
      return fail(diag::code::NotImplemented, o->range,
                  fmt::format("address {} is not implemented yet", o->address));
  for (int i = 0; i < 3; ++i)
    if ((parallelAxes_ & (1u << i)) && w.uvw[i]) { // U V W are axes, not incremental aliases
      w.extra[3 + i] = w.uvw[i];
      w.uvw[i] = nullptr;
    }
  if (block.sequence) state_.lastN = *block.sequence;
  if (w.d) state_.lastD = static_cast<int>(w.d->number);
  if (w.e) state_.lastE = w.e->number;
  if (w.h) state_.lastH = static_cast<int>(w.h->number);
  if (w.s) state_.lastS = w.s->number;
  if (w.s) speedProgrammed_ = true;
  if (!w.m.empty()) state_.lastM = static_cast<int>(w.m.back()->number);
  for (const ir::Word* o : w.other)
    if (o->is('O')) state_.lastO = static_cast<int>(o->number);
  const ModalState before = state_;
  pendingTurning_ = pendingContour_ = nullptr;
  if (!applyModal(w)) return false;
  if (pendingContour_ && !contourCycleSide(w, before)) return false;
  if (!threadSequenceEnd(w, false) || !surfaceSpeedSwitch(w, before)) return false;
  if (profile_.machine.surfaceSpeedHoldsCurrent && state_.surfaceSpeed && !before.surfaceSpeed &&
      !w.s) // the surface speed the spindle has now at the tool's radius
    state_.surfaceSpeedValue = state_.spindleSpeed * 2 * M_PI *
                               std::fabs(program_[profile_.machine.surfaceSpeedAxis]) / 1000.0;
  if (!radiusCompensation(w, before)) return false;
  if (!rotations_.empty() && w.hasAxisWord() && !w.has(GAction::DataInput)) { // none: no key
    const std::string key = workOffsetKey(state_.workOffset);
    for (int plane = 1; plane <= 3; ++plane)
      if (workRotation(key, plane) != 0)
        return fail(diag::code::NotImplemented, blockRange_,
                    fmt::format("moving in {} with a basic rotation (G10 L2 I J K) is not "
                                "implemented yet",
                                key));
  }
  selectPlaneAxes(w);
  emitModalChanges(before);
  bool consumed = false;
  if (!applyNonMotion(w, consumed)) return false;
  if (!beforeMotion(w)) return false;
  if (state_.cycle == GAction::DrillCycle && !deferCycles_) return drillBlock(w, consumed);
  if (pendingTurning_) return turningBlock(w);
  if (pendingContour_) return contourCycleBlock(w, before);
  const bool arcWithCentreOnly =
      (state_.motion == GAction::ArcCW || state_.motion == GAction::ArcCCW) &&
      (w.ijk[0] || w.ijk[1] || w.ijk[2] || (w.r && profile_.machine.strictArcRadius));
  if (const ir::Word* skip = w.findAction(GAction::SkipMove); skip && !skipWithoutTouch(*skip))
    return false;
  const ir::Word* probe = w.findAction(GAction::ProbeReturn);
  const Vec3 probeFrom = program_;
  if (probe) {
    probing_ = true;
    probePath_.clear();
  }
  const ir::Word* thread = w.findAction(GAction::ThreadOnce);
  const GAction motionMode = state_.motion;
  if (thread && !threadOnce(*thread)) return false;
  if (!consumed && (w.hasAxisWord() || arcWithCentreOnly || w.angle)) // ,A alone: a direction
    if (!move(w)) return false;
  if (thread) { // one block only: the modal motion and no thread sequence go on
    state_.motion = motionMode;
    threadLead_.reset();
  }
  if (probe && !probeBack(*probe, probeFrom)) return false;
  if (pendingDwell_) {
    emitDwell(*pendingDwell_);
    pendingDwell_.reset();
  }
  return afterMotion(w);
}

bool Interpreter::surfaceSpeedSwitch(const BlockWords& w, const ModalState& before) {
  if (!profile_.machine.surfaceSpeedSwitchNeedsS || w.s ||
      state_.surfaceSpeed == before.surfaceSpeed)
    return true;
  const GAction now = state_.surfaceSpeed ? GAction::SurfaceSpeedOn : GAction::SurfaceSpeedOff;
  const ir::Word* code = w.findAction(now);
  return fail(diag::code::SurfaceSpeedSwitchWithoutS, code ? code->range : blockRange_,
              fmt::format("{} switches the meaning of S ({} to {}) without a new S in the same "
                          "block, which the manual does not allow (wl4.md §2.4)",
                          code ? gName(*code) : codeName(profile_, now),
                          codeName(profile_, state_.surfaceSpeed ? GAction::SurfaceSpeedOff
                                                                 : GAction::SurfaceSpeedOn),
                          codeName(profile_, now)));
}

bool Interpreter::setModal(const GCodeSpec& g) {
  switch (g.action) {
  case GAction::Rapid:
  case GAction::Linear:
  case GAction::ArcCW:
  case GAction::ArcCCW:
  case GAction::FilletCW:
  case GAction::FilletCCW:
  case GAction::ThreadMotion:
  case GAction::ThreadReciprocating:
    if (g.action != GAction::ThreadMotion && g.action != GAction::ThreadReciprocating)
      threadLead_.reset(); // a thread sequence ends with the next G0-G3 (wl4.md §3.6)
    state_.motion = g.action;
    if (state_.cycle == GAction::DrillCycle && profile_.machine.motionCancelsCycle)
      cancelCycleMode();
    return true;
  case GAction::PlaneXY:
    state_.plane = Plane::XY;
    return true;
  case GAction::PlaneZX:
    state_.plane = Plane::ZX;
    return true;
  case GAction::PlaneYZ:
    state_.plane = Plane::YZ;
    return true;
  case GAction::Inch:
    state_.inch = true;
    return true;
  case GAction::Metric:
    state_.inch = false;
    return true;
  case GAction::Absolute:
    state_.incremental = false;
    return true;
  case GAction::Incremental:
    state_.incremental = true;
    return true;
  case GAction::FeedPerMinute:
    state_.perRevolution = false;
    return true;
  case GAction::FeedPerRevolution:
    state_.perRevolution = true;
    return true;
  case GAction::PolarOn:
    state_.polar = true;
    return true;
  case GAction::PolarOff:
    state_.polar = false;
    return true;
  case GAction::ExactStopMode:
  case GAction::CornerOverride:
  case GAction::TappingMode:
  case GAction::ContinuousMode:
    state_.feedControl = g.action;
    return true;
  case GAction::CycleCancel:
    cancelCycleMode();
    return true;
  case GAction::RadiusCompOff:
    state_.radiusComp = g.action;
    return true;
  case GAction::WorkOffset:
    state_.workOffset = g.arg;
    return true;
  case GAction::ReturnInitial:
  case GAction::ReturnR:
    state_.returnToR = g.action == GAction::ReturnR;
    return true;
  case GAction::SurfaceSpeedOff:
    state_.surfaceSpeed = false;
    return true;
  case GAction::SurfaceSpeedOn:
    state_.surfaceSpeed = true;
    return true;
  case GAction::StrokeLimitOff:
  case GAction::ModalMacroCancel:
  case GAction::Modeless:
  case GAction::ExactStopOnce:
    return true;
  default:
    return false;
  }
}

bool Interpreter::applyModal(const BlockWords& w) {
  for (std::size_t i = 0; i < w.gWords.size(); ++i) {
    const ir::Word& word = *w.gWords[i];
    const GCodeSpec* g = w.gCodes[i];
    if (!g)
      return fail(diag::code::UnknownGCodeAtRun, word.range,
                  fmt::format("{} is not a G code of the {} dialect and is not configured as a "
                              "macro call",
                              gName(word), profile_.name));
    if (g->group > 0 && g->group < static_cast<int>(modalCodes_.size()))
      modalCodes_[g->group] = g->code10;
    if (setModal(*g)) {
      if (g->action == GAction::WorkOffset) {
        if (profile_.machine.workOffsetEndsSetCoordinates) offsets_.g92 = Vec3::Zero();
        reexpress();
      }
      continue;
    }
    switch (g->action) {

    case GAction::ExtendedWorkOffset: {
      const int n = profile_.machine.extendedWorkOffsets;
      if (!w.p || w.p->number < 1 || w.p->number > n || w.p->number != std::floor(w.p->number))
        return fail(diag::code::MissingData, word.range,
                    fmt::format("G{:g} needs P1 to P{}", word.number, n));
      state_.workOffset = 100 + static_cast<int>(w.p->number);
      reexpress();
      break;
    }
    case GAction::LengthPlus:
    case GAction::LengthMinus:
    case GAction::LengthCancel:
    case GAction::TurningOffsets:
    case GAction::RotateOn:
    case GAction::RotateOff:
    case GAction::ScaleOn:
    case GAction::ScaleOff:
    case GAction::MirrorOn:
    case GAction::MirrorOff:
    case GAction::MirrorBySign:
    case GAction::Dwell:
    case GAction::DataInput:
    case GAction::DataInputEnd:
    case GAction::SetCoordinates:
    case GAction::LocalCoordinates:
    case GAction::MachineCoordinates:
    case GAction::ReferenceReturn:
    case GAction::OtherReferenceReturn:
    case GAction::DiameterMode:
    case GAction::HelicalQualifier:    // arc()
    case GAction::OneSidedPositioning: // move()
    case GAction::ImplicitPlus:
    case GAction::ImplicitMinus:
    case GAction::ProbeReturn: // probeBack() after the move
    case GAction::SkipMove:    // skipWithoutTouch() before the move
    case GAction::ThreadOnce:  // threadOnce() around the move
      break;                   // applyNonMotion
    case GAction::RadiusCompLeft:
    case GAction::RadiusCompRight:
      state_.radiusComp = g->action; // radiusCompensation() starts the stage
      break;
    case GAction::CornerArc:
    case GAction::VectorHold:
      break; // radiusCompensation()
    case GAction::DrillCycle:
      state_.cycle = g->action; // drillBlock() stores the block's data and drills
      break;
    case GAction::ContourCycle:
      if (!deferCycles_) pendingContour_ = g; // contourCycleBlock() runs it
      break;
    case GAction::TurningCycle:
      if (deferCycles_) break;
      if (g->group == 0) { // one-shot: turningBlock() runs it
        pendingTurning_ = g;
        break;
      }
      // G77.7-G79.7 hold group 1: every block with axis words repeats the cycle (§4.1)
      state_.motion = GAction::TurningCycle;
      turningMode_ = g;
      turningEnd_.reset();
      turningTaper_.reset();
      if (state_.cycle == GAction::DrillCycle && profile_.machine.motionCancelsCycle)
        cancelCycleMode();
      break;
    default:
      return fail(diag::code::NotImplemented, word.range,
                  fmt::format("{} ({}) is not implemented yet", gName(word), g->meaning));
    }
  }
  if (w.f) state_.feed = mm(w.f->number);
  // length compensation: a coordinate transformation, never a move of its own (nct.md §3.16)
  const ir::Word* lengthCode = nullptr;
  for (GAction a :
       {GAction::LengthPlus, GAction::LengthMinus, GAction::LengthCancel, GAction::TurningOffsets})
    if (const ir::Word* x = w.findAction(a)) lengthCode = x;
  if (lengthCode || (w.h && (state_.lengthSign != 0 || state_.turningOffsets))) {
    if (lengthCode) { // G43.7 applies the turning offsets; G43 G44 G49 return to length (§3.16)
      const GAction a = profile_.gcode(lengthCode->number)->action;
      state_.lengthSign = a == GAction::LengthPlus ? 1 : a == GAction::LengthMinus ? -1 : 0;
      state_.turningOffsets = a == GAction::TurningOffsets;
    }
    if (w.h) state_.lengthRegister = static_cast<int>(w.h->number);
    auto it = setup_.tools.find(state_.lengthRegister);
    const ToolData tool = it == setup_.tools.end() ? ToolData{} : it->second;
    offsets_.length = state_.lengthSign * tool.length;
    offsets_.turning = state_.turningOffsets
                           ? Vec3(tool.turning[0], tool.turning[1], tool.turning[2])
                           : Vec3::Zero();
    reexpress();
  }
  return transforms(w);
}

bool Interpreter::transforms(const BlockWords& w) {
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  auto centre = [&](bool allAxes) {
    Vec3 c = program_;
    for (int a = 0; a < 3; ++a) {
      if (!allAxes && a != ax.first && a != ax.second) continue;
      if (const ir::Word* x = w.axis[a]) {
        const double v = mm(x->number);
        c[a] = (state_.incremental || x->incremental) ? program_[a] + v : v;
      }
    }
    return c;
  };
  // the state without scaling and rotation, named by the codes that end them ("G50 G69")
  auto plainState = [&] {
    std::string codes = codeName(profile_, GAction::ScaleOff);
    const std::string rotateOff = codeName(profile_, GAction::RotateOff);
    return codes.empty() ? rotateOff : rotateOff.empty() ? codes : codes + " " + rotateOff;
  };
  const TransformRules& rules = profile_.machine.transformRules;
  const bool mirrorRefused =
      rules.mirrorOnlyWithoutRotationOrScaling && (transforms_.rotating() || transforms_.scaling());
  if (const ir::Word* g = w.findAction(GAction::MirrorOn)) {
    if (mirrorRefused)
      return fail(
          diag::code::MirrorWithTransform, g->range,
          fmt::format("mirror may only be switched on in {} state ({})", plainState(), rules.spec));
    unsigned mask = 0;
    for (int a = 0; a < 3; ++a)
      if (w.axis[a]) mask |= 1u << a;
    transforms_.mirror(mask, centre(true));
  }
  if (w.has(GAction::MirrorBySign) && !mirrorBySign(w)) return false;
  if (const ir::Word* g = w.findAction(GAction::MirrorOff)) {
    if (mirrorRefused)
      return fail(diag::code::MirrorWithTransform, g->range,
                  fmt::format("mirror may only be switched off in {} state ({})", plainState(),
                              rules.spec));
    unsigned mask = 0;
    for (int a = 0; a < 3; ++a)
      if (w.axis[a]) mask |= 1u << a;
    transforms_.cancelMirror(mask ? mask : 7u);
  }
  if (const ir::Word* g = w.findAction(GAction::RotateOff)) {
    if (rules.switchOffsMustNest && transforms_.rotating() &&
        transforms_.innermost() != Transforms::Kind::Rotate)
      return fail(diag::code::TransformNesting, g->range,
                  fmt::format("{} while {} switched on after {} is still active: switch-offs "
                              "must nest ({})",
                              gName(*g), codeName(profile_, GAction::ScaleOn),
                              codeName(profile_, GAction::RotateOn), rules.spec));
    transforms_.cancel(Transforms::Kind::Rotate);
  }
  if (const ir::Word* g = w.findAction(GAction::ScaleOff)) {
    if (rules.switchOffsMustNest && transforms_.scaling() &&
        transforms_.innermost() != Transforms::Kind::Scale)
      return fail(diag::code::TransformNesting, g->range,
                  fmt::format("{} while {} switched on after {} is still active: switch-offs "
                              "must nest ({})",
                              gName(*g), codeName(profile_, GAction::RotateOn),
                              codeName(profile_, GAction::ScaleOn), rules.spec));
    transforms_.cancel(Transforms::Kind::Scale);
  }
  const TransformWords& words = profile_.machine.transform;
  if (const ir::Word* g = w.findAction(GAction::ScaleOn)) {
    Vec3 factors(1, 1, 1);
    std::array<const ir::Word*, 3> axisFactor{};
    for (int a = 0; a < 3 && a < static_cast<int>(words.axisScale.size()); ++a)
      axisFactor[a] = w.letter(words.axisScale[a]);
    if (const ir::Word* u = words.uniformScale ? w.letter(words.uniformScale) : nullptr) {
      factors = Vec3::Constant(u->number);
    } else {
      for (int a = 0; a < 3; ++a)
        if (axisFactor[a]) factors[a] = axisFactor[a]->number;
      if (!axisFactor[0] && !axisFactor[1] && !axisFactor[2])
        diags_.warning(diag::code::MissingData, g->range, words.scaleWithoutFactor);
    }
    // factors given by the axis words leave no words for a centre: the work system's origin
    const bool axisWordsAreFactors = words.axisScale == "XYZ";
    transforms_.scale(axisWordsAreFactors ? Vec3::Zero() : centre(true), factors);
  }
  if (const ir::Word* g = w.findAction(GAction::RotateOn)) {
    double angle = 0;
    if (const ir::Word* a = w.letter(words.rotationAngle)) {
      angle = a->number;
      if (state_.incremental || a->incremental) angle += transforms_.rotationDegrees();
    } else {
      diags_.warning(diag::code::MissingData, g->range, words.rotationWithoutAngle);
    }
    transforms_.rotate(state_.plane, centre(false), angle);
  }
  return true;
}

bool Interpreter::applyNonMotion(const BlockWords& w, bool& consumed) {
  consumed = w.has(GAction::RotateOn) || w.has(GAction::ScaleOn) || w.has(GAction::MirrorOn) ||
             w.has(GAction::MirrorOff) || w.has(GAction::MirrorBySign);
  if (const ir::Word* g = w.findAction(GAction::Dwell)) {
    const DwellRule& dwell = profile_.machine.dwell;
    if (const ir::Word* x = dwell.rejectedWord ? w.letter(dwell.rejectedWord) : nullptr)
      return fail(diag::code::DwellWithoutP, x->range, dwell.rejectedMessage);
    const ir::Word* time = w.letter(dwell.word);
    if (!time && dwell.alternateWord) time = w.letter(dwell.alternateWord);
    if (!time) return fail(diag::code::MissingData, g->range, dwell.missingMessage);
    if (profile_.machine.dwellAfterMotion) {
      pendingDwell_ = time->number * dwell.secondsPerUnit; // executeBlock, after the motion
    } else {
      consumed = true;
      emitDwell(time->number * dwell.secondsPerUnit);
    }
  }
  if (w.has(GAction::DataInput)) {
    consumed = true;
    return dataInput(w, ir::Block{});
  }
  if (w.has(GAction::DataInputEnd)) dataMode_ = false;
  // X1: X in diameter, X0: in radius (nct.md §3.8)
  if (const ir::Word* g = w.findAction(GAction::DiameterMode)) {
    consumed = true;
    for (int a = 0; a < 3; ++a)
      if (w.axis[a]) {
        if (w.axis[a]->number == 1)
          state_.diameterAxes |= 1u << a;
        else if (w.axis[a]->number == 0)
          state_.diameterAxes &= ~(1u << a);
        else
          return fail(diag::code::DataOutOfRange, w.axis[a]->range,
                      fmt::format("{} takes 1 (diameter) or 0 (radius) per axis", gName(*g)));
      }
    return true;
  }
  if (const ir::Word* g = w.findAction(GAction::SetCoordinates)) {
    consumed = true;
    const double mode = setting(profile_, setup_, Setting::SetCoordinatesMode);
    if (mode != 0 && mode != 1 && mode != 2)
      return fail(diag::code::DataOutOfRange, g->range,
                  fmt::format("{} = {} gives {} no meaning (0, 1 or 2)",
                              settingLabel(profile_, Setting::SetCoordinatesMode),
                              emit::formatNumber(mode), gName(*g)));
    if (w.s && profile_.machine.setCoordinatesSIsSpindleLimit) { // nct.md §3.18
      if (w.hasAxisWord())
        return fail(diag::code::ForbiddenAddress, w.s->range,
                    fmt::format("{0} S (spindle limit) and {0} coordinates in one block (nct.md "
                                "Q28)",
                                gName(*g)));
      state_.maxSpindleSpeed = w.s->number;
      return true;
    }
    return mode == 0 ? setCoordinates(w) : setCoordinateOrigin(w, mode == 2);
  }
  if (w.has(GAction::LocalCoordinates)) {
    consumed = true;
    return localCoordinates(w);
  }
  if (w.has(GAction::MachineCoordinates)) {
    consumed = true;
    return machineMove(w);
  }
  if (const ir::Word* g = w.findAction(GAction::ReferenceReturn)) {
    consumed = true;
    if (profile_.machine.directReferencePointKey)
      return directReferenceReturn(w, profile_.gcode(g->number)->arg);
    return referenceReturn(w, 1);
  }
  if (const ir::Word* g = w.findAction(GAction::OtherReferenceReturn)) {
    consumed = true;
    const int points = profile_.machine.referencePoints;
    if (!w.p || w.p->number < 1 || w.p->number > points || w.p->number != std::floor(w.p->number))
      return fail(diag::code::MissingData, g->range,
                  fmt::format("{} needs P1 to P{} to name the reference point (nct.md Q15)",
                              gName(*g), points));
    return referenceReturn(w, static_cast<int>(w.p->number));
  }
  return true;
}

bool Interpreter::setCoordinates(const BlockWords& w) {
  // the current tool tip gets the coordinates v in every work system (nct.md §3.14)
  const Vec3 local =
      machine_ - offsets_.common - currentWorkOffset() - lengthVector() - offsets_.turning;
  for (int a = 0; a < 3; ++a) {
    if (w.uvw[a])
      return fail(diag::code::IllegalIncremental, w.uvw[a]->range,
                  "G92 takes absolute coordinates only");
    if (!w.axis[a]) continue;
    offsets_.g52[a] = 0; // G92 cancels G52 on the axes it names
    offsets_.g92[a] = local[a] - mm(w.axis[a]->number);
  }
  reexpress();
  return true;
}

bool Interpreter::localCoordinates(const BlockWords& w) {
  for (int a = 0; a < 3; ++a) {
    const ir::Word* x = w.axis[a] ? w.axis[a] : w.uvw[a];
    if (!x) continue;
    const double v = mm(x->number);
    const bool inc = state_.incremental || x->incremental || x == w.uvw[a];
    offsets_.g52[a] = inc ? offsets_.g52[a] + v : v;
  }
  reexpress();
  return true;
}

bool Interpreter::machineMove(const BlockWords& w) {
  Vec3 to = machine_;
  for (int a = 0; a < 3; ++a) {
    if (w.uvw[a] || (w.axis[a] && w.axis[a]->incremental))
      return fail(diag::code::IllegalIncremental, (w.uvw[a] ? w.uvw[a] : w.axis[a])->range,
                  "illegal incremental movement: G53 takes machine coordinates (nct.md §3.13)");
    if (w.axis[a]) to[a] = mm(w.axis[a]->number);
  }
  if (to != machine_) emitLine(Kind::Rapid, to);
  reexpress();
  return true;
}

bool Interpreter::referenceReturn(const BlockWords& w, int point) {
  if (!w.hasAxisWord()) return true;
  // phase 1: rapid to the intermediate point in the current work system (never polar)
  const Vec3 via = target(w, false);
  const Vec3 viaMachine = toMachine(via);
  if (viaMachine != machine_) emitLine(Kind::Rapid, viaMachine);
  // phase 2: the named axes to the reference point (machine coordinates)
  auto it = setup_.referencePoints.find(point);
  const std::array<double, 3> ref =
      it == setup_.referencePoints.end() ? std::array<double, 3>{0, 0, 0} : it->second;
  Vec3 to = machine_;
  for (int a = 0; a < 3; ++a)
    if (axisGiven(w, a)) to[a] = ref[a];
  if (to != machine_) emitLine(Kind::Rapid, to);
  reexpress();
  return true;
}

// Straight to the point on the named axes, whatever their values, offsets and compensation
// (FMS-3000 G28/G30/G31, fms3000.md §3.8); then the program position follows the offsets.
bool Interpreter::directReferenceReturn(const BlockWords& w, int point) {
  Vec3 to = machine_;
  for (int a = 0; a < 3; ++a)
    if (axisGiven(w, a))
      to[a] =
          point == 0
              ? 0.0
              : setup_.parameter(
                    fmt::format(fmt::runtime(profile_.machine.directReferencePointKey), a, point),
                    0.0);
  if (to != machine_) emitLine(Kind::Rapid, to);
  reexpress();
  return true;
}

bool Interpreter::dataInput(const BlockWords& w, const ir::Block& dataBlock) {
  if (dataBlock.kind == ir::BlockKind::Data) {
    // a parameter record: its number, the bit word and the value (Profile::dataRecord)
    const DataRecordFormat& format = profile_.dataRecord;
    if (!dataBlock.sequence || !format.valueWord) return true;
    const ir::Word* r = dataBlock.find(format.valueWord);
    if (!r || r->kind != ir::ValueKind::Number) return true;
    const MachineRules& rules = profile_.machine;
    std::string key = fmt::format("{}{:0{}}", rules.parameterKeyPrefix, *dataBlock.sequence,
                                  rules.parameterKeyDigits);
    if (const ir::Word* q = format.bitWord ? dataBlock.find(format.bitWord) : nullptr)
      key += fmt::format(".{}", q->number);
    const double old = setup_.parameter(key, 0);
    setup_.parameters[key] = r->incremental ? old + r->number : r->number;
    cacheSettings(); // the record may have set one of them
    return true;
  }
  const ir::Word* g = w.findAction(GAction::DataInput);
  const int l = w.l ? static_cast<int>(w.l->number) : -1;
  if (std::find(profile_.dataModeLCodes.begin(), profile_.dataModeLCodes.end(), l) !=
      profile_.dataModeLCodes.end()) {
    dataMode_ = true;
    return true;
  }
  const bool add = state_.incremental;
  const DataEntryCode* entry = nullptr;
  for (const DataEntryCode& e : profile_.dataEntries)
    if (e.l == l) entry = &e;
  const std::string code = fmt::format("G{:g} L{}", g->number, l);
  const auto standard = static_cast<int>(profile_.machine.workOffsetNames.size());
  const int extended = profile_.machine.extendedWorkOffsets;
  if (entry &&
      (entry->entry == DataEntry::WorkOffset || entry->entry == DataEntry::ExtendedWorkOffset)) {
    if (!w.p) return fail(diag::code::MissingData, g->range, code + " needs P");
    const int p = static_cast<int>(w.p->number);
    const bool isStandard = entry->entry == DataEntry::WorkOffset;
    std::string key;
    if (isStandard && p == 0)
      key = "common";
    else if (isStandard && p >= 1 && p <= standard)
      key = workOffsetKey(p);
    else if (!isStandard && p >= 1 && p <= extended)
      key = workOffsetKey(100 + p);
    else
      return fail(
          diag::code::DataOutOfRange, w.p->range,
          fmt::format("{} P{:g}: the offset numbers are {}", code, w.p->number,
                      isStandard ? fmt::format("0-{}", standard) : fmt::format("1-{}", extended)));
    auto value = setup_.workOffset(key);
    for (int a = 0; a < 3; ++a)
      if (w.axis[a]) {
        const double v = mm(w.axis[a]->number);
        value[a] = (add || w.axis[a]->incremental) ? value[a] + v : v;
      }
    setup_.workOffsets[key] = value;
    for (int a = 0; a < 3; ++a) // I = XY plane (gamma), J = ZX (beta), K = YZ (alpha)
      if (w.ijk[a]) {
        if (key == "common")
          return fail(diag::code::DataOutOfRange, w.ijk[a]->range,
                      "the common offset carries no rotation (nct.md §3.14)");
        const double v = w.ijk[a]->number;
        setWorkRotation(key, a + 1,
                        (add || w.ijk[a]->incremental) ? workRotation(key, a + 1) + v : v);
      }
    if (key == "common") offsets_.common = Vec3(value[0], value[1], value[2]);
    reexpress();
    return true;
  }
  if (entry) { // length geometry / wear: gcx keeps their sum per register
    const bool wear = entry->entry == DataEntry::ToolLengthWear;
    if (!w.p || !w.r) return fail(diag::code::MissingData, g->range, code + " needs P and R");
    ToolData& t = setup_.tools[static_cast<int>(w.p->number)];
    const double v = mm(w.r->number);
    if (add || w.r->incremental) {
      t.length += v;
      if (wear) wear_[static_cast<int>(w.p->number)] += v; // the geometry stays
    } else if (!wear)
      t.length = v + wear_[static_cast<int>(w.p->number)];
    else {
      t.length += v - wear_[static_cast<int>(w.p->number)];
      wear_[static_cast<int>(w.p->number)] = v;
    }
    return true;
  }
  return fail(diag::code::NotImplemented, g->range,
              fmt::format("{} L{} is not implemented yet", gName(*g), l));
}

double Interpreter::coordinate(int axis, const ir::Word& w) const {
  const double v = mm(w.number);
  return (state_.diameterAxes >> axis) & 1u ? v / 2 : v; // diameter axes (nct.md §3.8)
}

double Interpreter::rotaryDelta(double current, double value) const {
  // absolute rotary target -> signed travel (nct.md §3.10); without rollover: plain linear axis
  if (!rollover_.enabled) return value - current;
  const double a = rollover_.amount;
  double display = std::fmod(current, a);
  if (display < 0) display += a;
  if (rollover_.absoluteBySign) { // ABS=1: |value| mod A, direction by the sign, 0 positive
    const double t = std::fmod(std::fabs(value), a);
    double d = std::fmod(value >= 0 ? t - display : display - t, a);
    if (d < 0) d += a;
    return value >= 0 ? d : -d;
  }
  double d = std::fmod(value - display, a); // sign-preserving, whole turns removed
  if (rollover_.shortest) {
    if (d > a / 2)
      d -= a;
    else if (d < -a / 2)
      d += a;
  }
  return d;
}

motion::Extra Interpreter::extraTarget(const BlockWords& w) const {
  motion::Extra t = extra_;
  for (int i = 0; i < 6; ++i) {
    const ir::Word* x = w.extra[i];
    if (!x) continue;
    const bool inc = state_.incremental || x->incremental;
    if (i < 3) { // rotary, degrees, never converted by G20
      t[i] = inc ? extra_[i] + x->number : extra_[i] + rotaryDelta(extra_[i], x->number);
    } else { // U V W axes parallel to X Y Z
      const double v = mm(x->number);
      t[i] = inc ? extra_[i] + v : v;
    }
  }
  return t;
}

void Interpreter::selectPlaneAxes(const BlockWords& w) {
  // G17 U_ V_ selects the UV plane; each parallel-axis word replaces only its own role (§3.6)
  const bool xy = w.has(GAction::PlaneXY), zx = w.has(GAction::PlaneZX),
             yz = w.has(GAction::PlaneYZ);
  if (!xy && !zx && !yz) return;
  const bool u = w.extra[3], v = w.extra[4], ww = w.extra[5];
  std::string names;
  if (xy) names = {u ? 'U' : 'X', v ? 'V' : 'Y'};
  if (zx) names = {ww ? 'W' : 'Z', u ? 'U' : 'X'};
  if (yz) names = {v ? 'V' : 'Y', ww ? 'W' : 'Z'};
  const bool main = names == "XY" || names == "ZX" || names == "YZ";
  state_.planeAxes = main ? std::string() : names;
}

void Interpreter::emitModalChanges(const ModalState& before) {
  auto change = [&](Kind kind, double value) {
    motion::Event e;
    e.kind = kind;
    e.start = e.end = machine_;
    e.extraStart = e.extraEnd = extra_;
    e.value = value;
    e.plane = state_.plane;
    e.text = kind == Kind::PlaneChange ? state_.planeAxes : std::string();
    emit(std::move(e));
  };
  if (before.plane != state_.plane || before.planeAxes != state_.planeAxes)
    change(Kind::PlaneChange, 0);
  if (before.inch != state_.inch) change(Kind::UnitsChange, state_.inch ? 20 : 21);
  if (before.perRevolution != state_.perRevolution)
    change(Kind::FeedModeChange, state_.perRevolution ? 95 : 94);
}

Vec3 Interpreter::target(const BlockWords& w, bool allowPolar) const {
  Vec3 t = program_;
  for (int a = 0; a < 3; ++a) {
    if (const ir::Word* x = w.axis[a]) {
      const double v = coordinate(a, *x);
      t[a] = (state_.incremental || x->incremental) ? program_[a] + v : v;
    }
    if (const ir::Word* u = w.uvw[a]) t[a] += coordinate(a, *u); // U V W: incremental aliases
  }
  if (!allowPolar || !state_.polar) return t;
  // polar input (nct.md §3.9): first plane axis = radius, second = angle in degrees
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  const double c1 = program_[ax.first], c2 = program_[ax.second];
  const ir::Word* rw = w.axis[ax.first] ? w.axis[ax.first] : w.uvw[ax.first];
  const ir::Word* aw = w.axis[ax.second] ? w.axis[ax.second] : w.uvw[ax.second];
  if (!rw && !aw) return t;
  const double currentAngle = std::atan2(c2, c1);
  double angle = currentAngle;
  if (aw) {
    const double v = aw->number * M_PI / 180.0;
    const bool inc = state_.incremental || aw->incremental || aw == w.uvw[ax.second];
    angle = inc ? currentAngle + v : v;
  }
  double p1, p2;
  if (rw && (state_.incremental || rw->incremental || rw == w.uvw[ax.first])) {
    const double d = mm(rw->number); // travel from the start point in the direction `angle`
    p1 = c1 + d * std::cos(angle);
    p2 = c2 + d * std::sin(angle);
  } else {
    const double r = rw ? mm(rw->number) : std::hypot(c1, c2);
    p1 = r * std::cos(angle);
    p2 = r * std::sin(angle);
  }
  t[ax.first] = p1;
  t[ax.second] = p2;
  return t;
}

bool Interpreter::move(const BlockWords& w) {
  if (state_.cycle != GAction::CycleCancel) { // --to nct keeps the cycle: only track the hole
    const motion::PlaneAxes ax = motion::axesOf(state_.plane);
    const Vec3 hole = target(w, true);
    program_[ax.first] = hole[ax.first];
    program_[ax.second] = hole[ax.second];
    return true;
  }
  if (profile_.machine.centreWordsOnlyOnArcs &&
      (state_.motion == GAction::Rapid || state_.motion == GAction::Linear))
    for (const ir::Word* c : w.ijk)
      if (c)
        return fail(
            diag::code::ArcDefinition, c->range,
            fmt::format("{} belongs to an arc: it is an error in a G00/G01 block", c->address));
  Vec3 to = target(w, true);
  if (!contourGeometry(w, to)) return false;
  const motion::Extra extraTo = extraTarget(w);
  if (w.has(GAction::OneSidedPositioning)) return oneSidedRapid(w, to, extraTo);
  if (w.has(GAction::ImplicitPlus) || w.has(GAction::ImplicitMinus))
    return implicitCoordinate(w, to, extraTo);
  switch (state_.motion) {
  case GAction::Rapid:
    emitLine(Kind::Rapid, toMachine(to), extraTo);
    program_ = to;
    return true;
  case GAction::Linear:
    if (state_.feed <= 0)
      return fail(diag::code::MissingData, blockRange_, "linear move without a feed rate F");
    emitLine(Kind::Feed, toMachine(to), extraTo);
    program_ = to;
    return true;
  case GAction::ArcCW:
  case GAction::ArcCCW: {
    if (!state_.planeAxes.empty())
      return fail(diag::code::NotImplemented, blockRange_,
                  fmt::format("arcs in the {} plane of parallel axes are not implemented yet",
                              state_.planeAxes));
    const motion::PlaneAxes ax = motion::axesOf(state_.plane);
    if (overCentre_) { // an over-determined circle (nct.md §4.3)
      if (state_.feed <= 0)
        return fail(diag::code::MissingData, blockRange_, "arc without a feed rate F");
      const Vec3 centre = *std::exchange(overCentre_, std::nullopt);
      return arcTo(to, centre, state_.motion == GAction::ArcCW, 1, extraTo, state_.feed);
    }
    return arc(w, to, extraTo, axisGiven(w, ax.first) || axisGiven(w, ax.second));
  }
  case GAction::FilletCW:
  case GAction::FilletCCW:
    return fillet(to, extraTo);
  case GAction::ThreadMotion:
  case GAction::ThreadReciprocating:
    return threadMove(w, to, extraTo);
  case GAction::TurningCycle:
    return turningCycle(static_cast<cycles::TurningCycle>(turningMode_->arg), w);
  default:
    return fail(diag::code::NotImplemented, blockRange_, "motion mode not implemented yet");
  }
}

// A rapid whose programmed axes end moving in the approach direction: an axis that would
// arrive from the other side, or not move at all, first goes past its target by the overshoot
// (FMS-3000 G60, fms3000.md §3.3).
bool Interpreter::oneSidedRapid(const BlockWords& w, const Vec3& to, const motion::Extra& extraTo) {
  const double overshoot = profile_.machine.oneSidedOvershoot;
  const double side = overshoot < 0 ? -1.0 : 1.0;
  Vec3 via = to;
  bool detour = false;
  for (int a = 0; a < 3; ++a) {
    if (!axisGiven(w, a) || (to[a] - program_[a]) * side > 1e-9) continue;
    via[a] = to[a] - overshoot;
    detour = true;
  }
  if (detour) {
    emitLine(Kind::Rapid, toMachine(via));
    program_ = via;
  }
  emitLine(Kind::Rapid, toMachine(to), extraTo);
  program_ = to;
  return true;
}

// One axis of the plane programmed, the other moving by the same magnitude, + or - (FMS-3000
// G47/G48, fms3000.md §3.7): a 45-degree line, or on an arc a quarter circle (the short arc of
// radius |travel|).
bool Interpreter::implicitCoordinate(const BlockWords& w, Vec3 to, const motion::Extra& extraTo) {
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  const ir::Word* code = w.findAction(GAction::ImplicitPlus);
  const double sign = code ? 1.0 : -1.0;
  if (!code) code = w.findAction(GAction::ImplicitMinus);
  const bool first = axisGiven(w, ax.first), second = axisGiven(w, ax.second);
  if (first == second)
    return fail(diag::code::ArcDefinition, code->range,
                fmt::format("{} takes exactly one axis of the plane", gName(*code)));
  const int p = first ? ax.first : ax.second, q = first ? ax.second : ax.first;
  const double travel = std::fabs(to[p] - program_[p]);
  if (travel < 1e-9)
    return fail(diag::code::ArcDefinition, code->range,
                fmt::format("{} without a move", gName(*code)));
  to[q] = program_[q] + sign * travel;
  if (state_.motion == GAction::Rapid || state_.motion == GAction::Linear) {
    if (state_.motion == GAction::Linear && state_.feed <= 0)
      return fail(diag::code::MissingData, blockRange_, "linear move without a feed rate F");
    emitLine(state_.motion == GAction::Rapid ? Kind::Rapid : Kind::Feed, toMachine(to), extraTo);
    program_ = to;
    return true;
  }
  if (state_.motion != GAction::ArcCW && state_.motion != GAction::ArcCCW)
    return fail(diag::code::NotImplemented, code->range,
                fmt::format("{} in this motion mode is not implemented", gName(*code)));
  if (state_.feed <= 0)
    return fail(diag::code::MissingData, blockRange_, "arc without a feed rate F");
  const bool cw = state_.motion == GAction::ArcCW;
  const double s1 = program_[ax.first], s2 = program_[ax.second];
  const double d1 = to[ax.first] - s1, d2 = to[ax.second] - s2, chord = std::hypot(d1, d2);
  const double h = std::sqrt(std::max(0.0, travel * travel - chord * chord / 4));
  const double side = cw ? -1.0 : 1.0; // the short arc's centre: right of the chord for G2
  Vec3 centre = program_;
  centre[ax.first] = s1 + d1 / 2 - side * h * d2 / chord;
  centre[ax.second] = s2 + d2 / 2 + side * h * d1 / chord;
  return arcTo(to, centre, cw, 1, extraTo, state_.feed);
}

bool Interpreter::arc(const BlockWords& w, const Vec3& end, const motion::Extra& extraEnd,
                      bool haveInPlaneEnd) {
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  const bool cw = state_.motion == GAction::ArcCW;
  const SourceRange& at = blockRange_;
  const ir::Word* helixPitch = w.has(GAction::HelicalQualifier) ? w.ijk[ax.normal] : nullptr;
  if (w.has(GAction::HelicalQualifier) && !helixPitch)
    return fail(diag::code::ArcDefinition, w.findAction(GAction::HelicalQualifier)->range,
                fmt::format("a helix needs its pitch {}", "IJK"[ax.normal]));
  if (w.ijk[ax.normal] && !helixPitch)
    return fail(
        diag::code::ArcDefinition, w.ijk[ax.normal]->range,
        fmt::format("{} is outside the selected plane (nct.md §3.5)", w.ijk[ax.normal]->address));
  const bool centreGiven = w.ijk[ax.first] || w.ijk[ax.second];
  if (w.r && centreGiven)
    return fail(diag::code::ArcDefinition, w.r->range,
                "both R and I/J/K in one arc block (nct.md Q20)");
  if (!w.r && !centreGiven)
    return fail(diag::code::ArcDefinition, at, "arc without R or I/J/K (nct.md §3.5)");
  int turns = 1;
  const ir::Word* turnsWord = profile_.machine.arcL == ArcLMeaning::Turns ? w.l : nullptr;
  if (turnsWord) {
    if (turnsWord->number < 1 || turnsWord->number != std::floor(turnsWord->number))
      return fail(diag::code::DataOutOfRange, turnsWord->range,
                  "L of an arc counts started turns: 1 or more");
    turns = static_cast<int>(turnsWord->number);
  }
  const Vec3 start = program_;
  const double s1 = start[ax.first], s2 = start[ax.second];
  const double e1 = end[ax.first], e2 = end[ax.second];
  double c1, c2;
  if (w.r) {
    const double r = mm(w.r->number);
    const double d1 = e1 - s1, d2 = e2 - s2, chord = std::hypot(d1, d2);
    if (profile_.machine.strictArcRadius) {
      if (r == 0) return fail(diag::code::ArcZeroRadius, w.r->range, "arc of radius R0");
      if (!haveInPlaneEnd || chord == 0)
        return fail(diag::code::ArcDefinition, w.r->range,
                    "a full circle cannot be programmed by R; write I/J/K");
      if (std::fabs(r) < chord / 2 - 1e-9)
        return fail(diag::code::ArcDefinition, w.r->range,
                    fmt::format("the chord {} is longer than 2R", emit::formatNumber(chord)));
    }
    if (!haveInPlaneEnd) return true; // no motion, no alarm (000:1314-1318)
    if (chord == 0) return true;
    if (std::fabs(r) < chord / 2) {
      // R below half the chord: R is the start radius, centre on the chord (000:1343-1365)
      c1 = s1 + std::fabs(r) * d1 / chord;
      c2 = s2 + std::fabs(r) * d2 / chord;
    } else {
      const double h = std::sqrt(r * r - chord * chord / 4);
      // G3 with R>0 has its centre left of the chord, G2 right; R<0 (more than 180°) swaps
      const double side = (cw ? -1.0 : 1.0) * (r < 0 ? -1.0 : 1.0);
      c1 = (s1 + e1) / 2 - side * h * d2 / chord;
      c2 = (s2 + e2) / 2 + side * h * d1 / chord;
    }
  } else {
    // from the start point, unless the dialect's setting makes the centre absolute
    if (arcCentreMode_ == 1 || (arcCentreMode_ == 2 && !state_.incremental)) {
      c1 = w.ijk[ax.first] ? mm(w.ijk[ax.first]->number) : s1;
      c2 = w.ijk[ax.second] ? mm(w.ijk[ax.second]->number) : s2;
    } else {
      c1 = s1 + (w.ijk[ax.first] ? mm(w.ijk[ax.first]->number) : 0.0);
      c2 = s2 + (w.ijk[ax.second] ? mm(w.ijk[ax.second]->number) : 0.0);
    }
  }
  const double r0 = std::hypot(s1 - c1, s2 - c2), r1 = std::hypot(e1 - c1, e2 - c2);
  if (r0 < 1e-9) return fail(diag::code::ArcZeroRadius, at, "arc of radius 0");
  if (!turnsWord && std::fabs(r1 - r0) > radiusTolerance_)
    return fail(
        diag::code::ArcRadiusMismatch, at,
        fmt::format("end point radius {} differs from start radius {} by more than "
                    "{} ({}){}",
                    emit::formatNumber(std::round(r1 * 1e4) / 1e4),
                    emit::formatNumber(std::round(r0 * 1e4) / 1e4),
                    emit::formatNumber(radiusTolerance_),
                    settingLabel(profile_, Setting::ArcRadiusTolerance),
                    profile_.machine.arcL == ArcLMeaning::Turns ? "; program L for a spiral" : ""));
  if (state_.feed <= 0) return fail(diag::code::MissingData, at, "arc without a feed rate F");
  Vec3 centre = start;
  centre[ax.first] = c1;
  centre[ax.second] = c2;
  if (helixPitch) { // FMS-3000 G10: the turns follow from the travel and the pitch (§3.6)
    const double travel = end[ax.normal] - start[ax.normal];
    // the pitch letter of another linear axis (U V W, rotary) is not documented (§10 Q4)
    if (std::fabs(travel) < 1e-9 && (extraEnd - extra_).cwiseAbs().maxCoeff() > 1e-9)
      return fail(diag::code::NotImplemented, at,
                  fmt::format("a helix along another axis than {} is not implemented yet: the "
                              "manual names no pitch letter for it (fms3000.md §10 Q4)",
                              "XYZ"[ax.normal]));
    if (std::fabs(travel) < 1e-9)
      return fail(diag::code::ArcDefinition, at,
                  "a helix needs a move of the axis outside the arc's plane");
    const auto plan =
        planHelix(s1, s2, e1, e2, c1, c2, cw, travel, mm(helixPitch->number), radiusTolerance_);
    if (const std::string* why = std::get_if<std::string>(&plan))
      return fail(diag::code::ArcDefinition, helixPitch->range, *why);
    turns = std::get<HelixPlan>(plan).fullTurns + 1;
  }
  return arcTo(end, centre, cw, turns, extraEnd, state_.feed);
}

bool Interpreter::arcTo(const Vec3& end, const Vec3& centre, bool cw, int turns,
                        const motion::Extra& extraEnd, double feed) {
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  const SourceRange& at = blockRange_;
  const double r0 =
      std::hypot(program_[ax.first] - centre[ax.first], program_[ax.second] - centre[ax.second]);
  const double r1 =
      std::hypot(end[ax.first] - centre[ax.first], end[ax.second] - centre[ax.second]);
  // the transformed arc must stay a circle in its plane
  const auto similarity = motion::planeSimilarity(transforms_.matrix().linear(), state_.plane);
  if (!similarity)
    return fail(diag::code::UnequalArcScaling, at,
                "this arc is not a circle after scaling with unequal factors or a rotation out of "
                "its plane; gcx does not expand it yet (nct.md Q19)");
  const double k = similarity->scale;
  const bool mirrored = similarity->mirrored;

  motion::Event e;
  e.kind = Kind::Arc;
  e.start = machine_;
  e.extraStart = extra_;
  e.extraEnd = extraEnd;
  e.end = toMachine(end);
  e.center = toMachine(centre);
  e.plane = state_.plane;
  e.clockwise = cw != mirrored;
  e.turns = turns - 1;
  e.startRadius = r0 * k;
  e.endRadius = profile_.machine.arcWithinToleranceIsCircle ? e.startRadius : r1 * k;
  e.feed = feed;
  e.perRevolution = state_.perRevolution;
  machine_ = e.end;
  extra_ = extraEnd;
  program_ = end;
  emit(std::move(e));
  return true;
}

bool Interpreter::beforeMotion(const BlockWords& w) {
  return auxiliary(w, MTiming::BeforeMotion);
}

bool Interpreter::afterMotion(const BlockWords& w) {
  return auxiliary(w, MTiming::AfterMotion);
}

bool Interpreter::auxiliary(const BlockWords& w, MTiming phase) {
  // S, T and each M code act before or after the motion of their block as the dialect times
  // them (NCT: all after, nct.md §2.2)
  const MachineRules& rules = profile_.machine;
  if (w.t && rules.toolTiming == phase) {
    state_.selectedTool = static_cast<int>(w.t->number);
    if (rules.toolSelectsOffsets) { // the working point's offsets move the zero; T0: none
      const auto it = setup_.tools.find(state_.selectedTool);
      const bool none = state_.selectedTool == 0 || it == setup_.tools.end();
      const std::array<double, 3> t = none ? std::array<double, 3>{} : it->second.turning;
      offsets_.turning = Vec3(t[0], t[1], t[2]);
      reexpress(); // nothing moves: the next move of an axis goes to its new zero
    }
  }
  bool spindleChanged = false;
  // S in a set-coordinates block may be the surface speed's clamp, not a speed (G92 S)
  const bool clampOnly = w.has(GAction::SetCoordinates) && rules.setCoordinatesSIsSpindleLimit;
  if (w.s && !clampOnly && rules.speedTiming == phase) {
    if (state_.surfaceSpeed)
      state_.surfaceSpeedValue = w.s->number;
    else
      state_.spindleSpeed = w.s->number;
    spindleChanged = true;
  }
  for (const ir::Word* m : w.m) {
    const MCodeSpec* spec = rules.mcode(static_cast<int>(m->number));
    if (!spec || spec->timing != phase) continue;
    if (spec->action == MAction::SpindleCW || spec->action == MAction::SpindleCCW ||
        spec->action == MAction::SpindleStop) {
      state_.spindleDirection = spec->action == MAction::SpindleCW    ? 1
                                : spec->action == MAction::SpindleCCW ? -1
                                                                      : 0;
      spindleChanged = true;
    }
  }
  if (phase == MTiming::AfterMotion && state_.surfaceSpeed) {
    // G96: rpm from the surface speed at the block's end point, the radius along the
    // dialect's radial axis of the work system (nct.md §3.18: rapid blocks use the end point)
    const double radius = std::fabs(program_[rules.surfaceSpeedAxis]);
    const double metresPerMinute =
        state_.inch ? state_.surfaceSpeedValue * 0.3048 : state_.surfaceSpeedValue;
    double rpm = state_.maxSpindleSpeed;
    if (radius > 1e-9) rpm = metresPerMinute * 1000.0 / (2 * M_PI * radius);
    if (state_.maxSpindleSpeed > 0) rpm = std::min(rpm, state_.maxSpindleSpeed);
    if (rpm <= 0 && state_.surfaceSpeedValue > 0)
      return fail(diag::code::MissingData, blockRange_,
                  "constant surface speed at radius 0 needs a spindle limit (G92 S)");
    if (std::fabs(rpm - state_.spindleSpeed) > 1e-9) {
      state_.spindleSpeed = rpm;
      spindleChanged = true;
    }
  }
  if (spindleChanged) emitSpindle();
  return w.m.empty() || mcodes(w, phase); // most blocks have none: no call to set up its frame
}

bool Interpreter::mcodes(const BlockWords& w, MTiming timing) {
  for (const ir::Word* m : w.m) {
    const int code = static_cast<int>(m->number);
    const MCodeSpec* spec = profile_.machine.mcode(code);
    if (!spec) {
      if (timing == MTiming::AfterMotion)
        diags_.warning(diag::code::MCodeWithoutMotion, m->range,
                       fmt::format("M{} has no meaning in the motion model; it is not carried "
                                   "into the motion trace",
                                   code));
      continue;
    }
    if (spec->timing != timing) continue;
    motion::Event e;
    e.start = e.end = machine_;
    switch (spec->action) {
    case MAction::SpindleCW:
    case MAction::SpindleCCW:
    case MAction::SpindleStop:
      continue; // auxiliary() set the direction with the speed: one spindle event
    case MAction::SpindleOrient:
      e.kind = Kind::SpindleOrient;
      break;
    case MAction::ToolChange:
      state_.tool = state_.selectedTool;
      e.kind = Kind::ToolChange;
      e.value = state_.tool;
      break;
    case MAction::Coolant:
      state_.coolant = code;
      e.kind = Kind::Coolant;
      e.value = code;
      break;
    case MAction::GearRange:
      state_.gearRange = code;
      continue;
    case MAction::Stop:
    case MAction::OptionalStop:
      e.kind = Kind::Stop;
      e.optional = spec->action == MAction::OptionalStop;
      break;
    case MAction::End:
    case MAction::EndRewind:
      if (!threadSequenceEnd(w, true)) return false;
      e.kind = Kind::End;
      e.value = code;
      emit(std::move(e));
      ended_ = true;
      resetModal();
      return false;
    case MAction::Subprogram:
      return fail(diag::code::NotImplemented, m->range,
                  "subprogram calls need the expansion pass, which is not implemented yet");
    }
    emit(std::move(e));
  }
  return true;
}

void Interpreter::emitDwell(double p) {
  motion::Event e;
  e.kind = Kind::Dwell;
  e.start = e.end = machine_;
  e.extraStart = e.extraEnd = extra_;
  e.value = p; // seconds, or revolutions under feed per revolution unless the dialect's
               // setting keeps seconds (000:3427-3442)
  e.perRevolution =
      state_.perRevolution && setting(profile_, setup_, Setting::DwellSecondsAlways) == 0;
  emit(std::move(e));
}

void Interpreter::emitSpindle() {
  motion::Event e;
  e.kind = Kind::Spindle;
  e.start = e.end = machine_;
  e.extraStart = e.extraEnd = extra_;
  e.value = state_.spindleSpeed;
  e.direction = state_.spindleDirection;
  emit(std::move(e));
}

void Interpreter::message(const std::string& text, const motion::Provenance& from, bool stop) {
  from_ = from;
  motion::Event e;
  e.kind = Kind::Message;
  e.start = e.end = machine_;
  e.extraStart = e.extraEnd = extra_;
  e.text = text;
  emit(motion::Event(e)); // e again below
  if (stop) {
    e.kind = Kind::Stop;
    e.text.clear();
    emit(std::move(e));
  }
}

bool Interpreter::endOfFile(SourceRange lastBlock) {
  if (ended_) return true;
  const char* message = profile_.machine.endOfFileError;
  if (message && !pendingProfile_ && !directionLine_) // finish() reports those first
    return fail(diag::code::EndWithoutM30, blockRange_.begin.valid() ? blockRange_ : lastBlock,
                message);
  finish();
  return !stopped_;
}

void Interpreter::finish() {
  if (ended_) return;
  if (pendingProfile_) { // G164/G165 whose profile never ended
    fail(diag::code::FmsProfile, pendingProfile_->code,
         "the profile after this cycle has no `endcont` line (001:3255-3259)");
    return;
  }
  if (directionLine_) { // a line by ,A alone never met the line that ends it (nct.md §4.3)
    fail(diag::code::IntersectionElement, blockRange_,
         "the program ends after a line given by its direction alone (,A): no over-determined "
         "line or circle ends it (nct.md §4.3)");
    return;
  }
  ended_ = true;
  motion::Event e;
  e.kind = Kind::End;
  e.start = e.end = machine_;
  e.text = "end of file";
  emit(std::move(e));
}

} // namespace gcx::machine
