#include "passes/check/static_checks.h"

#include <array>
#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"
#include "dialect/control_flow.h"
#include "machine/code_names.h"

namespace gcx::check {

namespace {
std::string formatNumber(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e15)
    return fmt::format("{}", static_cast<long long>(v));
  return fmt::format("{}", v);
}
} // namespace

void StaticChecker::block(const ir::Block& b) {
  // a file of `%name ... %` units (WL4): the lines that frame a unit stand anywhere
  const bool units = profile_.controlFlow && profile_.controlFlow->namedUnits;
  if (b.kind == ir::BlockKind::ProgramEnd || (units && b.kind == ir::BlockKind::ProgramStart))
    return;
  if (b.kind == ir::BlockKind::ProgramStart) {
    // `%` opens (and by Fanuc habit may close) a tape; between blocks it is an error
    if (blocks_ > 0 && !percentAfterStart_) percentAfterStart_ = b.range;
    if (blocks_ == 0) startBeforeBlocks_ = true;
    return;
  }
  if (percentAfterStart_ && !b.empty()) {
    diags_.error(diag::code::MisplacedPercent, SourceRange{percentAfterStart_->begin, 1},
                 "'%' may only open or close the program");
    percentAfterStart_.reset();
  }
  if (b.kind == ir::BlockKind::Data) {
    dataRecord(b);
    return;
  }
  if (!b.empty()) ++blocks_;
  if (b.sequence) {
    if (*b.sequence < profile_.minSequenceNumber || *b.sequence > profile_.maxSequenceNumber)
      diags_.error(diag::code::DataOutOfRange, b.sequenceRange,
                   fmt::format("block number N{} is out of range {}-{}", *b.sequence,
                               profile_.minSequenceNumber, profile_.maxSequenceNumber));
    labels_.insert(*b.sequence);
  }
  for (const ir::Stmt& s : b.stmts) {
    statement(s);
    for (const ir::Expr* e : {&s.target, &s.value})
      finiteLiterals(*e);
    if (s.cond) finiteLiterals(s.cond->lhs), finiteLiterals(s.cond->rhs);
    for (const ir::Word& a : s.args)
      if (!a.isLiteral()) finiteLiterals(a.expr);
  }
  words(b);
}

// A number no double holds (a literal of 400 digits) would be read as infinity and printed as
// `inf`, which no dialect reads: an error where it is written, in an expression as in a word.
void StaticChecker::finiteLiterals(const ir::Expr& e) {
  if (e.kind == ir::ExprKind::Number && !std::isfinite(e.number))
    diags_.error(diag::code::DataOutOfRange, e.range,
                 "the number is beyond the range of a double (about 1.8e308)");
  for (const ir::Expr& a : e.args)
    finiteLiterals(a);
}

namespace {
// A whole number by one conversion, where that is exact (no library call for floor).
bool plainlyWhole(double v) {
  return std::fabs(v) < 1e15 && v == static_cast<double>(static_cast<std::int64_t>(v));
}
} // namespace

// The usual word passes at a glance; one that may not is looked at by literalFindings.
inline void StaticChecker::literal(const ir::Word& w, const AddressSpec& spec) {
  const double v = w.number;
  if ((spec.decimal || plainlyWhole(v)) && (spec.sign || !std::signbit(v)) && v >= spec.min &&
      v <= spec.max)
    return;
  literalFindings(w, spec);
}

void StaticChecker::literalFindings(const ir::Word& w, const AddressSpec& spec) {
  const double v = w.number;
  if (!spec.decimal && v != std::floor(v)) {
    diags_.error(diag::code::SyntaxError, w.range,
                 fmt::format("address {} takes a whole number, not {}", w.address, v));
    return;
  }
  if (std::signbit(v) && !spec.sign) { // signbit: `G-0` is refused too
    diags_.error(diag::code::DataOutOfRange, w.range,
                 fmt::format("address {} takes no sign: {}-{}", w.address, w.address,
                             formatNumber(std::fabs(v))));
    return;
  }
  if (v < spec.min || v > spec.max)
    diags_.error(diag::code::DataOutOfRange, w.range,
                 fmt::format("{}{} is out of range: {} takes {}-{}", w.address, formatNumber(v),
                             w.address, formatNumber(spec.min), formatNumber(spec.max)));
}

