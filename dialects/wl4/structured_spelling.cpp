#include "dialects/wl4/structured_spelling.h"

#include <fmt/format.h>

#include "dialects/wl4/hole_writer.h"
#include "dialects/wl4/profile.h"
#include "translate/flat_writer.h"

namespace gcx::wl4 {

namespace {

// The operators and functions of WL4's expressions (wl4.md §6.3): arithmetic with ** and a
// floored MOD, relations and logic giving 1 or 0, ROUND, FIX (down), FUP (up), ATAN(a)/(b).
bool writes(const ir::Expr& e) {
  switch (e.kind) {
  case ir::ExprKind::Number:
  case ir::ExprKind::Variable:
  case ir::ExprKind::Bracket:
    return true;
  case ir::ExprKind::Unary:
    return e.op == ir::Op::Neg || e.op == ir::Op::Plus;
  case ir::ExprKind::Binary:
    switch (e.op) {
    case ir::Op::Mod:
    case ir::Op::And:
    case ir::Op::Or:
    case ir::Op::Xor:
    case ir::Op::Not:
      return false;
    default:
      return true;
    }
  case ir::ExprKind::Call:
    return e.func != ir::Func::Fix && e.func != ir::Func::Fup && e.func != ir::Func::Atan;
  default:
    return false;
  }
}

ir::Comment comment(const std::string& text) {
  ir::Comment c;
  c.text = text;
  c.kind = ir::CommentKind::ToLineEnd;
  return c;
}

bool reserved(int n) {
  return n >= 81 && n <= 89; // the canned-cycle programs (§5.2)
}

// `%nn`: a two-digit name for a program `L nn` calls (wl4.md §6.7), the source's number when it
// has one below 100.
std::string subprogramName(const std::string& source, const std::set<std::string>& taken) {
  const bool digits = !source.empty() && source.size() <= 9 &&
                      source.find_first_not_of("0123456789") == std::string::npos;
  if (digits && std::stoi(source) <= 99) {
    const std::string name = fmt::format("{:02}", std::stoi(source));
    if (!reserved(std::stoi(source)) && !taken.count(name)) return name;
  }
  for (int n = 99; n >= 2; --n)
    if (!reserved(n) && !taken.count(fmt::format("{:02}", n))) return fmt::format("{:02}", n);
  return {};
}

xlate::StructuredSpelling make() {
  xlate::StructuredSpelling s;
  s.profile = &profile();
  s.label = "WL4";
  s.extension = ".wl4";
  s.decimals = 3; // resolution 0.001 mm (002:40)
  s.guardJumps = true;
  s.maxLabels = 127; // per program (002:2020-2021)
  s.statementsBesideWords = true;
  s.maxCallTimes = 99; // L nnpp
  s.writes = &writes;
  s.blockComment = &comment;
  s.commentLine = &emit::lineComment;
  s.unitsInOneFile = true;
  s.subprogramName = &subprogramName;
  s.mainName = [](const std::string& stem, const std::set<std::string>&) {
    return mainProgramName(stem);
  };
  s.fileName = [](const std::string& unit) { return unit + ".wl4"; };
  s.opening = [](const std::string& unit, bool) {
    ir::Block b;
    b.kind = ir::BlockKind::ProgramStart;
    b.programName = unit;
    return std::vector<ir::Block>{b};
  };
  s.closing = [](const std::string&, bool) {
    ir::Block b;
    b.kind = ir::BlockKind::ProgramEnd;
    return std::vector<ir::Block>{b};
  };
  s.call = [](ir::Block& b, const std::string& unit, long times) {
    ir::Stmt c;
    c.kind = ir::StmtKind::Call;
    c.callee = unit;
    c.value = ir::Expr::literal(static_cast<double>(times));
    c.order = static_cast<std::uint32_t>(b.words.size() + b.stmts.size());
    b.stmts.push_back(std::move(c));
  };
  s.holes = &makeHoleWriter;
  return s;
}

} // namespace

std::string mainProgramName(const std::string& name) {
  std::string upper;
  bool digitsOnly = true;
  for (char c : name) {
    const bool digit = c >= '0' && c <= '9';
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    if (!digit && !(c >= 'A' && c <= 'Z') && c != '_') return "MAIN";
    digitsOnly = digitsOnly && digit;
    upper += c;
  }
  const bool ok = !upper.empty() && upper.size() <= 80 && !(digitsOnly && upper.size() <= 2);
  return ok ? upper : "MAIN";
}

const xlate::StructuredSpelling& structuredSpelling() {
  static const xlate::StructuredSpelling s = make();
  return s;
}

} // namespace gcx::wl4
