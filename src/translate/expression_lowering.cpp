#include "translate/expression_lowering.h"

#include <cmath>
#include <fmt/format.h>
#include <functional>

namespace gcx::xlate {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

ir::Expr node(ir::ExprKind kind, std::vector<ir::Expr> args) {
  ir::Expr e;
  e.kind = kind;
  e.args = std::move(args);
  return e;
}
ir::Expr binary(ir::Op op, ir::Expr a, ir::Expr b) {
  ir::Expr e = node(ir::ExprKind::Binary, {std::move(a), std::move(b)});
  e.op = op;
  return e;
}
ir::Expr call(ir::Func f, ir::Expr a) {
  ir::Expr e = node(ir::ExprKind::Call, {std::move(a)});
  e.func = f;
  return e;
}

constexpr std::pair<ir::Op, ir::RelOp> kRelations[] = {
    {ir::Op::Eq, ir::RelOp::Eq}, {ir::Op::Ne, ir::RelOp::Ne}, {ir::Op::Lt, ir::RelOp::Lt},
    {ir::Op::Le, ir::RelOp::Le}, {ir::Op::Gt, ir::RelOp::Gt}, {ir::Op::Ge, ir::RelOp::Ge}};

bool isRelational(ir::Op op) {
  for (const auto& [o, r] : kRelations)
    if (o == op) return true;
  return false;
}

// toward zero from floor and ceiling chosen by the sign: [FLOOR(x)*[x>=0]+CEIL(x)*[x<0]];
// away from zero with the two swapped
ir::Expr bySign(const ir::Expr& x, ir::Func nonNegative, ir::Func negative) {
  const ir::Expr arg = bracketed(x);
  return node(ir::ExprKind::Bracket,
              {binary(ir::Op::Add,
                      binary(ir::Op::Mul, call(nonNegative, arg),
                             bracketed(binary(ir::Op::Ge, arg, ir::Expr::literal(0)))),
                      binary(ir::Op::Mul, call(negative, arg),
                             bracketed(binary(ir::Op::Lt, arg, ir::Expr::literal(0)))))});
}

class Lowering {
public:
  Lowering(const VariablePlan& plan, const StructuredSpelling& t, std::string& why)
      : plan_(plan), t_(t), why_(why) {}

  std::optional<ir::Expr> lower(const ir::Expr& e);

private:
  std::optional<ir::Expr> rewritten(const ir::Expr& e);
  bool writes(const ir::Expr& e) const { return t_.writes && t_.writes(e); }

  const VariablePlan& plan_;
  const StructuredSpelling& t_;
  std::string& why_;
};

std::optional<ir::Expr> Lowering::lower(const ir::Expr& e) {
  if (!t_.writes) { // no variables: only a value the text can hold
    if (const std::optional<double> v = foldConstant(e)) return ir::Expr::literal(*v, e.range);
    why_ = fmt::format("{} has no variables or expressions", t_.label);
    return std::nullopt;
  }
  ir::Expr out = e;
  if (e.kind == ir::ExprKind::Variable) {
    const auto it = plan_.renumber.find(static_cast<int>(e.number));
    if (it == plan_.renumber.end()) {
      why_ = fmt::format("#{} has no place in {}", static_cast<int>(e.number), t_.label);
      return std::nullopt;
    }
    out.number = it->second;
    return out;
  }
  if (e.kind == ir::ExprKind::Indirect) {
    why_ = "a variable numbered at run time cannot be renumbered for the target";
    return std::nullopt;
  }
  for (ir::Expr& a : out.args) {
    std::optional<ir::Expr> l = lower(a);
    if (!l) return std::nullopt;
    a = std::move(*l);
  }
  if (writes(out)) return out;
  if (std::optional<ir::Expr> r = rewritten(out)) return r;
  if (const std::optional<double> v = foldConstant(out)) // numbers only: the value itself
    return ir::Expr::literal(*v, out.range);
  why_ = fmt::format("{} has no {} of the same meaning", t_.label,
                     out.kind == ir::ExprKind::Call     ? ir::spelling(out.func)
                     : out.kind == ir::ExprKind::Binary ? ir::spelling(out.op)
                                                        : "operation");
  return std::nullopt;
}

// The target's own form of a node it does not write as it is.
std::optional<ir::Expr> Lowering::rewritten(const ir::Expr& e) {
  const auto writable = [&](const ir::Expr& x) {
    // every node of x: its own arguments were lowered already
    std::function<bool(const ir::Expr&)> all = [&](const ir::Expr& y) {
      if (!writes(y)) return false;
      for (const ir::Expr& a : y.args)
        if (!all(a)) return false;
      return true;
    };
    return all(x);
  };
  std::optional<ir::Expr> r;
  if (e.kind == ir::ExprKind::Call && e.func == ir::Func::Fix)
    r = bySign(e.args[0], ir::Func::Floor, ir::Func::Ceil);
  else if (e.kind == ir::ExprKind::Call && e.func == ir::Func::Fup)
    r = bySign(e.args[0], ir::Func::Ceil, ir::Func::Floor);
  else if (e.kind == ir::ExprKind::Call && e.func == ir::Func::Atan) {
    ir::Expr a = call(ir::Func::Atan2, e.args[0]); // ATAN(a)/(1)
    a.args.push_back(ir::Expr::literal(1));
    r = a;
  } else if (e.kind == ir::ExprKind::Binary && e.op == ir::Op::Pow &&
             e.args[1].kind == ir::ExprKind::Number && e.args[1].number >= 1 &&
             e.args[1].number <= 4 && e.args[1].number == std::floor(e.args[1].number)) {
    // a small whole power: the base multiplied by itself
    const ir::Expr base = bracketed(e.args[0]);
    ir::Expr product = base;
    for (int i = 1; i < static_cast<int>(e.args[1].number); ++i)
      product = binary(ir::Op::Mul, product, base);
    r = bracketed(product);
  } else if (e.kind == ir::ExprKind::Binary && e.op == ir::Op::Mod) {
    // the dividend's sign: a - b * trunc(a / b)
    const ir::Expr a = bracketed(e.args[0]), b = bracketed(e.args[1]);
    r = node(ir::ExprKind::Bracket,
             {binary(ir::Op::Sub, a,
                     binary(ir::Op::Mul, b,
                            bySign(binary(ir::Op::Div, a, b), ir::Func::Floor, ir::Func::Ceil)))});
  }
  if (r && writable(*r)) return r;
  return std::nullopt;
}

} // namespace

