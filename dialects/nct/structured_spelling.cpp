#include "dialects/nct/structured_spelling.h"

#include <fmt/format.h>

#include "dialect/control_flow.h"
#include "dialects/nct/hole_writer.h"
#include "dialects/nct/profile.h"

namespace gcx::nct {

namespace {

constexpr int kLastProgram = 9999;

// The operators and functions of NCT's macro language (nct-macro.md §3): arithmetic, its bitwise
// logic, truncating MOD, FIX, FUP; no powers, relations inside expressions or rounding.
bool writes(const ir::Expr& e) {
  switch (e.kind) {
  case ir::ExprKind::Number:
  case ir::ExprKind::Variable:
  case ir::ExprKind::Bracket:
    return true;
  case ir::ExprKind::Unary:
    return e.op == ir::Op::Neg || e.op == ir::Op::Plus || e.op == ir::Op::Not;
  case ir::ExprKind::Binary:
    switch (e.op) {
    case ir::Op::Add:
    case ir::Op::Sub:
    case ir::Op::Mul:
    case ir::Op::Div:
    case ir::Op::Mod:
    case ir::Op::And:
    case ir::Op::Or:
    case ir::Op::Xor:
      return true;
    default:
      return false;
    }
  case ir::ExprKind::Call:
    return e.func != ir::Func::Round && e.func != ir::Func::Floor && e.func != ir::Func::Ceil &&
           e.func != ir::Func::Atan2;
  default:
    return false;
  }
}

ir::Comment comment(const std::string& text) {
  ir::Comment c;
  c.text = text;
  for (char& ch : c.text) // a parenthesis would end or nest the comment
    if (ch == '(' || ch == ')') ch = ch == '(' ? '[' : ']';
  return c;
}

ir::Block commentLine(const std::string& text) {
  ir::Block b;
  b.comments.push_back(comment(text));
  return b;
}

ir::Word word(const char* address, double v) {
  ir::Word w;
  w.address = address;
  w.number = v;
  return w;
}

std::string freeNumber(int preferred, const std::set<std::string>& taken) {
  if (preferred >= 1 && preferred <= kLastProgram && !taken.count(std::to_string(preferred)))
    return std::to_string(preferred);
  for (int n = kLastProgram; n >= 1; --n)
    if (!taken.count(std::to_string(n))) return std::to_string(n);
  return {};
}

xlate::StructuredSpelling make() {
  xlate::StructuredSpelling s;
  s.profile = &profile();
  s.label = "NCT";
  s.extension = ".nct";
  s.decimals = 3;        // the least input increment, 0.001 mm
  s.maxWhileNesting = 3; // DO1-DO3 (nct-macro.md §4.5)
  s.gotoJumps = true;
  s.maxCallTimes = 9999; // M98 P L (nct.md §5.1)
  s.writes = &writes;
  s.blockComment = &comment;
  s.commentLine = &commentLine;
  s.subprogramName = [](const std::string& source, const std::set<std::string>& taken) {
    return freeNumber(programNumber(source), taken);
  };
  s.mainName = [](const std::string& stem, const std::set<std::string>& taken) {
    return freeNumber(programNumber(stem), taken);
  };
  s.fileName = [](const std::string& unit) {
    return profile().controlFlow->programFiles(unit, ".nct").front();
  };
  s.opening = [](const std::string& unit, bool) {
    ir::Block o;
    o.words.push_back(word("O", std::stod(unit)));
    return std::vector<ir::Block>{o};
  };
  s.closing = [](const std::string&, bool) { return std::vector<ir::Block>{}; };
  s.call = [](ir::Block& b, const std::string& unit, long times) {
    for (ir::Word w : {word("M", 98), word("P", std::stod(unit))}) {
      w.order = static_cast<std::uint32_t>(b.words.size() + b.stmts.size());
      b.words.push_back(std::move(w));
    }
    if (times > 1) {
      ir::Word l = word("L", static_cast<double>(times));
      l.order = static_cast<std::uint32_t>(b.words.size() + b.stmts.size());
      b.words.push_back(std::move(l));
    }
  };
  s.holes = &makeHoleWriter;
  return s;
}

} // namespace

int programNumber(const std::string& name) {
  std::string digits;
  for (char c : name)
    if (c >= '0' && c <= '9') digits += c;
  if (digits.empty() || digits.size() > 4) return 1;
  const int n = std::stoi(digits);
  return n == 0 ? 1 : n;
}

const xlate::StructuredSpelling& structuredSpelling() {
  static const xlate::StructuredSpelling s = make();
  return s;
}

} // namespace gcx::nct
