// The interpreter's side of the turning cycles (cycles.md §4): finding and checking the contour
// blocks ns..nf, resolving them into moves on a scratch copy of the engine (so the contour means
// exactly what the same blocks mean when G70.7 runs them), and G70.7 itself. The cycles'
// geometry is cycles/turning.h's.
#include <fmt/format.h>

#include "diag/codes.h"
#include "emit/number.h"
#include "machine/cycle_state.h"
#include "machine/interpreter.h"
#include "motion/geometry.h"

namespace gcx::machine {

using motion::Kind;

namespace {

/// What a contour block may contain (§4.7): moves G00-G03, G90/G91, G40-G42, coordinates and
/// arc words, chamfer and rounding, F S T.
bool allowedInContour(const ir::Word& w, const Profile& profile, char chamferLetter) {
  if (chamferLetter && w.is(chamferLetter)) return true; // the automatic chamfer's leg
  if (w.is('G')) {
    const GCodeSpec* g = profile.gcode(w.number);
    if (!g) return false;
    switch (g->action) {
    case GAction::Rapid:
    case GAction::Linear:
    case GAction::ArcCW:
    case GAction::ArcCCW:
    case GAction::Absolute:
    case GAction::Incremental:
    case GAction::RadiusCompOff:
    case GAction::RadiusCompLeft:
    case GAction::RadiusCompRight:
    case GAction::FilletCW: // a contour may use every motion of group 1 but threads (wl4.md §5.6)
    case GAction::FilletCCW:
      return true;
    default:
      return false;
    }
  }
  static const char* const allowed[] = {"X", "Y", "Z", "U", "V", "W", "I",  "J",
                                        "K", "R", "F", "S", "T", "N", ",C", ",R"};
  for (const char* a : allowed)
    if (w.address == a) return true;
  return false;
}

class Capture : public motion::Sink {
public:
  std::vector<motion::Event> moves;
  void event(const motion::Event& e) override {
    if (e.kind == Kind::Rapid || e.kind == Kind::Feed || e.kind == Kind::Arc) moves.push_back(e);
  }
};

} // namespace

bool Interpreter::contourBlocks(const BlockWords& w, std::vector<ContourBlock>& out) {
  const ir::Word* cycle = w.gWords.front();
  for (std::size_t i = 0; i < w.gWords.size(); ++i)
    if (w.gCodes[i] && (w.gCodes[i]->action == GAction::TurningCycle ||
                        w.gCodes[i]->action == GAction::ContourCycle))
      cycle = w.gWords[i];
  const std::string name = fmt::format("G{}", emit::formatNumber(cycle->number));
  if (!w.p || !w.q)
    return fail(diag::code::CyclePQNotFound, cycle->range,
                fmt::format("{} needs P (first contour block) and Q (last)", name));
  const auto ns = static_cast<std::int64_t>(w.p->number);
  const auto nf = static_cast<std::int64_t>(w.q->number);
  if (!contours_)
    return fail(
        diag::code::CyclePQNotFound, cycle->range,
        fmt::format("{}: the contour blocks cannot be found in a program read as a stream", name));
  const std::size_t errors = diags_.errorCount();
  if (!contours_(ns, nf, out) || out.empty())
    return diags_.errorCount() != errors
               ? false
               : fail(
                     diag::code::CyclePQNotFound, w.p->range,
                     fmt::format("{}: contour N{} to N{} not found in this program", name, ns, nf));
  const std::string& ignored = profile_.cycleChoices.contourIgnoredWords;
  const ContourWords& geometry = profile_.machine.contour;
  const char chamferLetter =
      parameter(geometry.chamferAxisKey, 0) == 1 ? geometry.chamferAxis : char{0};
  for (ContourBlock& c : out) {
    std::erase_if(c.block.words, [&](const ir::Word& word) { // F S T M of WL4 (§5.6)
      return word.address.size() == 1 && ignored.find(word.address[0]) != std::string::npos;
    });
    if (!c.block.stmts.empty())
      return fail(diag::code::CycleContourCommand, c.block.stmts.front().range,
                  "a macro statement inside a turning contour (cycles.md §4.7)");
    for (const ir::Word& word : c.block.words)
      if (!allowedInContour(word, profile_, chamferLetter))
        return fail(
            diag::code::CycleContourCommand, word.range,
            fmt::format("{} is not allowed inside a turning contour: only G00-G03, G40-G42, "
                        "coordinates, F, S and T (cycles.md §4.7)",
                        word.address == "G" ? fmt::format("G{}", emit::formatNumber(word.number))
                                            : word.address));
  }
  return true;
}

bool Interpreter::traceContour(const std::vector<ContourBlock>& blocks,
                               std::vector<cycles::ContourSegment>& out, const Vec3* start) {
  Capture capture;
  Interpreter probe(*this);
  probe.sink_ = &capture;
  if (start) {
    probe.program_ = *start;
    probe.machine_ = probe.toMachine(*start);
  }
  probe.comp_ = CompensationStage(compensationOptions()); // the contour's own path
  probe.corners_ = ContourCornerStage();
  probe.contours_ = nullptr;
  auto isComp = [&](const GCodeSpec* g) {
    return g && (g->action == GAction::RadiusCompOff || g->action == GAction::RadiusCompLeft ||
                 g->action == GAction::RadiusCompRight);
  };
  auto isMotion = [&](const GCodeSpec* g) {
    return g && (g->action == GAction::Rapid || g->action == GAction::Linear ||
                 g->action == GAction::ArcCW || g->action == GAction::ArcCCW);
  };
  for (const ContourBlock& c : blocks) {
    ir::Block b = c.block;
    bool modeProgrammed = false;
    std::erase_if(b.words, [&](const ir::Word& w) {
      const GCodeSpec* g = w.is('G') ? profile_.gcode(w.number) : nullptr;
      modeProgrammed = modeProgrammed || isMotion(g);
      return isComp(g);
    });
    const std::size_t before = capture.moves.size();
    if (!probe.execute(b, c.from)) return false;
    for (std::size_t i = before; i < capture.moves.size(); ++i) {
      const motion::Event& e = capture.moves[i];
      cycles::ContourSegment s;
      s.kind = e.kind == Kind::Rapid  ? cycles::OpKind::Rapid
               : e.kind == Kind::Feed ? cycles::OpKind::Feed
               : e.clockwise          ? cycles::OpKind::ArcCW
                                      : cycles::OpKind::ArcCCW;
      s.from = toProgram(e.start);
      s.to = toProgram(e.end);
      s.center = toProgram(e.center);
      s.feed = e.feed;
      s.range = c.block.range;
      s.modeProgrammed = modeProgrammed;
      out.push_back(s);
    }
  }
  return true;
}

cycles::TurningWords Interpreter::turningWords(cycles::TurningCycle cycle,
                                               const BlockWords& w) const {
  cycles::TurningWords t;
  t.cycle = cycle;
  for (std::size_t i = 0; i < w.gWords.size(); ++i)
    if (w.gCodes[i] && w.gCodes[i]->action == GAction::TurningCycle)
      t.label = "G" + emit::formatNumber(w.gWords[i]->number);
  t.plane = state_.plane;
  t.diameter = state_.diameterAxes;
  t.range = blockRange_;
  // not a first block of a two-block format: G71.7-G73.7 run with P and Q (their first block
  // has U/W words too), G74.7-G76.7 with an axis word
  const bool run = cycle <= cycles::TurningCycle::PatternRepeat ? (w.p && w.q) : w.hasAxisWord();
  auto put = [&](char letter, const ir::Word* x, bool length, bool axis) {
    if (!x) return;
    const bool incremental = axis && (state_.incremental || x->incremental);
    t.set(letter, length ? mm(x->number) : x->number, x->range, incremental);
  };
  for (int a = 0; a < 3; ++a) {
    put("XYZ"[a], w.axis[a], true, true);
    put("UVW"[a], w.uvw[a], true, false);
    put("IJK"[a], w.ijk[a], true, false);
  }
  // counts and codes keep their number: G73.7 R d (passes), G76.7 P(m)(r)(a) of the first block
  put('R', w.r, !(cycle == cycles::TurningCycle::PatternRepeat && !run), false);
  put('P', w.p,
      !(cycle == cycles::TurningCycle::MultipleThread && !run) &&
          cycle != cycles::TurningCycle::Finishing && cycle != cycles::TurningCycle::RoughTurning &&
          cycle != cycles::TurningCycle::RoughFacing &&
          cycle != cycles::TurningCycle::PatternRepeat,
      false);
  put('Q', w.q, cycle >= cycles::TurningCycle::FaceGrooving, false);
  put('F', w.f, true, false);
  put('L', w.l, false, false);
  return t;
}

bool Interpreter::turningCycle(cycles::TurningCycle cycle, const BlockWords& w) {
  using cycles::TurningCycle;
  const cycles::TurningWords words = turningWords(cycle, w);
  switch (cycles::updateModal(cycles_->turning, words, diags_)) {
  case cycles::TurningBlock::Error:
    return false;
  case cycles::TurningBlock::Stored:
    return true;
  case cycles::TurningBlock::Run:
    break;
  }
  cycles::TurningRequest req;
  req.plane = state_.plane;
  req.start = program_;
  req.feed = state_.feed;
  req.choices = profile_.cycleChoices;
  std::vector<ContourBlock> blocks;
  const bool contourCycle = cycle == TurningCycle::RoughTurning ||
                            cycle == TurningCycle::RoughFacing ||
                            cycle == TurningCycle::PatternRepeat;
  if (contourCycle) {
    if (!contourBlocks(w, blocks) || !traceContour(blocks, req.contour)) return false;
  } else {
    // the end point resolves like a move's; a repeat of G77.7-G79.7 keeps what it omits (§4.1)
    const bool repeat = cycle >= TurningCycle::TurningPass && turningEnd_;
    req.end = target(w, false);
    const motion::PlaneAxes ax = motion::axesOf(state_.plane);
    for (int a : {ax.first, ax.second})
      if (repeat && !axisGiven(w, a)) req.end[a] = (*turningEnd_)[a];
    if (cycle >= TurningCycle::TurningPass) {
      if (w.r) turningTaper_ = mm(w.r->number);
      req.taper = turningTaper_.value_or(0);
      turningEnd_ = req.end;
    } else if (w.r && cycle == TurningCycle::MultipleThread) {
      req.taper = mm(w.r->number);
    }
    if ((cycle == TurningCycle::MultipleThread || cycle == TurningCycle::ThreadPass) &&
        state_.surfaceSpeed)
      diags_.warning(diag::code::CycleThreadCss, blockRange_,
                     fmt::format("{} with constant surface speed G96 on: threading needs a fixed "
                                 "spindle speed (000:1682-1683)",
                                 words.label));
  }
  const auto ops = cycles::expandTurning(req, cycles_->turning, words, diags_);
  if (!ops) return false;
  // M S F of the P/Q block take effect at the start of the cycle (§4.7, 000:10482)
  if (!runCycleOps(*ops, contourCycle ? 0 : static_cast<std::size_t>(-1), w,
                   motion::axesOf(state_.plane).normal, words.label.c_str()))
    return false;
  if (contourCycle) resumeAfter_ = static_cast<std::int64_t>(w.q->number);
  return true;
}

bool Interpreter::finishingCycle(const BlockWords& w) {
  std::vector<ContourBlock> blocks;
  if (!contourBlocks(w, blocks)) return false;
  const Vec3 start = program_;
  const motion::Provenance caller = from_;
  const SourceRange callRange = blockRange_;
  const std::string what = fmt::format("G70.7 P{} Q{}", emit::formatNumber(w.p->number),
                                       emit::formatNumber(w.q->number));
  for (ContourBlock& c : blocks) {    // as ordinary blocks, with their own F S T (§4.11)
    motion::Provenance from = c.from; // its chain is the caller's: the contour is in its program
    from.chain.push_back({callRange.begin, what});
    if (!execute(c.block, from)) return false;
  }
  from_ = caller;
  blockRange_ = callRange;
  emitLine(Kind::Rapid, toMachine(start)); // back to the start point of the G70.7 block
  program_ = start;
  return true;
}

bool Interpreter::turningBlock(const BlockWords& w) {
  // the profile binds the code to a cycle of the library (GCodeSpec::arg)
  const auto cycle = std::optional(static_cast<cycles::TurningCycle>(pendingTurning_->arg));
  if (*cycle == cycles::TurningCycle::Finishing) return finishingCycle(w) && afterMotion(w);
  const bool contourRun = (*cycle == cycles::TurningCycle::RoughTurning ||
                           *cycle == cycles::TurningCycle::RoughFacing ||
                           *cycle == cycles::TurningCycle::PatternRepeat) &&
                          w.p && w.q;
  if (!turningCycle(*cycle, w)) return false;
  return contourRun || afterMotion(w); // a contour cycle ran the block's M S T before its passes
}

} // namespace gcx::machine
