#include "passes/macro/word_values.h"

#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"
#include "emit/number.h"

namespace gcx::macro {

namespace {

// Rounds to a multiple of resolution, ties away from zero; 1e-6 rounds as round(v*1e6)/1e6 so
// X[10/3] gives the double nearest 3.333333.
double roundTo(double v, double resolution) {
  const double k = std::round(1 / resolution);
  const bool decimal = k >= 1 && std::fabs(k * resolution - 1) < 1e-12;
  const double scale = decimal ? k : 1 / resolution;
  if (!(std::fabs(v) * scale < 0x1p52)) return v; // already whole at this resolution (or NaN)
  return decimal ? roundHalfAway(v * k) / k : roundHalfAway(v / resolution) * resolution;
}

bool isReference(ir::ExprKind k) {
  return k == ir::ExprKind::Variable || k == ir::ExprKind::Indirect || k == ir::ExprKind::Named;
}

} // namespace

std::optional<double> addressValue(double v, std::string_view address, const SourceRange& where,
                                   diag::Engine& diags, const WordOptions& opt) {
  static const WordValueRules none;
  const WordValueRules& rules = opt.rules ? *opt.rules : none;
  const AddressRule& rule = rules.find(address, opt.callNumber);
  double r = v;
  switch (rule.rounding) {
  case Rounding::Integer:
    r = roundHalfAway(v);
    break;
  case Rounding::Tenth:
    r = roundTo(v, 0.1);
    break;
  case Rounding::Resolution:
    r = roundTo(v, opt.resolution.value_or(rules.resolution));
    break;
  case Rounding::None:
    break;
  }
  r += 0.0; // -0 -> 0
  if (r >= rule.min && r <= rule.max) return r;
  const std::string shown = emit::formatNumber(r);
  std::string message;
  if (!std::isfinite(r))
    message = fmt::format("address {}: {} is not a finite number", address, shown);
  else if (r < 0 && rule.min >= 0)
    message = fmt::format("address {} takes no negative value: {}{}", address, address, shown);
  else
    message =
        fmt::format("{}{} is out of range: {} takes {}-{} ({})", address, shown, address,
                    emit::formatNumber(rule.min), emit::formatNumber(rule.max), rules.reference);
  diags.error(diag::code::AddressValueRange, where, std::move(message));
  return std::nullopt;
}

WordValue wordValue(const ir::Word& w, Evaluator& ev, const WordOptions& opt) {
  if (w.kind == ir::ValueKind::Number) return {WordResult::Value, w.number};
  if (w.kind == ir::ValueKind::Path) {
    ev.diags().error(diag::code::SyntaxError, w.range, "a file name is not a number");
    return {};
  }
  // §2.5 rule 4: a bare reference, optionally signed, drops the word when vacant
  const ir::Expr* core = &w.expr;
  bool negate = false;
  if (core->kind == ir::ExprKind::Unary && core->op != ir::Op::Not &&
      isReference(core->args[0].kind)) {
    negate = core->op == ir::Op::Neg;
    core = &core->args[0];
  }
  double n = 0;
  if (isReference(core->kind)) {
    auto v = ev.value(*core);
    if (!v) return {};
    if (v->vacant) return {WordResult::Dropped, 0};
    n = negate ? -v->number : v->number;
  } else { // [e], -[e]: always a number
    auto v = ev.number(w.expr);
    if (!v) return {};
    n = *v;
  }
  auto r = addressValue(n, w.address, w.range, ev.diags(), opt);
  if (!r) return {};
  return {WordResult::Value, *r};
}

} // namespace gcx::macro