ir::Expr conditionExpr(const ir::Condition& c) {
  ir::Expr e = binary(ir::Op::Eq, c.lhs, c.rhs);
  for (const auto& [o, r] : kRelations)
    if (r == c.op) e.op = o;
  e.range = c.lhs.range;
  return e;
}

ir::Condition asCondition(const ir::Expr& e) {
  const ir::Expr* x = &e;
  while (x->kind == ir::ExprKind::Bracket)
    x = &x->args[0];
  if (x->kind == ir::ExprKind::Binary)
    for (const auto& [o, r] : kRelations)
      if (x->op == o) return ir::Condition{x->args[0], r, x->args[1]};
  return ir::Condition{e, ir::RelOp::Ne, ir::Expr::literal(0)};
}

ir::Expr bracketed(ir::Expr e) {
  if (e.kind == ir::ExprKind::Number || e.kind == ir::ExprKind::Variable ||
      e.kind == ir::ExprKind::Bracket)
    return e;
  return node(ir::ExprKind::Bracket, {std::move(e)});
}

ir::Expr negated(const ir::Expr& c) {
  const ir::Expr* x = &c;
  while (x->kind == ir::ExprKind::Bracket)
    x = &x->args[0];
  if (x->kind == ir::ExprKind::Binary && isRelational(x->op)) {
    ir::Expr n = *x;
    switch (x->op) {
    case ir::Op::Eq:
      n.op = ir::Op::Ne;
      break;
    case ir::Op::Ne:
      n.op = ir::Op::Eq;
      break;
    case ir::Op::Lt:
      n.op = ir::Op::Ge;
      break;
    case ir::Op::Le:
      n.op = ir::Op::Gt;
      break;
    case ir::Op::Gt:
      n.op = ir::Op::Le;
      break;
    default:
      n.op = ir::Op::Lt;
      break;
    }
    return n;
  }
  return binary(ir::Op::Eq, bracketed(c), ir::Expr::literal(0));
}

std::optional<double> foldConstant(const ir::Expr& e) {
  std::vector<double> a;
  for (const ir::Expr& x : e.args) {
    const std::optional<double> v = foldConstant(x);
    if (!v) return std::nullopt;
    a.push_back(*v);
  }
  switch (e.kind) {
  case ir::ExprKind::Number:
    return e.number;
  case ir::ExprKind::Bracket:
    return a[0];
  case ir::ExprKind::Unary:
    if (e.op == ir::Op::Neg) return -a[0];
    if (e.op == ir::Op::Plus) return a[0];
    return std::nullopt;
  case ir::ExprKind::Binary:
    switch (e.op) {
    case ir::Op::Add:
      return a[0] + a[1];
    case ir::Op::Sub:
      return a[0] - a[1];
    case ir::Op::Mul:
      return a[0] * a[1];
    case ir::Op::Div:
      if (a[1] == 0) return std::nullopt;
      return a[0] / a[1];
    case ir::Op::Pow:
      return std::pow(a[0], a[1]);
    case ir::Op::Mod: // the dividend's sign (NCT)
      if (a[1] == 0) return std::nullopt;
      return std::fmod(a[0], a[1]);
    case ir::Op::FloorMod: // 0 <= r < |b| (WL4)
      if (a[1] == 0) return std::nullopt;
      return a[0] - std::fabs(a[1]) * std::floor(a[0] / std::fabs(a[1]));
    default:
      return std::nullopt;
    }
  case ir::ExprKind::Call:
    switch (e.func) {
    case ir::Func::Sin:
      return std::sin(a[0] * kDegree);
    case ir::Func::Cos:
      return std::cos(a[0] * kDegree);
    case ir::Func::Sqrt:
      if (a[0] < 0) return std::nullopt;
      return std::sqrt(a[0]);
    case ir::Func::Abs:
      return std::fabs(a[0]);
    default:
      return std::nullopt;
    }
  default:
    return std::nullopt;
  }
}

std::optional<ir::Expr> lowerExpression(const ir::Expr& e, const VariablePlan& plan,
                                        const StructuredSpelling& target, std::string& why) {
  Lowering l(plan, target, why);
  return l.lower(e);
}

std::optional<ir::Expr> lowerCondition(const ir::Expr& c, const VariablePlan& plan,
                                       const StructuredSpelling& target, std::string& why) {
  const ir::Expr* x = &c;
  while (x->kind == ir::ExprKind::Bracket)
    x = &x->args[0];
  if (x->kind != ir::ExprKind::Binary || !isRelational(x->op))
    return lowerExpression(c, plan, target, why);
  ir::Expr out = *x;
  for (ir::Expr& side : out.args) {
    std::optional<ir::Expr> l = lowerExpression(side, plan, target, why);
    if (!l) return std::nullopt;
    side = std::move(*l);
  }
  return out;
}

} // namespace gcx::xlate
