// Statements that run in order or loop: assignments, IF THEN, WHILE / DO / END, prints and the
// periphery (nct-macro.md §4). Jumps are in jumps.cpp.
#include <algorithm>
#include <fmt/format.h>

#include "diag/codes.h"
#include "passes/macro/expander.h"

namespace gcx::macro {

bool Expander::statement(Frame& f, const ir::Block& b) {
  const ir::Stmt& s = b.stmts.front(); // an NCT block holds at most one
  switch (s.kind) {
  case ir::StmtKind::Assign:
    if (!assign(s)) return false;
    ++f.pc;
    return true;
  case ir::StmtKind::IfThen: {
    auto c = eval_.condition(*s.cond);
    if (!c) return false;
    if (*c && !assign(s)) return false;
    ++f.pc;
    return true;
  }
  case ir::StmtKind::Goto:
    return jumpTo(f, s.value, s.range);
  case ir::StmtKind::IfGoto: {
    auto c = eval_.condition(*s.cond);
    if (!c) return false;
    if (*c) return jumpTo(f, s.value, s.range);
    ++f.pc;
    return true;
  }
  case ir::StmtKind::While:
  case ir::StmtKind::Do:
    return loopHead(f, s);
  case ir::StmtKind::End:
    return loopBack(f, f.program->loopPartner[f.pc], s.loopRange);
  case ir::StmtKind::Print:
    if (!print(s)) return false;
    ++f.pc;
    return true;
  case ir::StmtKind::Popen: // the periphery: `%`, then the first DPRNT names the file
    periphery_ = Periphery::AwaitingName;
    ++f.pc;
    return true;
  case ir::StmtKind::Pclos:
    if (periphery_ == Periphery::Open && print_) *print_ << "%\r\n";
    periphery_ = Periphery::Closed;
    ++f.pc;
    return true;
  case ir::StmtKind::Fopen:
  case ir::StmtKind::Fclos: // the print channel is the run's print output (DPRNT)
    ++f.pc;
    return true;
  case ir::StmtKind::Guard: // other dialects' statements; the NCT front end never builds them
  case ir::StmtKind::Jump:
  case ir::StmtKind::Call:
  case ir::StmtKind::CycleCall:
    return fail(diag::code::NotImplemented, s.range,
                "this statement is not implemented by the macro pass yet");
  }
  return true;
}

// WHILE tests its condition on entry; DO alone loops until a jump leaves it
bool Expander::loopHead(Frame& f, const ir::Stmt& s) {
  bool enter = true;
  if (s.kind == ir::StmtKind::While) {
    auto c = eval_.condition(*s.cond);
    if (!c) return false;
    enter = *c;
  }
  const std::size_t here = f.pc;
  auto it =
      std::find_if(f.loops.begin(), f.loops.end(), [&](const Loop& l) { return l.head == here; });
  if (!enter) {
    if (it != f.loops.end()) f.loops.erase(it);
    f.pc = f.program->loopPartner[here] + 1; // after the paired END
    return true;
  }
  if (it == f.loops.end()) f.loops.push_back({here, 1});
  ++f.pc;
  return true;
}

bool Expander::loopBack(Frame& f, std::size_t head, const SourceRange& where) {
  if (++jumps_ > limits_.maxJumps)
    return fail(diag::code::RunawayLoop, where,
                fmt::format("loop DO{} repeated more than {} times (exceeded --max-jumps {}; "
                            "raise it with --max-jumps N)",
                            f.program->blocks[head].stmts.front().loopId, limits_.maxJumps,
                            limits_.maxJumps));
  // END returns to the test of its paired WHILE even when the loop was entered by GOTO (W7)
  auto it =
      std::find_if(f.loops.begin(), f.loops.end(), [&](const Loop& l) { return l.head == head; });
  if (it != f.loops.end())
    ++it->iteration;
  else
    f.loops.push_back({head, 2});
  const ir::Stmt& s = f.program->blocks[head].stmts.front();
  if (s.kind == ir::StmtKind::While) {
    auto c = eval_.condition(*s.cond);
    if (!c) return false;
    if (!*c) {
      f.loops.erase(std::find_if(f.loops.begin(), f.loops.end(),
                                 [&](const Loop& l) { return l.head == head; }));
      f.pc = f.program->loopPartner[head] + 1;
      return true;
    }
  }
  f.pc = head + 1;
  return true;
}

} // namespace gcx::macro
