#include "translate/program_calls.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "dialect/control_flow.h"

namespace gcx::xlate {

namespace {

void addOnce(std::vector<std::string>& v, std::string s) {
  if (std::find(v.begin(), v.end(), s) == v.end()) v.push_back(std::move(s));
}

bool callsAProgram(FlowAction a) {
  return a == FlowAction::CallSubprogram || a == FlowAction::CallMacro ||
         a == FlowAction::ModalCall || a == FlowAction::ModalCallEveryBlock;
}

// The digits of a literal that can name a program; none for a value no program number has (a
// dialect's reader rejects those, but this scan must not depend on it: the conversions below
// take whole numbers of at most 15 digits).
std::optional<std::string> nameDigits(const ir::Word* w) {
  if (!w || !w->isLiteral() || !(std::fabs(w->number) < 1e15)) return std::nullopt;
  std::string digits = programDigits(*w);
  if (digits.size() > 15) return std::nullopt;
  return digits;
}

// The program a call row names in block b, when it is written as a literal.
std::optional<std::string> calledUnit(const Remap& r, const ir::Word& code, const ir::Block& b) {
  switch (r.program) {
  case ProgramSource::Word:
  case ProgramSource::CodeDigits: {
    const std::optional<std::string> digits =
        nameDigits(r.program == ProgramSource::Word ? b.find(r.programWord) : &code);
    if (!digits) return std::nullopt;
    return programFromDigits(r, *digits).unit;
  }
  case ProgramSource::Fixed:
    return r.fixedProgram;
  case ProgramSource::None:
    break;
  }
  return std::nullopt;
}

std::string spelled(const ir::Word& w) {
  return w.address + (w.text.empty() ? fmt::format("{}", w.number) : w.text);
}

} // namespace

void CallScanner::end(bool byReturn, const ir::Word& w) {
  if (ended_) return;
  ended_ = true;
  out_.endsByReturn = byReturn;
  out_.endCode = spelled(w);
}

void CallScanner::block(const ir::Block& b) {
  const ControlFlow* flow = profile_.controlFlow;
  for (const ir::Word& w : b.words) {
    if (w.kind == ir::ValueKind::Path) {
      addOnce(out_.files, w.text);
      continue;
    }
    if (!w.isLiteral()) continue;
    if (w.is('M'))
      if (const MCodeSpec* m = profile_.machine.mcode(static_cast<int>(w.number));
          m && (m->action == MAction::End || m->action == MAction::EndRewind))
        end(false, w);
    if (!flow || !flow->remaps.mayMatch(w.address)) continue;
    const Remap* r = flow->remaps.find(w.address, w.number);
    // a row that applies only to one program number (FMS-3000's M98 P...) is found with it
    if (r && r->programWord)
      if (const ir::Word* program = b.find(r->programWord); program && program->isLiteral())
        r = flow->remaps.find(w.address, w.number, program->number);
    if (!r || r->onlyIfProgramExists) continue;
    if (r->action == FlowAction::Return) end(true, w);
    if (r->action == FlowAction::EndProgram) end(false, w);
    if (callsAProgram(r->action))
      if (const std::optional<std::string> unit = calledUnit(*r, w, b)) addOnce(out_.units, *unit);
  }
  for (const ir::Stmt& s : b.stmts)
    if (s.kind == ir::StmtKind::Call && !s.callee.empty()) addOnce(out_.units, s.callee);
}

} // namespace gcx::xlate
