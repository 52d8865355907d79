#include "dialects/wl4/block_items.h"

#include <algorithm>
#include <fmt/format.h>

#include "diag/codes.h"
#include "front/decimal_text.h"

namespace gcx::wl4 {

namespace {

constexpr std::size_t kMaxName = 80; // program name (wl4.md §1.2)

struct FuncName {
  std::string_view name;
  ir::Func func;
};
// wl4.md §6.3: FIX rounds down, FUP up, ROUND to nearest (ties away from zero)
constexpr FuncName kFunctions[] = {
    {"ABS", ir::Func::Abs},   {"COS", ir::Func::Cos},     {"ACOS", ir::Func::Acos},
    {"SIN", ir::Func::Sin},   {"ASIN", ir::Func::Asin},   {"TAN", ir::Func::Tan},
    {"EXP", ir::Func::Exp},   {"FIX", ir::Func::Floor},   {"FUP", ir::Func::Ceil},
    {"LN", ir::Func::Ln},     {"ROUND", ir::Func::Round}, {"SQRT", ir::Func::Sqrt},
    {"ATAN", ir::Func::Atan},
};

struct OpSpelling {
  std::string_view spelling;
  ir::Op op;
};
// longer spellings first: `**` before `*`, `<=` before `<`
constexpr OpSpelling kLevel1[] = {
    {"**", ir::Op::Pow}, {"*", ir::Op::Mul}, {"/", ir::Op::Div}, {"MOD", ir::Op::FloorMod}};
constexpr OpSpelling kLevel2[] = {
    {"==", ir::Op::Eq},        {"<>", ir::Op::Ne},          {"<=", ir::Op::Le},
    {">=", ir::Op::Ge},        {"<", ir::Op::Lt},           {">", ir::Op::Gt},
    {"+", ir::Op::Add},        {"-", ir::Op::Sub},          {"AND", ir::Op::LogicalAnd},
    {"OR", ir::Op::LogicalOr}, {"XOR", ir::Op::LogicalXor},
};

bool isLetter(char c) {
  return c >= 'A' && c <= 'Z';
}

} // namespace

std::optional<std::pair<std::size_t, ir::Op>> operatorAt(std::string_view s, int level) {
  const auto check = [&](const auto& table) -> std::optional<std::pair<std::size_t, ir::Op>> {
    for (const OpSpelling& o : table) {
      if (s.substr(0, o.spelling.size()) != o.spelling) continue;
      const std::size_t n = o.spelling.size();
      if (isLetter(o.spelling[0]) && n < s.size() && isLetter(s[n])) continue;
      return std::pair{n, o.op};
    }
    return std::nullopt;
  };
  return level == 1 ? check(kLevel1) : check(kLevel2);
}

void reportTooDeep(const front::RawBlock& raw, std::size_t at, diag::Engine& diags) {
  diags.error(diag::code::ExpressionTooDeep, rangeOf(raw, at, 1),
              fmt::format("expression nested more than {} levels deep", kMaxExpressionDepth));
}

SourceRange rangeOf(const front::RawBlock& raw, std::size_t pos, std::size_t len) {
  return raw.rangeAt(pos, std::max<std::size_t>(len, 1));
}

void startBlock(const front::RawBlock& raw, ir::Block& out) {
  out = ir::Block{};
  out.range = rangeOf(raw, 0, raw.text.size());
  out.lastLine = raw.lastLine();
}

void finishBlock(ir::Block& out) {
  if (out.words.empty() && out.stmts.empty() && !out.sequence && out.skipLevel == 0)
    out.kind = ir::BlockKind::CommentLine;
}

std::optional<long long> nValue(const front::RawBlock& raw, std::size_t at, std::size_t end,
                                const std::string& digits, diag::Engine& diags) {
  const long long n = digits.size() > 9 ? 0 : std::stoll(digits);
  if (n >= 1 && n <= 65535) return n;
  diags.error(diag::code::DataOutOfRange, rangeOf(raw, at, end - at),
              fmt::format("N{} is out of range: block numbers and labels are 1-65535 (wl4.md §1.4)",
                          digits));
  return std::nullopt;
}

void setSequence(const front::RawBlock& raw, ir::Block& out, std::size_t at, std::size_t end,
                 const std::string& digits, long long n) {
  out.sequence = n;
  out.sequenceText = digits;
  out.sequenceRange = rangeOf(raw, at, end - at);
}

void addJump(const front::RawBlock& raw, ir::Block& out, std::size_t at, std::size_t end,
             const std::string& digits, long long n) {
  ir::Stmt s;
  s.kind = ir::StmtKind::Jump;
  s.label = digits;
  s.value = ir::Expr::literal(static_cast<double>(n), rangeOf(raw, at + 1, digits.size()));
  s.range = rangeOf(raw, at, end - at);
  s.order = static_cast<std::uint32_t>(at);
  out.stmts.push_back(std::move(s));
}

bool addCall(const front::RawBlock& raw, ir::Block& out, std::size_t at, std::size_t end,
             const std::string& digits, diag::Engine& diags) {
  const SourceRange r = rangeOf(raw, at, end - at);
  if (digits.size() != 2 && digits.size() != 4) {
    diags.error(diag::code::Wl4CallWord, r,
                fmt::format("L{}: a call is L and 2 digits (program) or 4 digits (program and "
                            "repeat count), L07 or L0703 (wl4.md §6.7)",
                            digits));
    return false;
  }
  const int times = digits.size() == 4 ? std::stoi(digits.substr(2)) : 1;
  if (times == 0) {
    diags.error(
        diag::code::Wl4CallWord, r,
        fmt::format("L{}: repeat count 00; write L{} to call once", digits, digits.substr(0, 2)));
    return false;
  }
  ir::Stmt s;
  s.kind = ir::StmtKind::Call;
  s.callee = digits.substr(0, 2);
  s.value = ir::Expr::literal(times, r);
  s.range = r;
  s.order = static_cast<std::uint32_t>(at);
  out.stmts.push_back(std::move(s));
  return true;
}

std::optional<int> guardPrecision(const front::RawBlock& raw, std::size_t digitsAt,
                                  const std::string& digits, diag::Engine& diags) {
  if (digits.size() == 1) return std::stoi(digits);
  diags.error(diag::code::Wl4Syntax, rangeOf(raw, digitsAt, digits.size()),
              fmt::format("IF{}: the precision is one digit", digits));
  return std::nullopt;
}

bool checkProgramName(const front::RawBlock& raw, std::size_t nameAt, std::string_view name,
                      diag::Engine& diags) {
  if (name.size() <= kMaxName) return true;
  diags.error(diag::code::Wl4ProgramName, rangeOf(raw, nameAt, name.size()),
              fmt::format("program name of {} characters: at most {} (wl4.md §1.2)", name.size(),
                          kMaxName));
  return false;
}

void addMessage(const front::RawBlock& raw, ir::Block& out, std::size_t at, std::size_t end) {
  ir::Comment m;
  m.kind = ir::CommentKind::Message;
  m.text = raw.text.substr(at + 1, end - at - 1);
  while (!m.text.empty() && m.text.back() == ' ')
    m.text.pop_back();
  m.range = rangeOf(raw, at, end - at);
  m.order = static_cast<std::uint32_t>(at);
  out.comments.push_back(std::move(m));
}

void addLineComment(const front::RawBlock& raw, ir::Block& out) {
  if (raw.lineCommentAt == std::string::npos) return;
  ir::Comment c;
  c.kind = ir::CommentKind::ToLineEnd;
  const std::size_t at = raw.lineCommentAt;
  c.text = raw.text.substr(at + 1);
  while (!c.text.empty() && (c.text.back() == ' ' || c.text.back() == '\r'))
    c.text.pop_back();
  c.range = rangeOf(raw, at, raw.text.size() - at);
  c.order = static_cast<std::uint32_t>(at);
  out.comments.push_back(std::move(c));
}

const ir::Func* functionNamed(std::string_view name) {
  for (const FuncName& k : kFunctions)
    if (k.name == name) return &k.func;
  return nullptr;
}

void setLiteral(ir::Word& w, char sign, const std::string& number) {
  w.kind = ir::ValueKind::Number;
  w.number = front::decimalValue(number) * (sign == '-' ? -1 : 1);
  w.text = (sign == '-' ? "-" : "") + number;
}

} // namespace gcx::wl4
