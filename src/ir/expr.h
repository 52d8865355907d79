// Macro expressions, dialect-neutral: numbers, variables, operators, functions (nct-macro.md §3,
// wl4.md §6.3). Where dialects give one spelling different meanings (NCT AND is bitwise, WL4 AND
// logical; NCT FIX truncates, WL4 FIX floors) the IR has distinct operators and functions, and
// each front end picks the one its dialect means.
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
  Assign,     // #n=e inside an expression: args[0] = the variable, args[1] = e; yields e's value
};

enum class Op : unsigned char {
  Neg,
  Plus,
  Not, // bitwise complement on 32 bits (NCT)
  Add,
  Sub,
  Mul,
  Div,
  Mod, // a - b*trunc(a/b): the sign of the dividend (NCT)
  And, // bitwise on 32 bits (NCT)
  Or,
  Xor,
  Pow,      // a ** b (WL4)
  FloorMod, // a - |b|*floor(a/|b|): 0 <= r < |b| (WL4 MOD)
  Eq,       // relational inside an expression, 1 or 0 (WL4 == <> < <= > >=)
  Ne,
  Lt,
  Le,
  Gt,
  Ge,
  LogicalAnd, // non-zero is true, result 1 or 0 (WL4 AND OR XOR)
  LogicalOr,
  LogicalXor,
};
enum class Func : unsigned char {
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Sqrt,
  Exp,
  Ln,
  Abs,
  Fix,   // toward zero (NCT)
  Fup,   // away from zero (NCT)
  Round, // nearest, halves away from zero (WL4)
  Floor, // down (WL4 FIX)
  Ceil,  // up (WL4 FUP)
  Atan2, // ATAN(a)/(b) of WL4: args[0] = a, args[1] = b, in (-180, 180]
};
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
