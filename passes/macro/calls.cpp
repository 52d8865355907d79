// Calls and returns with repeat counts (nct-macro.md §5.1-§5.4): which program a remapped code
// calls, the callee's local frame (shared, bound from arguments, or a copy), how often it runs,
// and where the caller continues.
#include <algorithm>
#include <fmt/format.h>
#include <map>

#include "diag/codes.h"
#include "emit/number.h"
#include "passes/macro/cycle_macro.h"
#include "passes/macro/expander.h"

namespace gcx::macro {

namespace {

std::string codeText(const ir::Word& w) {
  return w.address + emit::formatNumber(w.number);
}

// `#1`, `-#1`, `#[e]`, `#_NAME`: a reference whose vacancy an argument keeps
bool bareReference(const ir::Expr& e) {
  const ir::Expr* x = &e;
  if (x->kind == ir::ExprKind::Unary && x->op != ir::Op::Not) x = &x->args[0];
  return x->kind == ir::ExprKind::Variable || x->kind == ir::ExprKind::Indirect ||
         x->kind == ir::ExprKind::Named;
}

} // namespace

bool Expander::tooDeep(const SourceRange& where) {
  const int limit =
      flow_.maxCallDepth > 0 ? std::min(flow_.maxCallDepth, limits_.maxDepth) : limits_.maxDepth;
  if (static_cast<int>(stack_.size()) <= limit) return false;
  fail(diag::code::CallNesting, where,
       fmt::format("more than {} nested subprogram and macro calls", limit));
  return true;
}

std::string Expander::describe(const CodeMatch& m, const std::string& unit) const {
  if (!m.program && m.file)
    return fmt::format("{} ({} <{}>)", m.file->text, codeText(*m.code), m.file->text);
  if (m.program)
    return fmt::format("{} ({} {}{})", library_.label(unit), codeText(*m.code), m.program->address,
                       static_cast<std::int64_t>(m.program->number));
  return fmt::format("{} ({})", library_.label(unit), codeText(*m.code));
}

bool Expander::bind(const CallSite& site, std::vector<Value>& args) {
  // argument values from the source words: a vacant bare reference leaves its local vacant
  std::map<const ir::Word*, Value> values;
  for (const ir::Word& w : site.block->words) {
    if (w.kind == ir::ValueKind::Number) {
      values[&w] = Value::of(w.number);
    } else if (w.kind == ir::ValueKind::Expression) {
      auto v = eval_.value(w.expr);
      if (!v) return false;
      if (!bareReference(w.expr) && v->vacant) *v = Value::of(0); // [e] is always a number
      values[&w] = *v;
    }
  }
  CallSite s = site;
  s.vacant = [&](const ir::Word& w) {
    auto it = values.find(&w);
    return it != values.end() && it->second.vacant;
  };
  args.assign(frames_.size(), Value{});
  if (!flow_.bindArguments) return true;
  const CallArguments bound = flow_.bindArguments(s);
  if (!bound.ok()) return fail(bound.code, bound.offending->range, bound.message);
  for (const ArgumentBinding& a : bound.bindings) {
    if (a.variable < 0 || static_cast<std::size_t>(a.variable) >= args.size()) continue;
    Value v;
    if (a.literal) {
      v = Value::of(*a.literal);
    } else if (a.word && !a.vacant) {
      auto it = values.find(a.word);
      v = it != values.end()    ? it->second
          : a.word->isLiteral() ? Value::of(a.word->number)
                                : Value::empty();
    }
    args[a.variable] = v;
  }
  return true;
}

bool Expander::call(Frame& f, const ir::Block& b, const CodeMatch& m) {
  const Remap& r = *m.row;
  std::string unit;
  std::optional<long> digitTimes;
  if (r.program == ProgramSource::Word) {
    if (!m.program && !m.file)
      return fail(diag::code::MissingData, m.code->range,
                  fmt::format("{} without {} or <file>", codeText(*m.code), r.programWord));
    if (m.program) unit = programDigits(*m.program);
  } else {
    const ProgramCall pc = programFromDigits(r, programDigits(*m.code));
    unit = pc.unit;
    digitTimes = pc.times;
  }
  const std::int64_t times =
      m.repeat ? static_cast<std::int64_t>(m.repeat->number) : digitTimes.value_or(1);
  if (!r.repeatBelowOneRule.empty()) {
    if (times < 1)
      return fail(diag::code::DataOutOfRange, (m.repeat ? m.repeat : m.code)->range,
                  fmt::format("{} {} must be 1 or more ({})", codeText(*m.code), r.repeatWord,
                              r.repeatBelowOneRule));
    if (tooDeep(b.range)) return false;
  } else {
    if (tooDeep(b.range)) return false;
    if (times < 1) // no run at all
      return advance(f);
  }
  std::vector<Value> args;
  if (r.frame == LocalFrame::Arguments) {
    CallSite site;
    site.block = &b;
    site.callCode = m.code->number;
    site.programWord = m.program;
    if (!bind(site, args)) return false;
  }
  // a system cycle written as a macro: its checks come before the call (cycles.md §5)
  if (r.action == FlowAction::CallCycle && m.program)
    if (const CycleMacro* c =
            machine_.profile().cycleMacro(static_cast<std::int64_t>(m.program->number)))
      if (!checkCycleMacroCall(*c, {b, *m.code, *m.program, args, *f.program}, machine_, library_,
                               diags_))
        return false;
  const LoadedProgram* callee =
      !unit.empty() ? library_.byUnit(unit, *f.program, (m.program ? m.program : m.code)->range)
                    : library_.byName(m.file->text, *f.program, m.file->range);
  if (!callee) return false;
  machine_.setCalledProgram(m.program ? static_cast<int>(m.program->number) : 0);
  // a shared-frame call sees every modal call again; a macro sees what its caller sees
  // an open cycle's program sees none: it runs as one block of its caller (wl4.md §5.1)
  const std::size_t visible = r.action == FlowAction::CallOpenCycle ? 0
                              : r.frame == LocalFrame::Shared       ? static_cast<std::size_t>(-1)
                                                                    : f.modalVisible;
  return pushFrame(f, callee, r.frame, std::move(args), times, describe(m, unit), b.range, visible);
}

bool Expander::pushFrame(Frame& f, const LoadedProgram* program, LocalFrame frame,
                         std::vector<Value> args, std::int64_t times, std::string what,
                         const SourceRange& site, std::size_t modalVisible) {
  if (tooDeep(site)) return false;
  Frame c;
  c.program = program;
  c.remaining = times - 1;
  c.callBlock = f.pc;
  c.callSite = site.begin;
  c.what = std::move(what);
  c.modalVisible = modalVisible;
  c.level = f.level;
  if (frame == LocalFrame::Copy) args = frames_.copy(f.level);
  if (frame != LocalFrame::Shared) {
    c.ownLocals = true;
    c.level = frames_.push(args);
    c.args = std::move(args);
  }
  stack_.push_back(std::move(c));
  return true;
}

bool Expander::returnFromCall(Frame& f, const ir::Block& flat, const CodeMatch& m) {
  const ir::Word* p = m.program; // where the caller continues (§5.2 R4)
  const ir::Word* l = m.repeat;  // how often the callee runs again (§5.2 R5)
  if (stack_.size() == 1 && flow_.returnInMainError)
    return fail(
        flow_.returnInMainError, m.code->range,
        fmt::format("{} in the main program: there is no call to return from", codeText(*m.code)));
  if (stack_.size() == 1 && flow_.returnInMainEnds) {
    machine_.finish();
    done_ = true;
    return true;
  }
  if (stack_.size() == 1) {
    // a return in the main program: back to its start or to the block P (§5.2 R6), endlessly
    if (++jumps_ > limits_.maxJumps)
      return fail(diag::code::RunawayLoop, flat.range,
                  fmt::format("{} in the main program looped more than {} times (exceeded "
                              "--max-jumps {}; raise it with --max-jumps N)",
                              codeText(*m.code), limits_.maxJumps, limits_.maxJumps));
    if (!p) {
      f.pc = 0;
      return true;
    }
    const std::size_t t = f.program->find(static_cast<std::int64_t>(p->number), 0);
    if (t == LoadedProgram::npos)
      return fail(diag::code::BlockNotFound, p->range,
                  fmt::format("block N{} not found", emit::formatNumber(p->number)));
    f.pc = t;
    return true;
  }
  if (l) f.remaining = static_cast<std::int64_t>(l->number); // §5.2 R5
  if (f.remaining > 0) {
    // each repetition jumps back to the start of the called program
    if (++jumps_ > limits_.maxJumps)
      return fail(diag::code::RunawayLoop, flat.range,
                  fmt::format("{} repeated more than {} times by its L count (exceeded "
                              "--max-jumps {}; raise it with --max-jumps N)",
                              f.what, limits_.maxJumps, limits_.maxJumps));
    --f.remaining;
    f.pc = 0;
    f.loops.clear();
    if (f.ownLocals) frames_.load(f.level, f.args); // each run starts from the arguments (C2)
    return true;
  }
  const std::size_t callBlock = f.callBlock;
  if (f.ownLocals) frames_.pop(); // V3: the caller's frame is visible again
  stack_.pop_back();
  Frame& caller = stack_.back();
  if (p) {
    const std::size_t t = caller.program->find(static_cast<std::int64_t>(p->number), callBlock + 1);
    if (t == LoadedProgram::npos)
      return fail(
          diag::code::BlockNotFound, p->range,
          fmt::format("block N{} not found in the calling program", emit::formatNumber(p->number)));
    caller.pc = t;
    return true;
  }
  caller.pc = callBlock; // the calling block ends: its jump, or the next block
  return advance(caller);
}

} // namespace gcx::macro
