#include "passes/macro/evaluator.h"

#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <fmt/format.h>
#include <numbers>

#include "diag/codes.h"
#include "emit/number.h"

namespace gcx::macro {

namespace {

using emit::formatNumber;
using ir::ExprKind;

constexpr double kToRad = std::numbers::pi / 180.0;
constexpr double kToDeg = 180.0 / std::numbers::pi;

// §2.4: SIN and COS are exactly 0 / ±1 at whole multiples of 90°; fmod is exact.
double sinDeg(double x) {
  const double r = std::fmod(x, 360.0);
  if (std::fmod(r, 90.0) == 0) {
    static constexpr double quadrant[] = {0, 1, 0, -1};
    return quadrant[(static_cast<int>(r / 90.0) + 4) % 4];
  }
  return std::sin(r * kToRad);
}

double cosDeg(double x) {
  const double r = std::fmod(x, 360.0);
  if (std::fmod(r, 90.0) == 0) {
    static constexpr double quadrant[] = {1, 0, -1, 0};
    return quadrant[(static_cast<int>(r / 90.0) + 4) % 4];
  }
  return std::cos(r * kToRad);
}

// §3.2: truncate toward zero, keep the low 32 bits, operate, read back as signed 32-bit.
double bitwise(ir::Op op, double a, double b) {
  const auto bits = [](double v) {
    return static_cast<std::uint32_t>(static_cast<std::int64_t>(std::trunc(v)));
  };
  const std::uint32_t x = bits(a), y = bits(b);
  std::uint32_t r = ~x; // NOT
  if (op == ir::Op::And) r = x & y;
  if (op == ir::Op::Or) r = x | y;
  if (op == ir::Op::Xor) r = x ^ y;
  return static_cast<std::int32_t>(r);
}

} // namespace

double roundHalfAway(double v) {
  return std::round(v); // std::round rounds halfway cases away from zero
}

bool compare(const Value& lhs, ir::RelOp op, const Value& rhs, VacantOrder mode) {
  using ir::RelOp;
  if (op == RelOp::Eq || op == RelOp::Ne) {
    const bool equal =
        lhs.vacant || rhs.vacant ? lhs.vacant && rhs.vacant : lhs.number == rhs.number;
    return (op == RelOp::Eq) == equal;
  }
  if (mode == VacantOrder::Fanuc) // Fanuc Macro B: vacant orders exactly like 0 (§12 Q1)
    return compare(Value::of(lhs.orZero()), op, Value::of(rhs.orZero()), VacantOrder::Nct);
  if (!lhs.vacant && !rhs.vacant) {
    switch (op) {
    case RelOp::Gt:
      return lhs.number > rhs.number;
    case RelOp::Ge:
      return lhs.number >= rhs.number;
    case RelOp::Lt:
      return lhs.number < rhs.number;
    default:
      return lhs.number <= rhs.number;
    }
  }
  // vacant = 0⁺: order -1 / 0 / 1 of lhs against rhs
  int order = 0;
  if (lhs.vacant && !rhs.vacant) order = rhs.number <= 0 ? 1 : -1;
  if (!lhs.vacant && rhs.vacant) order = lhs.number <= 0 ? -1 : 1;
  switch (op) {
  case RelOp::Gt:
    return order > 0;
  case RelOp::Ge:
    return order >= 0;
  case RelOp::Lt:
    return order < 0;
  default:
    return order <= 0;
  }
}

void Evaluator::error(const char* code, const ir::Expr& where, std::string message) {
  diags_.error(code, where.range, std::move(message));
}

std::optional<int> Evaluator::integer(double v, const ir::Expr& where, const char* code,
                                      const char* what) {
  const double r = roundHalfAway(v);
  if (r >= INT_MIN && r <= INT_MAX) return static_cast<int>(r);
  error(code, where, fmt::format("{} {} is out of range", what, formatNumber(v)));
  return std::nullopt;
}

std::optional<int> Evaluator::index(const ir::Expr& e) {
  auto v = number(e);
  if (!v) return std::nullopt;
  return integer(*v, e, diag::code::UndefinedVariable, "variable number or index");
}

std::optional<int> Evaluator::variableNumber(const ir::Expr& target) {
  if (target.kind == ExprKind::Variable)
    return integer(target.number, target, diag::code::UndefinedVariable, "variable number");
  if (target.kind == ExprKind::Indirect) return index(target.args[0]);
  error(diag::code::SyntaxError, target, "an assignment target must be #n or #[expression]");
  return std::nullopt;
}

std::optional<double> Evaluator::number(const ir::Expr& e) {
  auto v = value(e);
  if (!v) return std::nullopt;
  return v->orZero();
}

std::optional<Value> Evaluator::value(const ir::Expr& e) {
  auto v = compute(e);
  if (v && !v->vacant && !std::isfinite(v->number)) {
    error(diag::code::ValueOutOfRange, e,
          "the result is not a finite number (beyond the range of a double)");
    return std::nullopt;
  }
  return v;
}

std::optional<Value> Evaluator::compute(const ir::Expr& e) {
  switch (e.kind) {
  case ExprKind::Number:
    return Value::of(e.number);
  case ExprKind::Variable:
  case ExprKind::Indirect: {
    auto n = variableNumber(e);
    if (!n) return std::nullopt;
    return vars_.read(*n, e.range);
  }
  case ExprKind::Named:
    return named(e);
  case ExprKind::Bracket: // [#1] keeps vacancy; any other content is already a number
    return value(e.args[0]);
  case ExprKind::Unary:
    return unary(e);
  case ExprKind::Binary:
    return binary(e);
  case ExprKind::Call:
    return call(e);
  case ExprKind::AxisNumber: {
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(e.name[0])));
    auto n = vars_.axisNumber(letter, e.range);
    if (!n) return std::nullopt;
    return Value::of(*n);
  }
  case ExprKind::Parameter:
    return parameter(e);
  case ExprKind::Assign:
    return assignment(e);
  }
  return std::nullopt;
}