void StaticChecker::words(const ir::Block& b) {
  bool callBlock = false;
  for (const ir::Word& w : b.words)
    callBlock |= w.is('G') && w.isLiteral() && profile_.macroCallGCode(w.number);

  std::uint64_t groupSeen = 0; // modal groups used in this block, by bit
  int gCount = 0, mCount = 0, exclusiveM = 0;
  auto& counts = wordCounts_; // a member: its capacity serves every block
  counts.clear();
  std::uint32_t lettersSeen = 0; // one-letter addresses, the usual words, by bit
  // true for an address written before in this block; letter: its one letter A-Z, or 0
  auto again = [&](char letter, std::string_view a) {
    if (letter) {
      const std::uint32_t bit = std::uint32_t{1} << (letter - 'A');
      const bool seen = lettersSeen & bit;
      lettersSeen |= bit;
      return seen;
    }
    for (auto& [addr, n] : counts)
      if (addr.size() == a.size() && (a.size() == 1 ? addr[0] == a[0] : addr == a)) return ++n > 1;
    counts.emplace_back(a, 1);
    return false;
  };

  if (callBlock) callArguments(b);
  for (const ir::Word& w : b.words) {
    // nearly every address is one letter: read it once
    const char letter =
        w.address.size() == 1 && w.address[0] >= 'A' && w.address[0] <= 'Z' ? w.address[0] : 0;
    const AddressSpec* spec = letter ? profile_.letterAddress(letter) : profile_.address(w.address);
    if (!spec) {
      diags_.error(diag::code::ForbiddenAddress, w.range,
                   fmt::format("unknown address '{}'", w.address));
      continue;
    }
    if (w.incremental && !spec->incremental) {
      diags_.error(callBlock ? diag::code::SyntaxError : diag::code::IncrementalNotAllowed, w.range,
                   fmt::format("the incremental operator I is not allowed after {}", w.address));
    }
    if (w.isLiteral())
      literal(w, *spec);
    else
      finiteLiterals(w.expr);
    const bool repeated = again(letter, w.address);
    if (letter == 'G') {
      ++gCount;
      if (callBlock && gCount > 1) {
        diags_.error(diag::code::ForbiddenAddress, w.range,
                     "a second G code in a macro call block (nct-macro.md §1.4 K4)");
        continue;
      }
      if (!w.isLiteral()) continue;
      const GCodeSpec* g = profile_.gcode(w.number);
      if (!g) {
        // a macro call defined by a machine setting is legal; only the machine setup knows
        diags_.warning(diag::code::UnknownGCode, w.range,
                       fmt::format("G{} is not in the G-code table; it must be configured as a "
                                   "macro call",
                                   formatNumber(w.number)));
        continue;
      }
      // the words after a cycle code are its parameters, a set of their own: FMS `X30 Y10 G88
      // U2 Z-10 X0.2 Y-0.1` positions at X30 Y10, then shifts by X0.2 Y-0.1 (fms3000.md §5.1)
      if (g->action == GAction::LevelDrillCycle) {
        counts.clear();
        lettersSeen = 0;
      }
      if (g->group > 0 && g->group < 64 && !profile_.lastOfModalGroupWins) {
        const std::uint64_t bit = std::uint64_t{1} << g->group;
        const bool seen = groupSeen & bit;
        groupSeen |= bit;
        if (seen)
          diags_.error(diag::code::ModalGroupConflict, w.range,
                       fmt::format("G{} is the second code of modal group {} in this block",
                                   formatNumber(w.number), g->group));
      }
      continue;
    }
    if (letter == 'M') {
      if (callBlock) continue; // in a call block M is argument #13
      if (++mCount == profile_.maxMCodesPerBlock + 1)
        diags_.error(diag::code::ConflictingMCodes, w.range,
                     fmt::format("more than {} M codes in one block", profile_.maxMCodesPerBlock));
      if (w.isLiteral())
        for (int m : profile_.exclusiveMCodes)
          if (w.number == m && ++exclusiveM == 2)
            diags_.error(diag::code::ConflictingMCodes, w.range,
                         fmt::format("conflicting spindle M codes: {} exclude each other",
                                     machine::mCodeList(profile_.exclusiveMCodes)));
      continue;
    }
    if (!repeated || spec->repeatable || callBlock) continue; // call blocks: see below
    diags_.error(diag::code::RepeatedAddress, w.range,
                 fmt::format("address {} appears twice in one block", w.address));
  }
}

void StaticChecker::callArguments(const ir::Block& b) {
  if (profile_.checkCallArguments) profile_.checkCallArguments(b, diags_);
}

void StaticChecker::dataRecord(const ir::Block& b) {
  // the dialect's record format: number, bit word, value word (Profile::dataRecord)
  const DataRecordFormat& format = profile_.dataRecord;
  if (b.empty()) return;
  if (b.sequence && (*b.sequence < 0 || *b.sequence > format.maxNumber))
    diags_.error(
        diag::code::DataOutOfRange, b.sequenceRange,
        fmt::format("parameter number {} is out of range 0-{}", *b.sequence, format.maxNumber));
  bool hasValue = false;
  for (const ir::Word& w : b.words) {
    if (format.valueWord && w.is(format.valueWord))
      hasValue = true;
    else if (format.bitWord && w.is(format.bitWord) && w.isLiteral() &&
             (w.number < 0 || w.number > format.maxBit))
      diags_.error(diag::code::DataOutOfRange, w.range,
                   fmt::format("bit number {} must be 0-{}", format.bitWord, format.maxBit));
    else if (w.address.size() != 1 || format.words.find(w.address[0]) == std::string::npos)
      diags_.error(diag::code::ForbiddenAddress, w.range,
                   fmt::format("address {} is not allowed in a {}", w.address, format.name));
  }
  if (!hasValue && b.sequence)
    diags_.error(diag::code::MissingData, b.range,
                 fmt::format("parameter record without {} value", format.valueWord));
}

