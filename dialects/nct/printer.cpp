#include "dialects/nct/printer.h"

#include "emit/number.h"

namespace gcx::nct {

namespace {

enum Level { Additive = 1, Multiplicative = 2, UnaryLevel = 3, Primary = 4 };

Level levelOf(const ir::Expr& e) {
  switch (e.kind) {
  case ir::ExprKind::Binary:
    switch (e.op) {
    case ir::Op::Add:
    case ir::Op::Sub:
    case ir::Op::Or:
    case ir::Op::Xor:
      return Additive;
    default:
      return Multiplicative;
    }
  case ir::ExprKind::Unary:
    return e.op == ir::Op::Not ? Primary : UnaryLevel;
  case ir::ExprKind::Number:
    return e.number < 0 ? UnaryLevel : Primary;
  default:
    return Primary;
  }
}

bool isKeywordOp(ir::Op op) {
  return op == ir::Op::Mod || op == ir::Op::And || op == ir::Op::Or || op == ir::Op::Xor;
}

void print(std::string& out, const ir::Expr& e, Level need);

void printAt(std::string& out, const ir::Expr& e, Level need) {
  if (levelOf(e) < need) {
    out += '[';
    print(out, e, Additive);
    out += ']';
  } else {
    print(out, e, need);
  }
}

void print(std::string& out, const ir::Expr& e, Level) {
  switch (e.kind) {
  case ir::ExprKind::Number:
    emit::appendNumber(out, e.number);
    return;
  case ir::ExprKind::Variable:
    out += '#';
    emit::appendNumber(out, e.number);
    return;
  case ir::ExprKind::Indirect:
    out += "#[";
    print(out, e.args[0], Additive);
    out += ']';
    return;
  case ir::ExprKind::Named:
    out += "#_" + e.name;
    if (!e.args.empty()) {
      out += '[';
      print(out, e.args[0], Additive);
      out += ']';
    }
    return;
  case ir::ExprKind::Bracket:
    out += '[';
    print(out, e.args[0], Additive);
    out += ']';
    return;
  case ir::ExprKind::Unary:
    if (e.op == ir::Op::Not) {
      out += "NOT ";
      printAt(out, e.args[0], Primary);
    } else {
      out += e.op == ir::Op::Neg ? '-' : '+';
      printAt(out, e.args[0], UnaryLevel);
    }
    return;
  case ir::ExprKind::Binary: {
    const Level mine = levelOf(e);
    printAt(out, e.args[0], mine);
    if (isKeywordOp(e.op)) {
      out += ' ';
      out += ir::spelling(e.op);
      out += ' ';
    } else {
      out += ir::spelling(e.op);
    }
    printAt(out, e.args[1], static_cast<Level>(mine + 1));
    return;
  }
  case ir::ExprKind::Call: {
    out += ir::spelling(e.func);
    const ir::Expr& a = e.args[0];
    if (a.kind == ir::ExprKind::Call || a.kind == ir::ExprKind::AxisNumber ||
        a.kind == ir::ExprKind::Parameter || (a.kind == ir::ExprKind::Unary && a.op == ir::Op::Not))
      out += ' ';
    printAt(out, a, Primary);
    return;
  }
  case ir::ExprKind::AxisNumber:
    out += "AXNUM[" + e.name + "]";
    return;
  case ir::ExprKind::Assign: // WL4's #n=e in an expression: not NCT, lowered by translation
    return;
  case ir::ExprKind::Parameter: {
    out += "PRM[";
    print(out, e.args[0], Additive);
    std::size_t next = 1;
    if (e.prmHasBit) {
      out += ',';
      print(out, e.args[next++], Additive);
    }
    out += ']';
    if (e.prmHasIndex) {
      out += "/[";
      print(out, e.args[next], Additive);
      out += ']';
    }
    return;
  }
  }
}

// A word value must be a literal, a (signed) variable or a (signed) bracket (grammar `value`).
void printValue(std::string& out, const ir::Word& w) {
  switch (w.kind) {
  case ir::ValueKind::Number:
    emit::appendNumber(out, w.number);
    return;
  case ir::ValueKind::Path:
    out += w.text + '>';
    return; // '<' is the address
  case ir::ValueKind::Expression:
    break;
  }
  const ir::Expr* e = &w.expr;
  if (e->kind == ir::ExprKind::Unary && e->op != ir::Op::Not) {
    out += e->op == ir::Op::Neg ? '-' : '+';
    e = &e->args[0];
  }
  const bool direct = e->kind == ir::ExprKind::Variable || e->kind == ir::ExprKind::Indirect ||
                      e->kind == ir::ExprKind::Named || e->kind == ir::ExprKind::Bracket;
  if (direct) {
    print(out, *e, Primary);
  } else {
    out += '[';
    print(out, *e, Additive);
    out += ']';
  }
}

void printCondition(std::string& out, const ir::Condition& c) {
  out += '[';
  print(out, c.lhs, Additive);
  out += ' ';
  out += ir::spelling(c.op);
  out += ' ';
  print(out, c.rhs, Additive);
  out += ']';
}

void printAssignment(std::string& out, const ir::Stmt& s) {
  print(out, s.target, Primary);
  out += '=';
  print(out, s.value, Additive);
}

void printStatement(std::string& out, const ir::Stmt& s) {
  switch (s.kind) {
  case ir::StmtKind::Assign:
    printAssignment(out, s);
    return;
  case ir::StmtKind::Goto:
    out += "GOTO ";
    print(out, s.value, Additive);
    return;
  case ir::StmtKind::IfGoto:
    out += "IF";
    printCondition(out, *s.cond);
    out += " GOTO ";
    print(out, s.value, Additive);
    return;
  case ir::StmtKind::IfThen:
    out += "IF";
    printCondition(out, *s.cond);
    out += " THEN ";
    printAssignment(out, s);
    return;
  case ir::StmtKind::While:
    out += "WHILE";
    printCondition(out, *s.cond);
    out += " DO" + std::to_string(s.loopId);
    return;
  case ir::StmtKind::Do:
    out += "DO" + std::to_string(s.loopId);
    return;
  case ir::StmtKind::End:
    out += "END" + std::to_string(s.loopId);
    return;
  case ir::StmtKind::Print:
    out += s.binaryPrint ? "BPRNT[" : "DPRNT[";
    for (const ir::PrintItem& it : s.items) {
      if (!it.isVariable) {
        out += it.text;
        continue;
      }
      out += '#' + std::to_string(it.variable);
      if (it.intDigits || it.fracDigits)
        out += '[' + std::to_string(it.intDigits) + std::to_string(it.fracDigits) + ']';
    }
    out += ']';
    return;
  case ir::StmtKind::Popen:
  case ir::StmtKind::Pclos:
    out += s.kind == ir::StmtKind::Popen ? "POPEN" : "PCLOS";
    if (s.device) emit::appendNumber(out, *s.device);
    return;
  case ir::StmtKind::Fopen:
    out += "FOPEN";
    emit::appendNumber(out, s.device.value_or(0));
    if (s.program) {
      out += " P";
      emit::appendNumber(out, *s.program);
    } else {
      out += " <" + s.path + ">";
    }
    return;
  case ir::StmtKind::Fclos:
    out += "FCLOS";
    return;
  case ir::StmtKind::Guard: // other dialects' statements: the NCT front end never builds them,
  case ir::StmtKind::Jump:  // and translation lowers them before NCT is printed
  case ir::StmtKind::Call:
  case ir::StmtKind::CycleCall:
    return;
  }
}

} // namespace

std::string printExpr(const ir::Expr& e) {
  std::string out;
  print(out, e, Additive);
  return out;
}

std::string printBlock(const ir::Block& b) {
  std::string out;
  auto sep = [&] {
    if (!out.empty()) out += ' ';
  };
  if (b.kind == ir::BlockKind::ProgramStart) {
    out += '%';
    out += b.programName;
  }
  if (b.skipLevel) out += b.skipLevel == 1 ? std::string("/") : '/' + std::to_string(b.skipLevel);
  if (b.sequence) {
    sep();
    out += 'N' + std::to_string(*b.sequence);
  }
  for (const ir::Stmt& s : b.stmts) {
    sep();
    printStatement(out, s);
  }
  for (const ir::Word& w : b.words) {
    sep();
    if (w.address == "AX") {
      out += "AX[";
      print(out, w.axisIndex.front(), Additive);
      out += "]=";
    } else if (w.kind == ir::ValueKind::Path) {
      out += '<';
    } else {
      out += w.address;
    }
    if (w.incremental) out += 'I';
    printValue(out, w);
  }
  for (const ir::Comment& c : b.comments) {
    sep();
    out += '(' + c.text + ')';
  }
  return out;
}

} // namespace gcx::nct