// `#n=e` inside an expression: the target first, then e, stored at once; yields e's value.
std::optional<Value> Evaluator::assignment(const ir::Expr& e) {
  if (!vars_.assignsInExpressions()) {
    error(diag::code::SyntaxError, e, "an assignment cannot stand inside an expression here");
    return std::nullopt;
  }
  auto n = variableNumber(e.args[0]);
  if (!n) return std::nullopt;
  auto v = value(e.args[1]);
  if (!v || !vars_.write(*n, *v, e.range)) return std::nullopt;
  return v;
}

std::optional<Value> Evaluator::named(const ir::Expr& e) {
  std::optional<int> idx;
  if (!e.args.empty()) {
    idx = index(e.args[0]);
    if (!idx) return std::nullopt;
  }
  return vars_.readNamed(e.name, idx, e.range);
}

// §9.2: PRM[id, bit]/[index]; a vacant operand counts as omitted; a missing id is 2064.
std::optional<Value> Evaluator::parameter(const ir::Expr& e) {
  std::optional<int> operands[3]; // id, bit, index
  const bool present[3] = {true, e.prmHasBit, e.prmHasIndex};
  std::size_t arg = 0;
  for (int k = 0; k < 3; ++k) {
    if (!present[k]) continue;
    const ir::Expr& a = e.args[arg++];
    auto v = value(a);
    if (!v) return std::nullopt;
    if (v->vacant) continue;
    operands[k] = integer(v->number, a, diag::code::DataOutOfRange, "PRM operand");
    if (!operands[k]) return std::nullopt;
  }
  if (!operands[0]) {
    error(diag::code::SyntaxError, e, "PRM without a parameter number (the operand is vacant)");
    return std::nullopt;
  }
  auto p = vars_.parameter(*operands[0], operands[1], operands[2], e.range);
  if (!p) return std::nullopt;
  return Value::of(*p);
}