void StaticChecker::statement(const ir::Stmt& s) {
  switch (s.kind) {
  case ir::StmtKind::While:
  case ir::StmtKind::Do: {
    if (s.loopId < 1 || s.loopId > 3) // still paired below, so its END does not cascade
      diags_.error(diag::code::DataOutOfRange, s.loopRange,
                   fmt::format("DO{} is out of range: loop numbers are 1-3", s.loopId));
    for (const OpenLoop& l : loops_)
      if (l.id == s.loopId) {
        diags_.error(diag::code::LoopPairing, s.loopRange,
                     fmt::format("DO{} is already open (nct-macro.md §4.4 W6)", s.loopId));
        break; // still pushed, so the two END's pair without cascading errors
      }
    loops_.push_back({s.loopId, s.loopRange});
    return;
  }
  case ir::StmtKind::End: {
    bool open = false;
    for (const OpenLoop& l : loops_)
      open |= l.id == s.loopId;
    if (!open) {
      diags_.error(diag::code::BlockNotFound, s.range,
                   fmt::format("END{} without DO{}", s.loopId, s.loopId));
      return;
    }
    if (loops_.back().id != s.loopId) {
      diags_.error(diag::code::LoopPairing, s.range,
                   fmt::format("END{} closes DO{} while DO{} inside it is still open (loops must "
                               "nest)",
                               s.loopId, s.loopId, loops_.back().id));
    }
    // drop only the loop END closes, so the inner one still pairs with its own END
    for (auto it = loops_.rbegin(); it != loops_.rend(); ++it)
      if (it->id == s.loopId) {
        loops_.erase(std::next(it).base());
        break;
      }
    return;
  }
  case ir::StmtKind::Goto:
  case ir::StmtKind::IfGoto:
    if (s.value.kind == ir::ExprKind::Number)
      jumps_.push_back({static_cast<std::int64_t>(std::llround(s.value.number)), s.range,
                        s.kind == ir::StmtKind::IfGoto});
    return;
  default:
    return;
  }
}

bool StaticChecker::join(StaticChecker&& next, std::int64_t lineShift) {
  // what a block's checks read of the blocks before: the open loops, a '%' waiting for the next
  // block, and whether any block came before (a '%' after blocks is suspect)
  if (!loops_.empty() || percentAfterStart_ || (blocks_ > 0 && next.startBeforeBlocks_))
    return false;
  auto shift = [lineShift](SourceRange& r) {
    if (r.begin.valid()) r.begin.line = static_cast<std::uint32_t>(r.begin.line + lineShift);
  };
  for (OpenLoop& l : next.loops_)
    shift(l.where);
  for (Jump& j : next.jumps_)
    shift(j.where);
  if (next.percentAfterStart_) shift(*next.percentAfterStart_);
  startBeforeBlocks_ = startBeforeBlocks_ || (blocks_ == 0 && next.startBeforeBlocks_);
  blocks_ += next.blocks_;
  percentAfterStart_ = next.percentAfterStart_;
  loops_ = std::move(next.loops_);
  jumps_.insert(jumps_.end(), next.jumps_.begin(), next.jumps_.end());
  labels_.merge(next.labels_);
  return true;
}

void StaticChecker::finish(FileId file, bool hadBadBlocks) {
  for (const OpenLoop& l : loops_)
    diags_.error(diag::code::LoopPairing, l.where,
                 fmt::format("DO{} without END{} in this file", l.id, l.id));
  loops_.clear();
  for (const Jump& j : jumps_) {
    if (labels_.count(j.target)) continue;
    if (j.conditional) // legal until taken: the run stops with 2125 if it ever is (§4.2)
      diags_.warning(diag::code::BlockNotFound, j.where,
                     fmt::format("block N{} not found in this file: alarm 2125 if the jump is "
                                 "taken",
                                 j.target));
    else
      diags_.error(diag::code::BlockNotFound, j.where,
                   fmt::format("block N{} not found in this file", j.target));
  }
  jumps_.clear();
  if (blocks_ == 0 && !hadBadBlocks)
    diags_.error(diag::code::EmptyProgram, SourceRange{SourceLoc{file, 1, 1, 0}, 0},
                 "the program has no blocks");
}

} // namespace gcx::check
