#include "dialects/wl4/printer.h"

#include <fmt/format.h>

#include "emit/number.h"
#include "ir/items.h"

namespace gcx::wl4 {

namespace {

const char* opText(ir::Op op) {
  switch (op) {
  case ir::Op::Neg:
  case ir::Op::Sub:
    return "-";
  case ir::Op::Plus:
  case ir::Op::Add:
    return "+";
  case ir::Op::Mul:
    return "*";
  case ir::Op::Div:
    return "/";
  case ir::Op::Pow:
    return "**";
  case ir::Op::FloorMod:
    return " MOD ";
  case ir::Op::Eq:
    return "==";
  case ir::Op::Ne:
    return "<>";
  case ir::Op::Lt:
    return "<";
  case ir::Op::Le:
    return "<=";
  case ir::Op::Gt:
    return ">";
  case ir::Op::Ge:
    return ">=";
  case ir::Op::LogicalAnd:
    return " AND ";
  case ir::Op::LogicalOr:
    return " OR ";
  case ir::Op::LogicalXor:
    return " XOR ";
  default: // NCT's bitwise and truncating operators have no WL4 spelling
    return nullptr;
  }
}

const char* funcText(ir::Func f) {
  switch (f) {
  case ir::Func::Sin:
    return "SIN";
  case ir::Func::Cos:
    return "COS";
  case ir::Func::Tan:
    return "TAN";
  case ir::Func::Asin:
    return "ASIN";
  case ir::Func::Acos:
    return "ACOS";
  case ir::Func::Atan:
  case ir::Func::Atan2:
    return "ATAN";
  case ir::Func::Sqrt:
    return "SQRT";
  case ir::Func::Exp:
    return "EXP";
  case ir::Func::Ln:
    return "LN";
  case ir::Func::Abs:
    return "ABS";
  case ir::Func::Round:
    return "ROUND";
  case ir::Func::Floor:
    return "FIX";
  case ir::Func::Ceil:
    return "FUP";
  default: // NCT's truncating FIX and FUP have no WL4 spelling
    return nullptr;
  }
}

// 2: ** * / MOD, evaluated first; 1: every other binary operator (wl4.md §6.3)
int level(ir::Op op) {
  return op == ir::Op::Pow || op == ir::Op::Mul || op == ir::Op::Div || op == ir::Op::FloorMod ? 2
                                                                                               : 1;
}

// A word's value: number | #n [= factor] | #(e) | (e), each with an optional sign (§1.5)
bool simpleValue(const ir::Expr& e) {
  const ir::Expr* x = &e;
  if (x->kind == ir::ExprKind::Unary) x = &x->args[0];
  return x->kind == ir::ExprKind::Number || x->kind == ir::ExprKind::Variable ||
         x->kind == ir::ExprKind::Indirect || x->kind == ir::ExprKind::Bracket ||
         x->kind == ir::ExprKind::Assign;
}

void appendItem(std::string& out, const std::string& text) {
  if (!out.empty() && out.back() != ' ' && out.back() != '/') out += ' ';
  out += text;
}

} // namespace

std::string printExpr(const ir::Expr& e) {
  switch (e.kind) {
  case ir::ExprKind::Number:
    return emit::formatNumber(e.number);
  case ir::ExprKind::Variable:
    return "#" + emit::formatNumber(e.number);
  case ir::ExprKind::Indirect:
    return "#(" + printExpr(e.args[0]) + ")";
  case ir::ExprKind::Bracket:
    return "(" + printExpr(e.args[0]) + ")";
  case ir::ExprKind::Unary: // a sign binds to the primary after it
    return std::string(opText(e.op) ? opText(e.op) : "-") + (e.args[0].kind == ir::ExprKind::Binary
                                                                 ? "(" + printExpr(e.args[0]) + ")"
                                                                 : printExpr(e.args[0]));
  case ir::ExprKind::Binary: {
    // two levels, each left to right (§6.3): a right operand of the same level, or an operand of
    // the looser level under the tighter one, is parenthesised (a parsed program keeps its own
    // parentheses as Bracket nodes, so it prints as written)
    const char* op = opText(e.op);
    const auto operand = [&](const ir::Expr& a, bool right) {
      const bool apart = a.kind == ir::ExprKind::Binary &&
                         (level(a.op) < level(e.op) || (right && level(a.op) == level(e.op)));
      return apart ? "(" + printExpr(a) + ")" : printExpr(a);
    };
    return operand(e.args[0], false) + (op ? op : "?") + operand(e.args[1], true);
  }
  case ir::ExprKind::Call: {
    const char* f = funcText(e.func);
    std::string s = std::string(f ? f : "?") + "(" + printExpr(e.args[0]) + ")";
    if (e.func == ir::Func::Atan2) s += "/(" + printExpr(e.args[1]) + ")";
    return s;
  }
  case ir::ExprKind::Assign:
    return printExpr(e.args[0]) + "=" + printExpr(e.args[1]);
  default: // NCT's #_NAME, PRM[] and AXNUM[] have no WL4 spelling
    return "?";
  }
}

std::string printBlock(const ir::Block& b) {
  if (b.kind == ir::BlockKind::ProgramStart || b.kind == ir::BlockKind::ProgramEnd) {
    // a unit line keeps its comments (`%P $PLATE`), as fmt keeps every comment
    std::string line = b.kind == ir::BlockKind::ProgramStart ? "%" + b.programName : "%";
    for (const ir::Comment& c : b.comments)
      appendItem(line, (c.kind == ir::CommentKind::Message ? "." : "$") + c.text);
    return line;
  }
  std::string out;
  if (b.skipLevel) out += "/";
  if (b.sequence) appendItem(out, "N" + b.sequenceText);
  ir::forEachItem(b, [&](ir::ItemRef r) {
    switch (r.kind) {
    case ir::ItemKind::Word: {
      const ir::Word& w = b.words[r.index];
      if (w.isLiteral())
        appendItem(out, w.address + emit::formatNumber(w.number));
      else
        appendItem(out, w.address + (simpleValue(w.expr) ? printExpr(w.expr)
                                                         : "(" + printExpr(w.expr) + ")"));
      break;
    }
    case ir::ItemKind::Stmt: {
      const ir::Stmt& s = b.stmts[r.index];
      switch (s.kind) {
      case ir::StmtKind::Assign:
        appendItem(out, printExpr(s.target) + "=" + printExpr(s.value));
        break;
      case ir::StmtKind::Guard:
        appendItem(out,
                   "IF" + (s.precision ? std::to_string(*s.precision) : std::string()) +
                       (s.value.kind == ir::ExprKind::Bracket ? printExpr(s.value)
                                                              : "(" + printExpr(s.value) + ")"));
        break;
      case ir::StmtKind::Jump:
        appendItem(out, "N" + s.label);
        break;
      case ir::StmtKind::Call: {
        const long times = std::lround(s.value.number);
        appendItem(out, "L" + s.callee + (times == 1 ? "" : fmt::format("{:02}", times)));
        break;
      }
      default: // NCT's statements have no WL4 spelling; expand flattens them first
        appendItem(out, "$?");
      }
      break;
    }
    case ir::ItemKind::Comment: {
      const ir::Comment& c = b.comments[r.index];
      appendItem(out, (c.kind == ir::CommentKind::Message ? "." : "$") + c.text);
      break;
    }
    }
  });
  return out;
}

} // namespace gcx::wl4
