#include "translate/counted_loops.h"

#include <algorithm>
#include <optional>

#include "translate/variable_plan.h"

namespace gcx::xlate {

namespace {

constexpr long kMaxCount = 1000000; // a longer loop is left as it is

const ir::Expr& unbracketed(const ir::Expr& e) {
  const ir::Expr* x = &e;
  while (x->kind == ir::ExprKind::Bracket)
    x = &x->args[0];
  return *x;
}

std::optional<double> literal(const ir::Expr& e) {
  const ir::Expr& x = unbracketed(e);
  if (x.kind == ir::ExprKind::Number) return x.number;
  if (x.kind == ir::ExprKind::Unary && x.op == ir::Op::Neg &&
      unbracketed(x.args[0]).kind == ir::ExprKind::Number)
    return -unbracketed(x.args[0]).number;
  return std::nullopt;
}

bool isVariable(const ir::Expr& e, int v) {
  const ir::Expr& x = unbracketed(e);
  return x.kind == ir::ExprKind::Variable && static_cast<int>(x.number) == v;
}

// A step that holds nothing but `flows`, its `before` or its `after` (comments aside).
bool only(const Step& s, const std::vector<Flow>& flows) {
  if (!s.label.empty() || s.guard || s.hasNcPart()) return false;
  const std::vector<Flow>& other = &flows == &s.before ? s.after : s.before;
  return other.empty();
}

// `v = c`: the variable and the value.
std::optional<std::pair<int, double>> setting(const Step& s) {
  const std::vector<Flow>& f = !s.before.empty() ? s.before : s.after;
  if (f.size() != 1 || f[0].kind != FlowKind::Assign || !only(s, f)) return std::nullopt;
  const std::optional<double> c = literal(f[0].value);
  if (!c) return std::nullopt;
  return std::pair{static_cast<int>(f[0].target.number), *c};
}

// `v = v + d` or `v = v - d`: the step d.
std::optional<double> stepOf(const Flow& f, int v) {
  if (f.kind != FlowKind::Assign || static_cast<int>(f.target.number) != v) return std::nullopt;
  const ir::Expr& e = unbracketed(f.value);
  if (e.kind != ir::ExprKind::Binary || (e.op != ir::Op::Add && e.op != ir::Op::Sub))
    return std::nullopt;
  if (!isVariable(e.args[0], v)) return std::nullopt;
  const std::optional<double> d = literal(e.args[1]);
  if (!d) return std::nullopt;
  return e.op == ir::Op::Add ? *d : -*d;
}

// Whether `v op c` (or `c op v`) holds for the counter's value x; nullopt when the condition is
// not such a comparison.
std::optional<bool> holds(const ir::Expr& condition, int v, double x) {
  const ir::Expr& c = unbracketed(condition);
  if (c.kind != ir::ExprKind::Binary) return std::nullopt;
  double a = 0, b = 0;
  if (isVariable(c.args[0], v) && literal(c.args[1])) {
    a = x;
    b = *literal(c.args[1]);
  } else if (literal(c.args[0]) && isVariable(c.args[1], v)) {
    a = *literal(c.args[0]);
    b = x;
  } else {
    return std::nullopt;
  }
  switch (c.op) {
  case ir::Op::Eq:
    return a == b;
  case ir::Op::Ne:
    return a != b;
  case ir::Op::Lt:
    return a < b;
  case ir::Op::Le:
    return a <= b;
  case ir::Op::Gt:
    return a > b;
  case ir::Op::Ge:
    return a >= b;
  default:
    return std::nullopt;
  }
}

// How often the body runs: tested before each pass (WHILE) or after it (a jump back).
std::optional<long> count(const ir::Expr& condition, int v, double start, double step,
                          bool testFirst) {
  double x = start;
  long n = 0;
  while (n <= kMaxCount) {
    if (testFirst || n > 0) {
      const std::optional<bool> h = holds(condition, v, x);
      if (!h) return std::nullopt;
      if (!*h) return n;
    }
    ++n;
    x += step;
  }
  return std::nullopt;
}

// Whether variable v is read or written in steps [from, to) other than those skipped.
bool usedElsewhere(const UnitSteps& u, int v, const std::vector<std::size_t>& counterSteps) {
  bool used = false;
  for (std::size_t i = 0; i < u.steps.size(); ++i) {
    if (std::find(counterSteps.begin(), counterSteps.end(), i) != counterSteps.end()) continue;
    forEachVariable(u.steps[i], [&](int n, const SourceRange&, bool) { used = used || n == v; });
  }
  return used;
}

bool jumpedToElsewhere(const UnitSteps& u, const std::string& label, std::size_t except) {
  for (std::size_t i = 0; i < u.steps.size(); ++i)
    for (const Flow& f : u.steps[i].after)
      if (i != except && f.kind == FlowKind::Jump && f.label == label) return true;
  return false;
}

Step marker(const Step& from, FlowKind kind, long times) {
  Step s;
  s.range = from.range;
  s.comments = from.comments;
  Flow f;
  f.kind = kind;
  f.times = times;
  f.range = from.range;
  s.after.push_back(f);
  return s;
}

// init; WHILE [v op c] ...; v = v + d; END
bool whileLoop(UnitSteps& u, std::size_t i) {
  const std::optional<std::pair<int, double>> init = setting(u.steps[i]);
  if (!init || i + 1 >= u.steps.size()) return false;
  const Step& head = u.steps[i + 1];
  if (head.before.size() != 1 || head.before[0].kind != FlowKind::WhileStart ||
      !only(head, head.before))
    return false;
  const int loop = head.before[0].loop;
  std::size_t end = i + 2;
  while (end < u.steps.size() &&
         !(u.steps[end].after.size() == 1 && u.steps[end].after[0].kind == FlowKind::WhileEnd &&
           u.steps[end].after[0].loop == loop))
    ++end;
  if (end >= u.steps.size() || end < i + 4 || !only(u.steps[end], u.steps[end].after)) return false;
  const Step& inc = u.steps[end - 1];
  const std::vector<Flow>& incFlow = !inc.before.empty() ? inc.before : inc.after;
  if (incFlow.size() != 1 || !only(inc, incFlow)) return false;
  const std::optional<double> step = stepOf(incFlow[0], init->first);
  if (!step) return false;
  const std::optional<long> n =
      count(*head.before[0].condition, init->first, init->second, *step, true);
  if (!n || *n < 1 || usedElsewhere(u, init->first, {i, i + 1, end - 1})) return false;
  const Step start = marker(u.steps[i], FlowKind::RepeatStart, *n);
  const Step last = marker(u.steps[end], FlowKind::RepeatEnd, 0);
  u.steps[end] = last;
  u.steps.erase(u.steps.begin() + static_cast<std::ptrdiff_t>(end - 1));
  u.steps.erase(u.steps.begin() + static_cast<std::ptrdiff_t>(i + 1));
  u.steps[i] = start;
  return true;
}

// init; Nlabel ...; [v = v + d;] IF (v op c) jump to the label
bool jumpLoop(UnitSteps& u, std::size_t i) {
  const std::optional<std::pair<int, double>> init = setting(u.steps[i]);
  if (!init || i + 1 >= u.steps.size() || u.steps[i + 1].label.empty()) return false;
  const std::string label = u.steps[i + 1].label;
  const int v = init->first;
  for (std::size_t k = i + 2; k < u.steps.size(); ++k) {
    const Step& s = u.steps[k];
    if (s.after.size() != 1 || s.after[0].kind != FlowKind::Jump || s.after[0].label != label)
      continue;
    // the condition: a guard on a lone jump (WL4) or the jump's own (NCT IF [c] GOTO)
    const std::optional<ir::Expr> cond = s.after[0].condition ? s.after[0].condition : s.guard;
    if (!cond || (s.guard && s.after[0].condition) || s.hasNcPart() || !s.label.empty())
      return false;
    std::optional<double> step;
    std::vector<std::size_t> counterSteps = {i, k};
    if (s.before.size() == 1) {
      step = stepOf(s.before[0], v);
    } else if (s.before.empty() && k >= i + 2) {
      // the step before: the counter's step alone, or as the last thing after its NC part
      const Step& inc = u.steps[k - 1];
      const std::vector<Flow>& f = !inc.before.empty() ? inc.before : inc.after;
      const bool labelOk = inc.label.empty() || k - 1 == i + 1; // the body's first step
      if (f.size() == 1 &&
          (only(inc, f) || (&f == &inc.after && labelOk && !inc.guard && inc.before.empty())))
        step = stepOf(f[0], v);
      counterSteps.push_back(k - 1);
    }
    if (!step) return false;
    const std::optional<long> n = count(*cond, v, init->second, *step, false);
    if (!n || usedElsewhere(u, v, counterSteps) || jumpedToElsewhere(u, label, k)) return false;
    const Step start = marker(u.steps[i], FlowKind::RepeatStart, *n);
    u.steps[k] = marker(u.steps[k], FlowKind::RepeatEnd, 0);
    if (counterSteps.size() == 3) {
      Step& inc = u.steps[k - 1];
      if (inc.hasNcPart())
        inc.after.clear(); // its NC part stays in the body
      else
        u.steps.erase(u.steps.begin() + static_cast<std::ptrdiff_t>(k - 1));
    }
    u.steps[i + 1].label.clear();
    u.steps[i] = start;
    return true;
  }
  return false;
}

// The step holding `label`, or npos.
std::size_t labelStep(const UnitSteps& u, const std::string& label) {
  for (std::size_t i = 0; i < u.steps.size(); ++i)
    if (u.steps[i].label == label) return i;
  return static_cast<std::size_t>(-1);
}

// Whether a jump other than the one at `k` enters or leaves the steps [i, k].
bool crossed(const UnitSteps& u, std::size_t i, std::size_t k) {
  for (std::size_t j = 0; j < u.steps.size(); ++j)
    for (const Flow& f : u.steps[j].after) {
      if (f.kind != FlowKind::Jump || j == k) continue;
      const std::size_t t = labelStep(u, f.label);
      if ((j >= i && j <= k) != (t >= i && t <= k)) return true;
    }
  return false;
}

} // namespace

int backwardJumpsAsDoLoops(UnitSteps& unit) {
  int rewritten = 0;
  for (std::size_t k = 0; k < unit.steps.size(); ++k) {
    Step& s = unit.steps[k];
    if (s.after.empty() || s.after.back().kind != FlowKind::Jump) continue;
    Flow& jump = s.after.back();
    // the condition: the jump's own (NCT IF [c] GOTO), or the guard of a block that only jumps
    const bool guarded = s.guard && !s.hasNcPart() && s.after.size() == 1 && s.before.empty();
    if (!jump.condition && !guarded) continue;
    const std::size_t i = labelStep(unit, jump.label);
    if (i > k || jumpedToElsewhere(unit, jump.label, k) || crossed(unit, i, k)) continue;
    Flow end;
    end.kind = FlowKind::DoEnd;
    end.condition = jump.condition ? *jump.condition : *s.guard;
    end.loop = 1000 + ++rewritten;
    end.range = jump.range;
    Flow start = end;
    start.kind = FlowKind::DoStart;
    start.condition.reset();
    if (guarded) s.guard.reset();
    jump = end;
    unit.steps[i].label.clear();
    unit.steps[i].before.insert(unit.steps[i].before.begin(), start);
  }
  return rewritten;
}

int countedLoopsAsRepeats(UnitSteps& unit) {
  int rewritten = 0;
  for (std::size_t i = 0; i < unit.steps.size(); ++i)
    if (whileLoop(unit, i) || jumpLoop(unit, i)) ++rewritten;
  return rewritten;
}

} // namespace gcx::xlate
