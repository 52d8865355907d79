// Blocks whose words and statements run left to right (WL4, wl4.md §1.9): each value is
// evaluated where it stands, an assignment takes effect at once, a guard `IF<p> (cond)` that
// fails drops the rest of the block, then the block's NC words run as one block, then its call
// (a Call statement), and after the call returns its jump (a Jump statement).
#include <fmt/format.h>

#include "diag/codes.h"
#include "emit/number.h"
#include "ir/items.h"
#include "passes/macro/expander.h"

namespace gcx::macro {

namespace {

bool orderedKind(ir::StmtKind k) {
  return k == ir::StmtKind::Assign || k == ir::StmtKind::Guard || k == ir::StmtKind::Jump ||
         k == ir::StmtKind::Call;
}

} // namespace

bool Expander::runsInOrder(const ir::Block& b) {
  // an NCT statement block (one statement, no words) keeps its own path
  if (b.stmts.empty()) return false;
  bool ordered = b.stmts.size() > 1 || !b.words.empty();
  for (const ir::Stmt& s : b.stmts) {
    if (!orderedKind(s.kind)) return false;
    ordered = ordered || s.kind != ir::StmtKind::Assign;
  }
  return ordered;
}

bool Expander::orderedBlock(Frame& f, const ir::Block& b) {
  ir::Block flat = b;
  flat.words.clear();
  flat.stmts.clear();
  const WordOptions opt = scanRemaps(b);
  BlockTail tail;
  bool ok = true, dropped = false;
  ir::forEachItem(b, [&](ir::ItemRef r) {
    if (!ok || dropped || r.kind == ir::ItemKind::Comment) return;
    if (r.kind == ir::ItemKind::Word) {
      ok = resolveWord(b.words[r.index], opt, flat);
      return;
    }
    const ir::Stmt& s = b.stmts[r.index];
    switch (s.kind) {
    case ir::StmtKind::Assign:
      ok = assign(s);
      break;
    case ir::StmtKind::Guard: { // false: the rest of the block is dropped (§6.5)
      const auto holds = eval_.guard(s.value, s.precision);
      ok = holds.has_value();
      dropped = ok && !*holds;
      break;
    }
    case ir::StmtKind::Call:
      ok = tailCall(f, s, tail);
      break;
    case ir::StmtKind::Jump:
      ok = tailJump(f, s, tail);
      break;
    default: // runsInOrder admits no other statement
      break;
    }
  });
  if (!ok) return false;
  f.tail = std::move(tail);
  return ncFlat(f, b, flat);
}

bool Expander::tailCall(const Frame& f, const ir::Stmt& s, BlockTail& tail) {
  const auto times = eval_.number(s.value);
  if (!times) return false;
  const LoadedProgram* callee = library_.byUnit(s.callee, *f.program, s.range);
  if (!callee) return false;
  tail.call = callee; // the last call of a block wins, as a repeated address does (§1.3)
  tail.times = static_cast<std::int64_t>(roundHalfAway(*times));
  tail.what = tail.times == 1 ? library_.label(s.callee)
                              : fmt::format("{} ({} times)", library_.label(s.callee), tail.times);
  tail.site = s.range;
  return true;
}

bool Expander::tailJump(const Frame& f, const ir::Stmt& s, BlockTail& tail) {
  const auto n = eval_.number(s.value);
  if (!n) return false;
  const std::int64_t label = static_cast<std::int64_t>(roundHalfAway(*n));
  // the label's blocks in the running program; a block number that is no label does not count
  const LoadedProgram& p = *f.program;
  std::size_t target = LoadedProgram::npos;
  if (auto it = p.labels.find(label); it != p.labels.end())
    for (std::size_t i : it->second) {
      if (flow_.isLabel && !flow_.isLabel(p.blocks[i].sequenceText)) continue;
      if (target == LoadedProgram::npos || (target <= f.pc && i > f.pc)) target = i;
    }
  if (target == LoadedProgram::npos)
    return fail(diag::code::BlockNotFound, s.range,
                fmt::format("label {} not found in {}", label,
                            p.name.empty() ? std::string("the program") : library_.label(p.name)));
  tail.jump = target;
  return true;
}

bool Expander::errorStop(const Frame& f) {
  // a block with a message that jumps to itself never ends: the cycle programs stop this way
  // (the error blocks of WL4's %1, M0 and a message, wl4.md §5.3); the call is where to look.
  // A program stop that jumps to itself is the same stop without a text (wl4.md §7 example 7,
  // `N05 M0 N05`: "no touch: stop"). Any other block is an endless loop (the jump limit).
  const ir::Block& b = f.program->blocks[f.pc];
  std::string text;
  for (const ir::Comment& c : b.comments)
    if (c.kind == ir::CommentKind::Message) text = c.text;
  if (text.empty() && hasProgramStop(b))
    text = "a program stop that jumps to itself: the program cannot go on";
  if (text.empty()) return false;
  const SourceRange where = stack_.size() > 1 ? SourceRange{f.callSite, 1} : b.range;
  fail(diag::code::ErrorStop, where,
       fmt::format("{} (the error stop of {})", text,
                   f.program->name.empty() ? std::string("the program")
                                           : library_.label(f.program->name)));
  return true;
}

bool Expander::hasProgramStop(const ir::Block& b) const {
  for (const ir::Word& w : b.words)
    if (w.is('M') && w.isLiteral())
      if (const MCodeSpec* m = machine_.profile().machine.mcode(static_cast<int>(w.number));
          m && m->action == MAction::Stop)
        return true;
  return false;
}

bool Expander::advance(Frame& f) {
  if (const LoadedProgram* callee = std::exchange(f.tail.call, nullptr)) {
    if (f.tail.times < 1) return advance(f);
    const std::size_t visible =
        flow_.callFrame == LocalFrame::Shared ? static_cast<std::size_t>(-1) : f.modalVisible;
    return pushFrame(f, callee, flow_.callFrame, {}, f.tail.times, f.tail.what, f.tail.site,
                     visible); // the callee's return comes back here for the jump
  }
  const std::size_t target = std::exchange(f.tail.jump, LoadedProgram::npos);
  if (target == LoadedProgram::npos) {
    ++f.pc;
    return true;
  }
  if (target == f.pc && errorStop(f)) return false;
  if (target <= f.pc && ++jumps_ > limits_.maxJumps)
    return fail(diag::code::RunawayLoop, f.program->blocks[f.pc].range,
                fmt::format("more than {} backward jumps: runaway loop (exceeded --max-jumps {}; "
                            "raise it with --max-jumps N)",
                            limits_.maxJumps, limits_.maxJumps));
  f.pc = target;
  return true;
}

} // namespace gcx::macro
