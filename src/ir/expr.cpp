#include "ir/expr.h"

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
  }
  return "?";
}

const char* spelling(Func f) {
  static const char* const names[] = {"SIN",  "COS", "TAN", "ASIN", "ACOS", "ATAN",
                                      "SQRT", "EXP", "LN",  "ABS",  "FIX",  "FUP"};
  return names[static_cast<int>(f)];
}

const char* spelling(RelOp op) {
  static const char* const names[] = {"EQ", "NE", "GT", "GE", "LT", "LE"};
  return names[static_cast<int>(op)];
}

} // namespace gcx::ir
