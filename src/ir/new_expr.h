// A new expression, and making a used one new again in place: words reused block after block
// (the fast parse, the packed blocks of a two-thread run) reset their expressions so.
#pragma once
#include "ir/expr.h"

namespace gcx::ir {

/// What a literal word's expression is.
inline const Expr kNewExpr{};

/// e made equal to a new Expr; without heap parts to drop (a literal word's expression, the
/// usual case) field by field, cheaper than building one and moving it in.
inline void resetExpr(Expr& e) {
  if (!e.name.empty() || !e.args.empty()) {
    e = Expr{};
    return;
  }
  e.kind = kNewExpr.kind;
  e.op = kNewExpr.op;
  e.func = kNewExpr.func;
  e.prmHasBit = kNewExpr.prmHasBit;
  e.prmHasIndex = kNewExpr.prmHasIndex;
  e.number = kNewExpr.number;
  e.range = kNewExpr.range;
}

} // namespace gcx::ir
