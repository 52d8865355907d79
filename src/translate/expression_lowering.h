// An expression of the source written with the target's operators and variable numbers: a function
// the target spells otherwise is rewritten into the target's own (NCT FIX, toward zero, is
// WL4's FIX and FUP chosen by the sign), and a target without variables gets the value of an
// expression of literals. What has no equal form is refused with the reason.
#pragma once
#include <optional>
#include <string>

#include "ir/expr.h"
#include "translate/structured_spelling.h"
#include "translate/variable_plan.h"

namespace gcx::xlate {

/// `e` for the target, or nullopt with the reason in `why`.
std::optional<ir::Expr> lowerExpression(const ir::Expr& e, const VariablePlan& plan,
                                        const StructuredSpelling& target, std::string& why);

/// The value of an expression of literals, or nullopt when it reads a variable or uses an
/// operation gcx does not fold.
std::optional<double> foldConstant(const ir::Expr& e);

/// A relational expression's negation (a < b -> a >= b); anything else compared with 0.
ir::Expr negated(const ir::Expr& condition);

/// `c` for the target as a condition: a relation at its top keeps its operator (NCT writes one only
/// there, `IF [a LT b]`), its sides are lowered as expressions.
std::optional<ir::Expr> lowerCondition(const ir::Expr& c, const VariablePlan& plan,
                                       const StructuredSpelling& target, std::string& why);

/// A condition `a op b` (NCT's IF and WHILE) as an expression with its relational operator.
ir::Expr conditionExpr(const ir::Condition& c);
/// An expression as a condition: its relation at the top, or `e NE 0`.
ir::Condition asCondition(const ir::Expr& e);

/// `e` in brackets unless it is a number or a variable.
ir::Expr bracketed(ir::Expr e);

} // namespace gcx::xlate
