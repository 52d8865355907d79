// LinuxCNC RS274/NGC text of IR expressions (LinuxCNC "O Codes" and "Expressions" chapters):
// every binary operation in its own brackets, so no precedence rule of either language decides
// the meaning. An operator or function LinuxCNC spells with another meaning has no text here.
#pragma once
#include <functional>
#include <string>

#include "ir/block.h"

namespace gcx::ngc {

/// How a source variable number reads in LinuxCNC ("#100", "#<_l31>"), or empty with `why`
/// set when it has no same-meaning LinuxCNC parameter.
using VariableText = std::function<std::string(int number, std::string& why)>;

/// The expression's text; false with `why` set when a part has no LinuxCNC form.
bool expressionText(const ir::Expr& e, const VariableText& variable, std::string& out,
                    std::string& why);

/// A word value: a number, a parameter, or a bracketed expression.
bool wordValueText(const ir::Word& w, const VariableText& variable, std::string& out,
                   std::string& why);

/// `[lhs EQ rhs]`.
bool conditionText(const ir::Condition& c, const VariableText& variable, std::string& out,
                   std::string& why);

} // namespace gcx::ngc
