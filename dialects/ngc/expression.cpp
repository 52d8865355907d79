#include "dialects/ngc/expression.h"

#include "emit/number.h"

namespace gcx::ngc {

namespace {

// LinuxCNC's spelling of an operator that means the same there, or null.
const char* binarySpelling(ir::Op op) {
  switch (op) {
  case ir::Op::Add:
  case ir::Op::Sub:
  case ir::Op::Mul:
  case ir::Op::Div:
  case ir::Op::Pow:
    return ir::spelling(op); // + - * / **
  case ir::Op::FloorMod:     // LinuxCNC MOD: fmod, then + |b| when negative
    return "MOD";
  case ir::Op::Eq:
    return "EQ";
  case ir::Op::Ne:
    return "NE";
  case ir::Op::Lt:
    return "LT";
  case ir::Op::Le:
    return "LE";
  case ir::Op::Gt:
    return "GT";
  case ir::Op::Ge:
    return "GE";
  case ir::Op::LogicalAnd: // LinuxCNC AND OR XOR: non-zero is true
    return "AND";
  case ir::Op::LogicalOr:
    return "OR";
  case ir::Op::LogicalXor:
    return "XOR";
  default:
    return nullptr;
  }
}

// Functions of one argument LinuxCNC spells with the same meaning; null for those call() writes.
const char* functionSpelling(ir::Func f) {
  switch (f) {
  case ir::Func::Floor: // LinuxCNC's FIX rounds down
    return "FIX";
  case ir::Func::Ceil: // LinuxCNC's FUP rounds up
    return "FUP";
  case ir::Func::Fix:
  case ir::Func::Fup:
  case ir::Func::Atan:
  case ir::Func::Atan2:
    return nullptr;
  default: // SIN ... ABS in degrees, ROUND halves away from zero: the same in both
    return ir::spelling(f);
  }
}

struct Printer {
  const VariableText& variable;
  std::string& why;

  bool print(const ir::Expr& e, std::string& out) const {
    switch (e.kind) {
    case ir::ExprKind::Number:
      emit::appendNumber(out, e.number);
      return true;
    case ir::ExprKind::Variable: {
      const std::string v = variable(static_cast<int>(e.number), why);
      out += v;
      return !v.empty();
    }
    case ir::ExprKind::Bracket:
      return print(e.args[0], out);
    case ir::ExprKind::Unary:
      if (e.op == ir::Op::Plus) return print(e.args[0], out);
      if (e.op == ir::Op::Neg && e.args[0].kind == ir::ExprKind::Number) {
        emit::appendNumber(out, -e.args[0].number);
        return true;
      }
      if (e.op == ir::Op::Neg) { // LinuxCNC reads a sign only before a number
        out += "[-1*";
        if (!print(e.args[0], out)) return false;
        out += ']';
        return true;
      }
      why = "the bitwise NOT has no LinuxCNC operator";
      return false;
    case ir::ExprKind::Binary:
      return binary(e, out);
    case ir::ExprKind::Call:
      return call(e, out);
    case ir::ExprKind::Indirect:
      why = "an indirect variable #[...] may name any variable, LinuxCNC's reserved ones too";
      return false;
    default:
      why = "a system variable or parameter read has no LinuxCNC counterpart";
      return false;
    }
  }

  bool binary(const ir::Expr& e, std::string& out) const {
    const char* op = binarySpelling(e.op);
    if (!op) {
      why = e.op == ir::Op::Mod ? "NCT MOD keeps the dividend's sign, LinuxCNC MOD is never "
                                  "negative"
                                : "NCT AND/OR/XOR are bitwise, LinuxCNC's logical";
      return false;
    }
    out += '[';
    if (!print(e.args[0], out)) return false;
    const bool word = op[0] >= 'A' && op[0] <= 'Z';
    out += word ? std::string(" ") + op + " " : std::string(op);
    if (!print(e.args[1], out)) return false;
    out += ']';
    return true;
  }

  bool bracketed(const ir::Expr& e, std::string& out) const {
    out += '[';
    if (!print(e, out)) return false;
    out += ']';
    return true;
  }

  bool call(const ir::Expr& e, std::string& out) const {
    const ir::Expr& a = e.args[0];
    switch (e.func) {
    case ir::Func::Atan: // one argument: LinuxCNC's ATAN takes y/x
      out += "ATAN";
      if (!bracketed(a, out)) return false;
      out += "/[1]";
      return true;
    case ir::Func::Atan2:
      out += "ATAN";
      if (!bracketed(a, out)) return false;
      out += '/';
      return bracketed(e.args[1], out);
    case ir::Func::Fix:   // toward zero: LinuxCNC's FIX floors, FUP ceils
    case ir::Func::Fup: { // away from zero
      std::string v;
      if (!print(a, v)) return false;
      const std::string x = "[" + v + "]";
      const bool toZero = e.func == ir::Func::Fix;
      out += "[[FIX" + x + "*[" + v + (toZero ? " GE 0]" : " LT 0]") + "]+[FUP" + x + "*[" + v +
             (toZero ? " LT 0]" : " GE 0]") + "]]";
      return true;
    }
    default:
      break;
    }
    const char* f = functionSpelling(e.func);
    if (!f) {
      why = "the function has no LinuxCNC counterpart";
      return false;
    }
    out += f;
    return bracketed(a, out);
  }
};

} // namespace

bool expressionText(const ir::Expr& e, const VariableText& variable, std::string& out,
                    std::string& why) {
  return Printer{variable, why}.print(e, out);
}

bool wordValueText(const ir::Word& w, const VariableText& variable, std::string& out,
                   std::string& why) {
  if (w.kind == ir::ValueKind::Number) {
    emit::appendNumber(out, w.number);
    return true;
  }
  if (w.kind == ir::ValueKind::Path) {
    why = "a program called by file name";
    return false;
  }
  if (w.expr.kind == ir::ExprKind::Variable) return expressionText(w.expr, variable, out, why);
  std::string text;
  if (!expressionText(w.expr, variable, text, why)) return false;
  // a binary operation or a negation brings its brackets, a number needs none, a function them
  const bool number = text.find_first_not_of("-.0123456789") == std::string::npos;
  out += text.front() == '[' || number ? text : "[" + text + "]";
  return true;
}

bool conditionText(const ir::Condition& c, const VariableText& variable, std::string& out,
                   std::string& why) {
  out += '[';
  if (!expressionText(c.lhs, variable, out, why)) return false;
  out += ' ';
  out += ir::spelling(c.op);
  out += ' ';
  if (!expressionText(c.rhs, variable, out, why)) return false;
  out += ']';
  return true;
}

} // namespace gcx::ngc