std::optional<Value> Evaluator::unary(const ir::Expr& e) {
  auto v = value(e.args[0]);
  if (!v) return std::nullopt;
  switch (e.op) {
  case ir::Op::Plus: // `+` is not stored (000:85): +#1 is #1, vacancy included
    return v;
  case ir::Op::Neg:
    return Value::of(-v->orZero());
  default: { // NOT
    if (!bitRange(v->orZero(), e.args[0])) return std::nullopt;
    return Value::of(bitwise(ir::Op::Not, v->orZero(), 0));
  }
  }
}

// §3.2: each operand must satisfy -(2³²-1) <= v < 2³², else 2129.
bool Evaluator::bitRange(double v, const ir::Expr& operand) {
  if (v >= -4294967295.0 && v < 4294967296.0) return true;
  error(diag::code::BitOperandRange, operand,
        fmt::format("invalid operation on #: {} is outside the 32-bit operand range "
                    "-(2^32-1) <= v < 2^32",
                    formatNumber(v)));
  return false;
}

std::optional<Value> Evaluator::binary(const ir::Expr& e) {
  auto lhs = value(e.args[0]);
  if (!lhs) return std::nullopt;
  auto rhs = value(e.args[1]);
  if (!rhs) return std::nullopt;
  const double a = lhs->orZero(), b = rhs->orZero(); // §2.5 rule 2
  switch (e.op) {
  case ir::Op::Add:
    return Value::of(a + b);
  case ir::Op::Sub:
    return Value::of(a - b);
  case ir::Op::Mul:
    return Value::of(a * b);
  case ir::Op::Div:
  case ir::Op::Mod:
    if (b == 0) {
      error(diag::code::DivideByZero, e, "attempt to divide by zero");
      return std::nullopt;
    }
    // MOD: r = a - b·trunc(a/b) in binary64, sign of the dividend (§3.2, §12 Q3)
    return Value::of(e.op == ir::Op::Div ? a / b : a - b * std::trunc(a / b));
  case ir::Op::And:
  case ir::Op::Or:
  case ir::Op::Xor: {
    if (!bitRange(a, e.args[0]) || !bitRange(b, e.args[1])) return std::nullopt;
    return Value::of(bitwise(e.op, a, b));
  }
  case ir::Op::Pow: // a result that is no finite number is reported by value()
    return Value::of(std::pow(a, b));
  case ir::Op::FloorMod:
    if (b == 0) {
      error(diag::code::DivideByZero, e, "attempt to divide by zero");
      return std::nullopt;
    }
    return Value::of(a - std::fabs(b) * std::floor(a / std::fabs(b)));
  case ir::Op::Eq:
  case ir::Op::Ne:
  case ir::Op::Lt:
  case ir::Op::Le:
  case ir::Op::Gt:
  case ir::Op::Ge:
    return relational(e, *lhs, *rhs);
  case ir::Op::LogicalAnd:
    return Value::of((a != 0) && (b != 0) ? 1.0 : 0.0);
  case ir::Op::LogicalOr:
    return Value::of((a != 0) || (b != 0) ? 1.0 : 0.0);
  case ir::Op::LogicalXor:
    return Value::of((a != 0) != (b != 0) ? 1.0 : 0.0);
  case ir::Op::Neg: // unary; the parsers never build them here
  case ir::Op::Plus:
  case ir::Op::Not:
    break;
  }
  error(diag::code::SyntaxError, e, fmt::format("{} is not a binary operator", ir::spelling(e.op)));
  return std::nullopt;
}

namespace {

ir::RelOp relOpOf(ir::Op op) {
  switch (op) {
  case ir::Op::Eq:
    return ir::RelOp::Eq;
  case ir::Op::Ne:
    return ir::RelOp::Ne;
  case ir::Op::Lt:
    return ir::RelOp::Lt;
  case ir::Op::Le:
    return ir::RelOp::Le;
  case ir::Op::Gt:
    return ir::RelOp::Gt;
  default:
    return ir::RelOp::Ge;
  }
}

// Rounds half away from zero to p decimals.
double roundTo(double v, int p) {
  const double scale = std::pow(10.0, p);
  return roundHalfAway(v * scale) / scale;
}

} // namespace

