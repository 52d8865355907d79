#include "ir/expr.h"

// The spellings name each operator and function distinctly (gcx dump); a dialect's printer
// spells them its own way.

namespace gcx::ir {

const char* spelling(Op op) {
  switch (op) {
  case Op::Neg:
    return "-";
  case Op::Plus:
    return "+";
  case Op::Not:
    return "NOT";
  case Op::Add:
    return "+";
  case Op::Sub:
    return "-";
  case Op::Mul:
    return "*";
  case Op::Div:
    return "/";
  case Op::Mod:
    return "MOD";
  case Op::And:
    return "AND";
  case Op::Or:
    return "OR";
  case Op::Xor:
    return "XOR";
  case Op::Pow:
    return "**";
  case Op::FloorMod:
    return "FLOORMOD";
  case Op::Eq:
    return "==";
  case Op::Ne:
    return "<>";
  case Op::Lt:
    return "<";
  case Op::Le:
    return "<=";
  case Op::Gt:
    return ">";
  case Op::Ge:
    return ">=";
  case Op::LogicalAnd:
    return "&&";
  case Op::LogicalOr:
    return "||";
  case Op::LogicalXor:
    return "^^";
  }
  return "?";
}

const char* spelling(Func f) {
  static const char* const names[] = {"SIN",   "COS",   "TAN",  "ASIN", "ACOS", "ATAN",
                                      "SQRT",  "EXP",   "LN",   "ABS",  "FIX",  "FUP",
                                      "ROUND", "FLOOR", "CEIL", "ATAN2"};
  return names[static_cast<int>(f)];
}

const char* spelling(RelOp op) {
  static const char* const names[] = {"EQ", "NE", "GT", "GE", "LT", "LE"};
  return names[static_cast<int>(op)];
}

} // namespace gcx::ir
