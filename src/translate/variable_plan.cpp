#include "translate/variable_plan.h"

#include <fmt/format.h>
#include <set>

namespace gcx::xlate {

namespace {

void forEachIn(const ir::Expr& e, const std::function<void(int, const SourceRange&, bool)>& f) {
  if (e.kind == ir::ExprKind::Variable) f(static_cast<int>(e.number), e.range, false);
  for (const ir::Expr& a : e.args)
    forEachIn(a, f);
}

void forEachInFlow(const Flow& fl, const std::function<void(int, const SourceRange&, bool)>& f) {
  if (fl.kind == FlowKind::Assign) {
    f(static_cast<int>(fl.target.number), fl.range, true);
    forEachIn(fl.value, f);
  }
  if (fl.condition) forEachIn(*fl.condition, f);
}

bool isLocal(const VariableSpace& s, int n) {
  return n >= s.localFirst && n <= s.localLast;
}
bool isCommon(const VariableSpace& s, int n) {
  return n >= s.commonFirst && n <= s.commonLast;
}

} // namespace

void forEachVariable(const Step& s, const std::function<void(int, const SourceRange&, bool)>& f) {
  for (const Flow& fl : s.before)
    forEachInFlow(fl, f);
  if (s.guard) forEachIn(*s.guard, f);
  for (const Operand& o : s.words)
    if (!o.value.literal) forEachIn(o.value.expr, f);
  if (s.dwellSeconds && !s.dwellSeconds->literal) forEachIn(s.dwellSeconds->expr, f);
  for (const Flow& fl : s.after)
    forEachInFlow(fl, f);
  if (s.otherwise) forEachVariable(*s.otherwise, f);
}

bool planVariables(const std::vector<UnitSteps>& units, const ControlFlow& source,
                   const ControlFlow& target, int counters, VariablePlan& plan, Unkept& why) {
  std::map<int, SourceRange> used; // first use of each variable
  std::set<int> read, written;
  std::optional<SourceRange> localInCallee, localReadInCallee;
  for (const UnitSteps& u : units)
    for (const Step& s : u.steps)
      forEachVariable(s, [&](int n, const SourceRange& at, bool write) {
        used.emplace(n, at);
        (write ? written : read).insert(n);
        if (write && !u.main && isLocal(source.variables, n) && !localInCallee) localInCallee = at;
        if (!write && !u.main && isLocal(source.variables, n) && !localReadInCallee)
          localReadInCallee = at;
      });
  if (used.empty() && counters == 0) return true;
  if (!target.hasVariables) {
    const auto& [n, at] = *used.begin();
    why = {at, fmt::format("#{}", n), "the target has no variables"};
    return false;
  }
  const VariableSpace& from = source.variables;
  const VariableSpace& to = target.variables;
  // a callee that shares its caller's locals (NCT M98) on a control whose calls copy them (WL4
  // L): the locals become the target's common variables, which every level shares
  const bool localsToCommons =
      source.callFrame == LocalFrame::Shared && target.callFrame != LocalFrame::Shared;
  if (source.callFrame != LocalFrame::Shared && target.callFrame == LocalFrame::Shared &&
      localInCallee) {
    why = {*localInCallee, "a local variable written in a called program",
           "the source's callee writes its own copy of the caller's locals, the target's the "
           "caller's own"};
    return false;
  }
  // a callee that reads a copy of its caller's locals (WL4 L) on a control whose calls start
  // with locals of their own (LinuxCNC o-call)
  if (source.callFrame == LocalFrame::Copy && target.callFrame == LocalFrame::Arguments &&
      localReadInCallee) {
    why = {*localReadInCallee, "a caller's local variable read in a called program",
           "the source's callee reads a copy of its caller's locals, the target's its own"};
    return false;
  }
  std::set<int> taken;
  const auto take = [&](int preferred, bool local) -> std::optional<int> {
    const int first = local ? to.localFirst : to.commonFirst;
    const int last = local ? to.localLast : to.commonLast;
    if (preferred >= first && preferred <= last && !taken.count(preferred)) return preferred;
    for (int n = first; n <= last; ++n)
      if (!taken.count(n)) return n;
    return std::nullopt;
  };
  for (const auto& [n, at] : used) {
    const bool local = isLocal(from, n);
    if (!local && !isCommon(from, n)) {
      why = {at, fmt::format("#{}", n), "a system variable of the source's control"};
      return false;
    }
    if (from.vacant && !to.vacant && read.count(n) && !written.count(n)) {
      why = {at, fmt::format("#{}", n),
             "it is read and never written: vacant in the source, 0 in the target"};
      return false;
    }
    const std::optional<int> t = take(n, local && !localsToCommons);
    if (!t) {
      why = {at, fmt::format("#{}", n), "the target's variables are all taken"};
      return false;
    }
    taken.insert(*t);
    plan.renumber[n] = *t;
    if (!from.vacant && to.vacant && read.count(n)) plan.zeroAtStart.push_back(*t);
  }
  // counters from the top of the locals down, one per loop: the machine's commons may be kept
  // between runs (NCT #500-#999), and a loop's count is its own either way
  for (int n = to.localLast;
       n >= to.localFirst && static_cast<int>(plan.counters.size()) < counters; --n)
    if (!taken.count(n)) plan.counters.push_back(n);
  if (static_cast<int>(plan.counters.size()) < counters) {
    why = {{}, "a counted loop", "the target has no free variable for its count"};
    return false;
  }
  return true;
}

} // namespace gcx::xlate
