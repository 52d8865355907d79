#include "cli/packed_blocks.h"

#include <algorithm>
#include <limits>

#include "ir/new_expr.h"
#include "ir/short_text.h"

namespace gcx::cli {

namespace {

inline bool sameLine(const SourceLoc& a, const SourceLoc& line) {
  return a.file == line.file && a.line == line.line && a.col >= 1 && line.col >= 1 &&
         a.offset - a.col == line.offset - line.col;
}

// Whether e is a new ir::Expr: what a literal word holds (the fast parse resets it so).
inline bool isNewExpr(const ir::Expr& e) {
  return e.kind == ir::kNewExpr.kind && e.number == ir::kNewExpr.number && e.name.empty() &&
         e.args.empty() && e.op == ir::kNewExpr.op && e.func == ir::kNewExpr.func &&
         e.prmHasBit == ir::kNewExpr.prmHasBit && e.prmHasIndex == ir::kNewExpr.prmHasIndex &&
         e.range.begin.file == ir::kNewExpr.range.begin.file && e.range.begin.line == 0 &&
         e.range.begin.col == 0 && e.range.begin.offset == 0 && e.range.length == 0;
}

inline bool packableWord(const ir::Word& w, const SourceLoc& line) {
  return w.address.size() == 1 && w.kind == ir::ValueKind::Number && w.axisIndex.empty() &&
         w.text.size() <= PackedBlocks::kMaxText && sameLine(w.range.begin, line) &&
         isNewExpr(w.expr);
}

// to = the range on the line of `line` that starts at col, stored field by field (a temporary
// copied whole would make the copy wait for its narrow stores).
inline void writeOnLine(SourceRange& to, const SourceLoc& line, std::uint32_t col,
                        std::uint32_t length) {
  to.begin.file = line.file;
  to.begin.line = line.line;
  to.begin.col = col;
  to.begin.offset = line.offset - line.col + col;
  to.length = length;
}

} // namespace

namespace {
// The conditions on the block itself; its words are checked one by one as they are packed.
bool packableBlock(const ir::Block& b) {
  const SourceLoc& line = b.range.begin;
  if (!b.programName.empty() || !b.stmts.empty() || !b.comments.empty() ||
      b.words.size() > std::numeric_limits<std::uint8_t>::max() || b.skipLevel < 0 ||
      b.skipLevel > std::numeric_limits<std::int8_t>::max())
    return false;
  if (b.sequence)
    return b.sequenceText.size() <= PackedBlocks::kMaxText && sameLine(b.sequenceRange.begin, line);
  return b.sequenceText.empty() && !b.sequenceRange.begin.valid();
}
} // namespace

namespace {
// A prefetch to write: the line comes in owned, not shared, so the stores to it need not ask the
// other core again. x86's PREFETCHW, which every x86-64 processor of the last decade has and
// older ones execute as a no-op (the compiler emits it only for a -march that names it);
// elsewhere the compiler's own.
inline void prefetchToWrite(const char* p) {
#if defined(__x86_64__)
  asm volatile("prefetchw %0" : : "m"(*p));
#else
  __builtin_prefetch(p, 1, 3);
#endif
}

// Room for n more after the first `used` of v, grown by doubling: the first batches set the size
// for the run.
template <class T> T* room(std::vector<T>& v, std::size_t used, std::size_t n) {
  if (used + n > v.size()) v.resize(std::max(v.size() * 2, used + n));
  T* at = v.data() + used;
  // The batch was last read by the executing thread: its lines are in that core's cache. Each
  // line is asked for (to write) some blocks ahead of its stores, so it comes over while this
  // thread builds those blocks, rather than with the stores waiting for it and every store
  // behind them (a prefetch never faults, past the end included).
  constexpr std::size_t kAhead = 1024, kLine = 64;
  const char* const begin = reinterpret_cast<const char*>(at) + kAhead;
  for (const char* p = begin; p < begin + n * sizeof(T); p += kLine)
    prefetchToWrite(p);
  return at;
}
} // namespace

bool PackedBlocks::pack(const ir::Block& b) {
  if (!packableBlock(b)) return false;
  // the words first: one that has no packed form leaves nothing behind (wordsUsed_ is kept)
  const std::size_t n = b.words.size();
  Word* q = room(words_, wordsUsed_, n);
  for (const ir::Word& w : b.words) {
    if (!packableWord(w, b.range.begin)) return false;
    q->number = w.number;
    q->col = w.range.begin.col;
    q->length = w.range.length;
    q->order = w.order;
    q->letter = w.address[0];
    q->incremental = w.incremental;
    q->textLength = static_cast<std::uint8_t>(w.text.size());
    ir::copyShort(q->text, w.text.data(), w.text.size());
    ++q;
  }
  Block& p = *room(blocks_, blocksUsed_, 1);
  p.range = b.range;
  p.lastLine = b.lastLine;
  p.kind = b.kind;
  p.skipLevel = static_cast<std::int8_t>(b.skipLevel);
  p.hasSequence = b.sequence.has_value();
  p.sequence = b.sequence.value_or(0);
  p.sequenceTextLength = static_cast<std::uint8_t>(b.sequenceText.size());
  ir::copyShort(p.sequenceText, b.sequenceText.data(), b.sequenceText.size());
  p.sequenceCol = b.sequenceRange.begin.col;
  p.sequenceLength = b.sequenceRange.length;
  p.firstWord = static_cast<std::uint32_t>(wordsUsed_);
  p.wordCount = static_cast<std::uint8_t>(n);
  wordsUsed_ += n;
  ++blocksUsed_;
  return true;
}

void PackedBlocks::unpack(std::size_t i, UnpackedBlock& to) const {
  ir::Block& out = to.block_;
  const Block& p = blocks_[i];
  // the reading thread wrote these lines: asked for some blocks ahead, they come over while this
  // thread executes the blocks before them
  constexpr std::size_t kAhead = 1024, kLine = 64;
  __builtin_prefetch(reinterpret_cast<const char*>(&p) + kAhead);
  const char* const words = reinterpret_cast<const char*>(words_.data() + p.firstWord) + kAhead;
  for (const char* at = words; at < words + p.wordCount * sizeof(Word); at += kLine)
    __builtin_prefetch(at);
  out.kind = p.kind;
  out.skipLevel = p.skipLevel;
  if (p.hasSequence) {
    out.sequence = p.sequence;
    ir::assignShort(out.sequenceText, p.sequenceText, p.sequenceTextLength);
    writeOnLine(out.sequenceRange, p.range.begin, p.sequenceCol, p.sequenceLength);
  } else {
    out.sequence.reset();
    out.sequenceText.clear();
    out.sequenceRange = {};
  }
  out.range = p.range;
  out.lastLine = p.lastLine;
  out.words.resize(p.wordCount); // a new slot: a literal with a new expression, no address
  const Word* q = words_.data() + p.firstWord;
  for (ir::Word& w : out.words) {
    if (w.address.size() == 1)
      w.address[0] = q->letter;
    else
      w.address.assign(1, q->letter);
    w.incremental = q->incremental;
    w.order = q->order;
    w.number = q->number;
    ir::assignShort(w.text, q->text, q->textLength);
    writeOnLine(w.range, p.range.begin, q->col, q->length);
    ++q;
  }
}

} // namespace gcx::cli
