#include "dialects/nct/fast_parser.h"

#include <cstdint>
#include <string_view>

namespace gcx::nct {

namespace {

bool isDigit(char c) {
  return static_cast<unsigned char>(c - '0') < 10;
}
bool isLetter(char c) {
  return static_cast<unsigned char>(c - 'A') < 26;
}

// 10^0 .. 10^15: exact doubles
constexpr double kPowersOfTen[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                   1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

// Scans a NUMBER token (grammar/NCT.g4): DIGIT+ ('.' DIGIT*)? | '.' DIGIT+ from p, which points
// into a NUL-terminated text (so the scan needs no bounds: NUL is no digit). Returns its end, or
// null when there is none. Reads its value on the way when it has at most 15 digits (exact):
// front::decimalValue's (Clinger's fast path: a mantissa below 10^15 and a power of ten up to
// 10^15 are exact doubles, and one division of exact operands is correctly rounded), and so many
// digits are never too many significant ones (nct.md §1.2 rule 2). Beyond 15 digits the mantissa
// wraps; it is not used then. Always inline: the value and exactness stay in registers.
[[gnu::always_inline]] inline const char* scanNumber(const char* p, double& value, bool& exact) {
  const char* const start = p;
  std::uint64_t mantissa = 0;
  for (; isDigit(*p); ++p)
    mantissa = mantissa * 10 + static_cast<std::uint64_t>(*p - '0');
  std::size_t digits = static_cast<std::size_t>(p - start), fraction = 0;
  if (*p == '.') {
    const char* const frac = ++p;
    for (; isDigit(*p); ++p)
      mantissa = mantissa * 10 + static_cast<std::uint64_t>(*p - '0');
    fraction = static_cast<std::size_t>(p - frac);
    if (digits == 0 && fraction == 0) return nullptr; // a lone '.'
    digits += fraction;
  } else if (digits == 0) {
    return nullptr;
  }
  exact = digits <= 15;
  if (exact) {
    const double m = static_cast<double>(mantissa);
    value = fraction > 0 ? m / kPowersOfTen[fraction] : m;
  }
  return p;
}

const char* skipBlanks(const char* p) {
  while (*p == ' ')
    ++p;
  return p;
}

} // namespace

FastResult parseFast(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags) {
  if (!raw.plain) return FastResult::Declined;
  // One pass: each piece goes into the block as soon as it is scanned. A block declined half way
  // is rebuilt from scratch by the grammar path, so what was written by then does not matter.
  const char* const s = raw.lexText.c_str(); // NUL-terminated: every scan below stops at it
  const auto at = [s](const char* q) { return static_cast<std::size_t>(q - s); };
  BlockBuilder b(raw, out, diags, true);
  const char* p = skipBlanks(s);
  // a comment's ')' is in the block: an LF inside a comment does not end it
  auto comment = [&] {
    const char* close = p;
    while (*close != ')' && *close)
      ++close;
    if (!*close) return false;
    b.comment(at(p), at(close) - at(p) + 1);
    p = skipBlanks(close + 1);
    return true;
  };
  // leading comments may precede '/': the grammar hides comments, so `(c) /2 X1` is legal too
  while (*p == '(')
    if (!comment()) return FastResult::Declined;
  if (*p == '/') {
    const char* const slash = p;
    p = skipBlanks(p + 1);
    const char* const digits = p;
    if (isDigit(*p) || *p == '.') {
      double unused = 0;
      bool exact = false;
      p = scanNumber(p, unused, exact);
      if (!p) return FastResult::Declined;
    }
    // a level with a diagnostic is the grammar path's to report
    if (!b.skip(at(slash), at(p) - at(slash), std::string_view(digits, at(p) - at(digits)), false))
      return FastResult::Declined;
  }
  bool anyWord = false;
  for (p = skipBlanks(p); *p; p = skipBlanks(p)) {
    if (*p == '(') {
      if (!comment()) return FastResult::Declined;
      continue;
    }
    const char letter = *p;
    if (!isLetter(letter)) return FastResult::Declined;
    const char* const start = p;
    p = skipBlanks(p + 1);
    const bool incremental = *p == 'I';
    if (incremental) p = skipBlanks(p + 1);
    char sign = 0;
    if (*p == '-' || *p == '+') {
      sign = *p;
      p = skipBlanks(p + 1);
    }
    const char* const digits = p;
    if (!(isDigit(*p) || *p == '.')) return FastResult::Declined;
    double value;
    bool exact;
    p = scanNumber(p, value, exact);
    if (!p) return FastResult::Declined;
    const std::size_t pos = at(start), len = at(p) - pos, count = at(p) - at(digits);
    // the grammar's `sequenceNumber : N PLUS? NUMBER` takes an N before any word, without a
    // minus (a `+` is discarded, nct.md §1.2 rule 3)
    const bool sequence = letter == 'N' && !anyWord && !incremental && sign != '-';
    anyWord = true;
    if (sequence) {
      if (!b.sequence(pos, len, std::string_view(digits, count), false))
        return FastResult::Declined;
    } else if (!exact) { // too many digits to read here; the grammar path reads or reports them
      return FastResult::Declined;
    } else if (!sign || digits[-1] == sign) {
      // the sign, if any, right before the digits: the text as written is one view
      const std::size_t signed_ = sign ? 1 : 0;
      b.literalWord(letter, pos, len, incremental, sign == '-',
                    std::string_view(digits - signed_, count + signed_), value);
    } else { // `X- 5`: the text drops the blank
      b.literalWord(std::string_view(start, 1), pos, len, incremental, sign,
                    std::string_view(digits, count));
    }
  }
  b.finish();
  return FastResult::Parsed;
}

} // namespace gcx::nct
