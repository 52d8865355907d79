#include "dialects/nct/block_builder.h"

#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"
#include "front/decimal_text.h"

namespace gcx::nct {

namespace {
constexpr int kMaxSignificantDigits = 15; // nct.md §1.2 rule 2 (000:2713)

int significantDigits(std::string_view digits) {
  int n = 0;
  bool leading = true;
  for (char c : digits) {
    if (c == '.') continue;
    if (leading && c == '0') continue;
    leading = false;
    ++n;
  }
  // trailing zeros after the point are not significant either
  if (digits.find('.') != std::string_view::npos) {
    for (auto it = digits.rbegin(); it != digits.rend() && (*it == '0' || *it == '.'); ++it)
      if (*it == '0' && n > 0) --n;
  }
  return n;
}
} // namespace

bool wholeNumber(std::string_view digits, std::int64_t& value) {
  auto dot = digits.find('.');
  std::string_view intPart = digits.substr(0, dot);
  if (dot != std::string_view::npos)
    for (char c : digits.substr(dot + 1))
      if (c != '0') return false;
  value = 0;
  for (char c : intPart) {
    if (value > 999999999999LL) return false;
    value = value * 10 + (c - '0');
  }
  return true;
}

BlockBuilder::BlockBuilder(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags,
                           bool reuseWords)
    : raw_(raw), out_(out), diags_(diags), reuse_(reuseWords) {
  // reset field by field: clearing keeps the vectors' capacity for the next block
  out_.kind = ir::BlockKind::Normal;
  out_.skipLevel = 0;
  out_.sequence.reset();
  out_.sequenceText.clear();
  out_.sequenceRange = {};
  out_.programName.clear();
  if (reuse_)
    reusable_ = out_.words.size();
  else
    out_.words.clear();
  out_.stmts.clear();
  out_.comments.clear();
  // field by field: a SourceRange built in a temporary and then copied makes the copy's wide
  // loads wait for the temporary's narrow stores (a failed store forwarding), every block
  out_.range.begin = raw.begin;
  out_.range.length = static_cast<std::uint32_t>(raw.text.size());
  out_.lastLine = raw.lastLine();
}

double BlockBuilder::number(std::string_view digits, std::size_t pos) {
  if (significantDigits(digits) > kMaxSignificantDigits) {
    diags_.error(diag::code::TooManyDigits, range(pos, digits.size()),
                 fmt::format("number '{}' has more than {} significant digits", digits,
                             kMaxSignificantDigits));
    ok_ = false;
  }
  return front::decimalValue(digits);
}

bool BlockBuilder::skip(std::size_t pos, std::size_t len, std::string_view digits, bool report) {
  std::int64_t level = 1;
  if (!digits.empty()) {
    if (!wholeNumber(digits, level) || level < 1 || level > 9) {
      if (!report) return false;
      diags_.error(diag::code::DataOutOfRange, range(pos, len),
                   fmt::format("block skip level '{}' is out of range 1-9", digits));
      ok_ = false;
      return false;
    }
    if (level == 9) {
      if (!report) return false;
      diags_.warning(diag::code::SkipLevelNine, range(pos, len),
                     "block skip level 9: the manual's chapter 14 allows only 1-8 (nct.md Q3)");
    }
  }
  out_.skipLevel = static_cast<int>(level);
  return true;
}

bool BlockBuilder::sequence(std::size_t pos, std::size_t len, std::string_view digits,
                            bool report) {
  std::int64_t n = 0;
  if (!wholeNumber(digits, n)) {
    if (!report) return false;
    diags_.error(diag::code::SyntaxError, range(pos, len),
                 fmt::format("block number 'N{}' must be a whole number", digits));
    ok_ = false;
    return false;
  }
  out_.sequence = n;
  out_.sequenceText.assign(digits);
  out_.sequenceRange = range(pos, len);
  return true;
}

void BlockBuilder::programStart(std::size_t pos, std::string_view number) {
  out_.kind = ir::BlockKind::ProgramStart;
  if (number.empty()) return;
  std::int64_t n = 0;
  if (!wholeNumber(number, n)) {
    diags_.error(diag::code::SyntaxError, range(pos, 1), "program number must be a whole number");
    ok_ = false;
    return;
  }
  out_.programName = fmt::format("O{:04}", n); // the number names the program: O1 is O0001
}

ir::Stmt& BlockBuilder::newStmt(ir::StmtKind kind, std::size_t pos, std::size_t len) {
  ir::Stmt& s = out_.stmts.emplace_back();
  s.kind = kind;
  s.range = range(pos, len);
  s.order = static_cast<std::uint32_t>(pos);
  return s;
}

namespace {
// A word of an earlier block made equal to a new ir::Word, keeping its strings' storage.
void resetWord(ir::Word& w) {
  w.incremental = false;
  w.kind = ir::ValueKind::Number;
  w.number = 0;
  w.text.clear();
  ir::resetExpr(w.expr);
  w.axisIndex.clear();
}
} // namespace

ir::Word& BlockBuilder::newWord(std::string_view address, std::size_t pos, std::size_t len) {
  bool reused = false;
  ir::Word& w = nextWord(reused);
  if (reused) resetWord(w);
  if (address.size() == 1 && w.address.size() == 1)
    w.address[0] = address[0]; // the usual case of a reused word: one letter for another
  else
    w.address.assign(address);
  w.range = range(pos, len);
  w.order = static_cast<std::uint32_t>(pos);
  return w;
}

void BlockBuilder::literalWord(std::string_view address, std::size_t pos, std::size_t len,
                               bool incremental, char signText, std::string_view digits) {
  const bool negative = signText == '-';
  ir::Word& w = newWord(address, pos, len);
  w.incremental = incremental;
  w.kind = ir::ValueKind::Number;
  const std::size_t numPos = pos + len - digits.size();
  double v = number(digits, numPos);
  w.number = negative ? -v : v;
  if (signText) w.text.push_back(signText);
  w.text.append(digits);
}

void BlockBuilder::comment(std::size_t pos, std::size_t len) {
  ir::Comment c;
  c.text = raw_.text.substr(pos + 1, len >= 2 ? len - 2 : 0);
  c.range = range(pos, len);
  c.order = static_cast<std::uint32_t>(pos);
  out_.comments.push_back(std::move(c));
}

} // namespace gcx::nct
