// Evaluation of macro expressions and conditions (nct-macro.md §2.5, §3): binary64 arithmetic,
// vacant rules, bitwise operations on 32 bits, functions in degrees, domain errors.
#pragma once
#include <optional>

#include "diag/diagnostic.h"
#include "ir/expr.h"
#include "passes/macro/value.h"

namespace gcx::macro {

/// §2.5 rule 3: EQ/NE see vacancy; GT GE LT LE order a vacant operand as 0⁺ (above every
/// number <= 0, below every number > 0, equal to another vacant).
/// How a vacant variable orders against numbers in GT GE LT LE (nct-macro.md §2.5, §12 Q1):
/// NCT's manual makes it 0⁺ (`#1 GT 0` is true); Fanuc controls treat it as 0.
enum class VacantOrder { Nct, Fanuc };
bool compare(const Value& lhs, ir::RelOp op, const Value& rhs,
             VacantOrder order = VacantOrder::Nct);

/// Rounds half away from zero (§2.2 indirect numbers, §2.6 integer addresses).
double roundHalfAway(double v);

class Evaluator {
public:
  Evaluator(VariableAccess& vars, diag::Engine& diags) : vars_(vars), diags_(diags) {}

  /// The value of e; vacant only for a bare variable reference, possibly in brackets (§2.5
  /// rule 1). nullopt after an error was reported at the offending expression.
  /// The value of e; a result that is not a finite number (EXP[1000], 1E300*1E300) is an error
  /// at the expression that produced it, so no infinity or NaN reaches a variable or a word.
  std::optional<Value> value(const ir::Expr& e);
  /// The value of e with vacant read as 0 (AX[e], bracketed address values). Where vacancy
  /// matters (GOTO#1 is 2125, §2.5 rule 5) use value().
  std::optional<double> number(const ir::Expr& e);
  std::optional<bool> condition(const ir::Condition& c);
  /// A guard `IF<p> (e)` (wl4.md §6.5): each relational operator inside compares
  /// round_p(a-b) with 0, and e holds when round_p(e) != 0; no precision: exact.
  std::optional<bool> guard(const ir::Expr& e, std::optional<int> precision);
  /// The number n of an assignment target `#n` or `#[e]` (e rounded half away from zero).
  std::optional<int> variableNumber(const ir::Expr& target);
  /// e as a variable number or symbolic index: vacant = 0, rounded half away from zero (§2.2);
  /// NCTX01 if it is no int.
  std::optional<int> index(const ir::Expr& e);

  diag::Engine& diags() { return diags_; }
  void setVacantOrder(VacantOrder o) { vacantOrder_ = o; }

private:
  std::optional<Value> compute(const ir::Expr& e);
  std::optional<Value> unary(const ir::Expr& e);
  std::optional<Value> binary(const ir::Expr& e);
  std::optional<Value> call(const ir::Expr& e);
  std::optional<Value> relational(const ir::Expr& e, const Value& lhs, const Value& rhs);
  std::optional<Value> assignment(const ir::Expr& e);
  std::optional<Value> parameter(const ir::Expr& e);
  std::optional<Value> named(const ir::Expr& e);
  std::optional<int> integer(double v, const ir::Expr& where, const char* code, const char* what);
  bool bitRange(double v, const ir::Expr& operand);
  void error(const char* code, const ir::Expr& where, std::string message);

  VariableAccess& vars_;
  diag::Engine& diags_;
  VacantOrder vacantOrder_ = VacantOrder::Nct;
  std::optional<int> precision_; // of the guard being evaluated
};

} // namespace gcx::macro
