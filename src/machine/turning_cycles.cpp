// The interpreter's side of the turning cycles (cycles.md §4): finding and checking the contour
// blocks ns..nf, resolving them into moves on a scratch copy of the engine (so the contour means
// exactly what the same blocks mean when G70.7 runs them), and G70.7 itself. The cycles'
// geometry is passes/cycles/turning.h's.
#include <fmt/format.h>

#include "diag/codes.h"
#include "emit/number.h"
#include "machine/interpreter.h"

namespace gcx::machine {

using motion::Kind;

namespace {

/// What a contour block may contain (§4.7): moves G00-G03, G90/G91, G40-G42, coordinates and
/// arc words, chamfer and rounding, F S T.
bool allowedInContour(const ir::Word& w, const Profile& profile) {
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
    if (w.gCodes[i] && w.gCodes[i]->action == GAction::TurningCycle) cycle = w.gWords[i];
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
  for (const ContourBlock& c : out) {
    if (c.block.stmt)
      return fail(diag::code::CycleContourCommand, c.block.stmt->range,
                  "a macro statement inside a turning contour (cycles.md §4.7)");
    for (const ir::Word& word : c.block.words)
      if (!allowedInContour(word, profile_))
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
                               std::vector<cycles::CycleOp>& out,
                               std::vector<SourceRange>& ranges) {
  Capture capture;
  Interpreter probe(*this);
  probe.sink_ = &capture;
  probe.contours_ = nullptr;
  for (const ContourBlock& c : blocks) {
    ir::Block b = c.block;
    std::erase_if(b.words, [&](const ir::Word& w) {
      const GCodeSpec* g = w.is('G') ? profile_.gcode(w.number) : nullptr;
      return g && (g->action == GAction::RadiusCompOff || g->action == GAction::RadiusCompLeft ||
                   g->action == GAction::RadiusCompRight);
    });
    const std::size_t before = capture.moves.size();
    if (!probe.execute(b, c.from)) return false;
    ranges.resize(ranges.size() + (capture.moves.size() - before), c.block.range);
  }
  for (const motion::Event& e : capture.moves) {
    cycles::CycleOp op;
    op.kind = e.kind == Kind::Rapid  ? cycles::OpKind::Rapid
              : e.kind == Kind::Feed ? cycles::OpKind::Feed
              : e.clockwise          ? cycles::OpKind::ArcCW
                                     : cycles::OpKind::ArcCCW;
    op.to = toProgram(e.end);
    op.center = toProgram(e.center);
    op.feed = e.feed;
    out.push_back(op);
  }
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
  for (ContourBlock& c : blocks) { // as ordinary blocks, with their own F S T (§4.11)
    motion::Provenance from = c.from;
    from.chain.insert(from.chain.begin(), caller.chain.begin(), caller.chain.end());
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
  switch (pendingTurning_) {
  case 707:
    if (!finishingCycle(w)) return false;
    break;
  default:
    return fail(
        diag::code::NotImplemented, blockRange_,
        fmt::format("G{} is not implemented yet", emit::formatNumber(pendingTurning_ / 10.0)));
  }
  return afterMotion(w);
}

} // namespace gcx::machine