// A relational operator inside an expression is 1 or 0; inside a guard with a precision p it
// compares round_p(a-b) with 0 (wl4.md §6.5).
std::optional<Value> Evaluator::relational(const ir::Expr& e, const Value& lhs, const Value& rhs) {
  const ir::RelOp op = relOpOf(e.op);
  const bool holds =
      precision_
          ? compare(Value::of(roundTo(lhs.orZero() - rhs.orZero(), *precision_)), op, Value::of(0))
          : compare(lhs, op, rhs, vacantOrder_);
  return Value::of(holds ? 1.0 : 0.0);
}

std::optional<bool> Evaluator::guard(const ir::Expr& e, std::optional<int> precision) {
  const std::optional<int> outer = precision_;
  precision_ = precision;
  auto v = number(e);
  precision_ = outer;
  if (!v) return std::nullopt;
  return (precision ? roundTo(*v, *precision) : *v) != 0;
}

// §3.3: functions in degrees with the manual's domain errors.
std::optional<Value> Evaluator::call(const ir::Expr& e) {
  auto arg = value(e.args[0]);
  if (!arg) return std::nullopt;
  const double x = arg->orZero();
  switch (e.func) {
  case ir::Func::Sin:
    return Value::of(sinDeg(x));
  case ir::Func::Cos:
    return Value::of(cosDeg(x));
  case ir::Func::Tan: {
    const double r = std::fmod(x, 180.0);
    if (std::fabs(r) == 90.0) {
      error(diag::code::TanDomain, e,
            fmt::format("TAN {}: the argument is an odd multiple of 90 degrees", formatNumber(x)));
      return std::nullopt;
    }
    return Value::of(r == 0 ? 0.0 : std::tan(r * kToRad));
  }
  case ir::Func::Asin:
  case ir::Func::Acos:
    if (!(std::fabs(x) <= 1)) {
      error(diag::code::ArcDomain, e,
            fmt::format("{} {}: the absolute value of the argument is greater than 1",
                        ir::spelling(e.func), formatNumber(x)));
      return std::nullopt;
    }
    return Value::of((e.func == ir::Func::Asin ? std::asin(x) : std::acos(x)) * kToDeg);
  case ir::Func::Atan:
    return Value::of(std::atan(x) * kToDeg);
  case ir::Func::Sqrt:
    if (x < 0) {
      error(diag::code::SqrtNegative, e,
            fmt::format("SQRT {}: root of a negative value", formatNumber(x)));
      return std::nullopt;
    }
    return Value::of(std::sqrt(x));
  case ir::Func::Exp:
    return Value::of(std::exp(x));
  case ir::Func::Ln:
    if (!(x > 0)) {
      error(diag::code::LogDomain, e,
            fmt::format("LN {}: the argument is not positive", formatNumber(x)));
      return std::nullopt;
    }
    return Value::of(std::log(x));
  case ir::Func::Abs:
    return Value::of(std::fabs(x));
  case ir::Func::Fix:
    return Value::of(std::trunc(x));
  case ir::Func::Fup: // away from zero; a whole number stays (§12 Q2)
    return Value::of(x >= 0 ? std::ceil(x) : std::floor(x));
  case ir::Func::Round:
    return Value::of(roundHalfAway(x));
  case ir::Func::Floor:
    return Value::of(std::floor(x));
  case ir::Func::Ceil:
    return Value::of(std::ceil(x));
  case ir::Func::Atan2: { // ATAN(a)/(b): atan2 in (-180, 180] (wl4.md §6.3)
    auto divisor = value(e.args[1]);
    if (!divisor) return std::nullopt;
    const double deg = std::atan2(x, divisor->orZero()) * kToDeg;
    return Value::of(deg == -180.0 ? 180.0 : deg);
  }
  }
  return std::nullopt;
}

std::optional<bool> Evaluator::condition(const ir::Condition& c) {
  auto lhs = value(c.lhs);
  if (!lhs) return std::nullopt;
  auto rhs = value(c.rhs);
  if (!rhs) return std::nullopt;
  return compare(*lhs, c.op, *rhs, vacantOrder_);
}

} // namespace gcx::macro
