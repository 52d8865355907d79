#include "dialects/ngc/structured_spelling.h"

#include <fmt/format.h>

#include "dialects/ngc/hole_writer.h"
#include "dialects/ngc/profile.h"

namespace gcx::ngc {

namespace {

// What dialects/ngc/expression.h writes with the same meaning: not NCT's bitwise logic or its
// truncating MOD (FIX, FUP and one-argument ATAN it writes in LinuxCNC's own terms).
bool writes(const ir::Expr& e) {
  switch (e.kind) {
  case ir::ExprKind::Number:
  case ir::ExprKind::Variable:
  case ir::ExprKind::Bracket:
  case ir::ExprKind::Call:
    return true;
  case ir::ExprKind::Unary:
    return e.op == ir::Op::Neg || e.op == ir::Op::Plus;
  case ir::ExprKind::Binary:
    return e.op != ir::Op::Mod && e.op != ir::Op::And && e.op != ir::Op::Or && e.op != ir::Op::Xor;
  default:
    return false;
  }
}

ir::Comment comment(const std::string& text) {
  ir::Comment c;
  c.text = text;
  return c;
}

ir::Block commentLine(const std::string& text) {
  ir::Block b;
  b.comments.push_back(comment(text));
  return b;
}

// o<n> with the source's number where it is one, else a free one from 9999 down
std::string subprogramName(const std::string& source, const std::set<std::string>& taken) {
  const bool digits = !source.empty() && source.size() <= 5 &&
                      source.find_first_not_of("0123456789") == std::string::npos;
  if (digits) {
    const std::string n = std::to_string(std::stoi(source));
    if (!taken.count(n)) return n;
  }
  for (int n = 9999; n >= 1; --n)
    if (!taken.count(std::to_string(n))) return std::to_string(n);
  return {};
}

xlate::StructuredSpelling make() {
  xlate::StructuredSpelling s;
  s.profile = &profile();
  s.label = "LinuxCNC";
  s.extension = ".ngc";
  s.decimals = 4;
  s.maxWhileNesting = 1000; // o-word loops nest freely
  s.uniqueLoopIds = true;
  s.doWhileLoops = true;
  s.callsAlone = true;
  s.returnAtEnd = true;
  s.subprogramsFirst = true;
  s.maxCallTimes = 1; // more runs: a counted loop around the call
  s.writes = &writes;
  s.blockComment = &comment;
  s.commentLine = &commentLine;
  s.unitsInOneFile = true;
  s.subprogramName = &subprogramName;
  s.mainName = [](const std::string&, const std::set<std::string>&) { return std::string(); };
  s.fileName = [](const std::string& unit) { return unit + ".ngc"; };
  s.opening = [](const std::string& unit, bool main) {
    std::vector<ir::Block> out;
    if (main) return out;
    ir::Block b;
    b.kind = ir::BlockKind::ProgramStart;
    b.programName = unit;
    out.push_back(std::move(b));
    return out;
  };
  s.closing = [](const std::string& unit, bool main) {
    std::vector<ir::Block> out;
    if (main) return out;
    ir::Block b;
    b.kind = ir::BlockKind::ProgramEnd;
    b.programName = unit;
    out.push_back(std::move(b));
    return out;
  };
  s.call = [](ir::Block& b, const std::string& unit, long) {
    ir::Stmt c;
    c.kind = ir::StmtKind::Call;
    c.callee = unit;
    c.value = ir::Expr::literal(1);
    b.stmts.push_back(std::move(c));
  };
  s.holes = &makeHoleWriter;
  return s;
}

} // namespace

const xlate::StructuredSpelling& structuredSpelling() {
  static const xlate::StructuredSpelling s = make();
  return s;
}

} // namespace gcx::ngc
