// Macro expressions (nct-macro.md §3), dialect-neutral: numbers, variables, operators, functions.
#pragma once
#include <string>
#include <vector>

#include "ir/source.h"

namespace gcx::ir {

enum class ExprKind : unsigned char {
  Number,     // literal; value in `number`
  Variable,   // #n; n in `number`
  Indirect,   // #[e]; args[0] = e
  Named,      // #_NAME or #_NAME[e]; name in `name`, optional index in args[0]
  Bracket,    // [e]; kept so a bare variable and a bracketed one stay apart (macro §2.5)
  Unary,      // op applied to args[0]
  Binary,     // args[0] op args[1]
  Call,       // func applied to args[0]
  AxisNumber, // AXNUM[letter]; letter in `name`
  Parameter,  // PRM[id(,bit)](/[index]); args in order id, bit?, index?
};

enum class Op : unsigned char { Neg, Plus, Not, Add, Sub, Mul, Div, Mod, And, Or, Xor };
enum class Func : unsigned char { Sin, Cos, Tan, Asin, Acos, Atan, Sqrt, Exp, Ln, Abs, Fix, Fup };
enum class RelOp : unsigned char { Eq, Ne, Gt, Ge, Lt, Le };

struct Expr {
  ExprKind kind = ExprKind::Number;
  Op op = Op::Add;
  Func func = Func::Sin;
  bool prmHasBit = false;   // PRM[id, bit]
  bool prmHasIndex = false; // PRM[...]/[index]
  double number = 0;
  std::string name;
  std::vector<Expr> args;
  SourceRange range;

  static Expr literal(double v, SourceRange r = {}) {
    Expr e;
    e.kind = ExprKind::Number;
    e.number = v;
    e.range = r;
    return e;
  }
  static Expr variable(double n, SourceRange r = {}) {
    Expr e = literal(n, r);
    e.kind = ExprKind::Variable;
    return e;
  }
};

struct Condition {
  Expr lhs;
  RelOp op = RelOp::Eq;
  Expr rhs;
};

const char* spelling(Op op);
const char* spelling(Func f);
const char* spelling(RelOp op);

} // namespace gcx::ir
