#include "dialects/nct/fast_parser.h"

#include <array>
#include <cstdint>
#include <string_view>

namespace gcx::nct {

namespace {

// No member initializers: a block's buffer of pieces is left uninitialised; newPiece sets all.
struct Piece {
  enum Kind : unsigned char { Skip, Sequence, Word, Comment } kind;
  char letter;
  bool incremental;
  char sign;         // '-', '+' or none
  std::uint32_t pos; // first byte of the piece
  std::uint32_t len;
  std::uint32_t digitsPos;
  std::uint32_t digitsLen;
  double value; // Word: the digits' value, when exact (see exact)
  bool exact;   // Word: at most 15 digits, value set
};

Piece newPiece(Piece::Kind kind, std::size_t pos) {
  Piece p;
  p.kind = kind;
  p.letter = p.sign = 0;
  p.incremental = false;
  p.pos = static_cast<std::uint32_t>(pos);
  p.len = p.digitsPos = p.digitsLen = 0;
  p.value = 0;
  p.exact = false;
  return p;
}

Piece commentPiece(std::size_t pos, std::size_t len) {
  Piece p = newPiece(Piece::Comment, pos);
  p.len = static_cast<std::uint32_t>(len);
  return p;
}

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}
bool isLetter(char c) {
  return c >= 'A' && c <= 'Z';
}

// 10^0 .. 10^15: exact doubles
constexpr double kPowersOfTen[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                   1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

// Scans a NUMBER token (grammar/NCT.g4): DIGIT+ ('.' DIGIT*)? | '.' DIGIT+, and reads its value
// on the way when it has at most 15 digits (exact: then true). The value is front::decimalValue's
// (Clinger's fast path: a mantissa below 10^15 and a power of ten up to 10^15 are exact doubles,
// and one division of exact operands is correctly rounded), and so many digits are never too
// many significant ones (nct.md §1.2 rule 2).
// The text is a string_view and the position a local: writes through a reference would make
// the compiler reload both for every digit.
bool scanNumber(std::string_view s, std::size_t& pos, double& value, bool& exact) {
  std::size_t i = pos;
  const std::size_t start = i;
  std::uint64_t mantissa = 0;
  while (i < s.size() && isDigit(s[i]))
    mantissa = mantissa * 10 + static_cast<std::uint64_t>(s[i++] - '0');
  std::size_t digits = i - start, fraction = 0;
  if (i < s.size() && s[i] == '.') {
    ++i;
    const std::size_t frac = i;
    while (i < s.size() && isDigit(s[i]) && digits + (i - frac) <= 15)
      mantissa = mantissa * 10 + static_cast<std::uint64_t>(s[i++] - '0');
    while (i < s.size() && isDigit(s[i]))
      ++i;
    pos = i;
    if (frac == start + 1 && i == frac) return false; // a lone '.'
    fraction = i - frac;
    digits += fraction;
  }
  pos = i;
  exact = digits <= 15;
  if (exact) {
    const double m = static_cast<double>(mantissa);
    value = fraction > 0 ? m / kPowersOfTen[fraction] : m;
  }
  return i > start;
}

} // namespace

FastResult parseFast(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags) {
  if (!raw.plain) return FastResult::Declined;
  const std::string_view s = raw.lexText;
  const std::size_t n = s.size();
  // A block rarely has more than a dozen words; a fixed buffer keeps the fast path allocation-free.
  std::array<Piece, 48> pieces;
  std::size_t count = 0;
  bool anyWord = false;
  std::size_t i = 0;
  auto skipBlanks = [&] {
    while (i < n && s[i] == ' ')
      ++i;
  };
  auto push = [&](const Piece& p) {
    if (count == pieces.size()) return false;
    pieces[count++] = p;
    return true;
  };

  skipBlanks();
  // leading comments may precede '/': the grammar hides comments, so `(c) /2 X1` is legal too
  while (i < n && s[i] == '(') {
    std::size_t close = s.find(')', i);
    if (!push(commentPiece(i, close - i + 1))) return FastResult::Declined;
    i = close + 1;
    skipBlanks();
  }
  if (i < n && s[i] == '/') {
    Piece p = newPiece(Piece::Skip, i);
    ++i;
    skipBlanks();
    std::size_t d = i;
    if (i < n && (isDigit(s[i]) || s[i] == '.')) {
      double unused = 0;
      bool exact = false;
      if (!scanNumber(s, i, unused, exact)) return FastResult::Declined;
      p.digitsPos = static_cast<std::uint32_t>(d);
      p.digitsLen = static_cast<std::uint32_t>(i - d);
    }
    p.len = static_cast<std::uint32_t>(i - p.pos);
    if (!push(p)) return FastResult::Declined;
  }
  while (true) {
    skipBlanks();
    if (i >= n) break;
    const char c = s[i];
    if (c == '(') {
      std::size_t close = s.find(')', i);
      if (!push(commentPiece(i, close - i + 1))) return FastResult::Declined;
      i = close + 1;
      continue;
    }
    if (!isLetter(c)) return FastResult::Declined;
    Piece p = newPiece(Piece::Word, i);
    p.letter = c;
    ++i;
    skipBlanks();
    if (i < n && s[i] == 'I') {
      p.incremental = true;
      ++i;
      skipBlanks();
    }
    if (i < n && (s[i] == '-' || s[i] == '+')) {
      p.sign = s[i];
      ++i;
      skipBlanks();
    }
    const std::size_t d = i;
    if (i >= n || !(isDigit(s[i]) || s[i] == '.') || !scanNumber(s, i, p.value, p.exact))
      return FastResult::Declined;
    p.digitsPos = static_cast<std::uint32_t>(d);
    p.digitsLen = static_cast<std::uint32_t>(i - d);
    p.len = static_cast<std::uint32_t>(i - p.pos);
    // the grammar's `sequenceNumber : N PLUS? NUMBER` takes an N before any word, without a
    // minus (a `+` is discarded, nct.md §1.2 rule 3)
    if (c == 'N' && !anyWord && !p.incremental && p.sign != '-') p.kind = Piece::Sequence;
    anyWord = true;
    if (!push(p)) return FastResult::Declined;
  }

  BlockBuilder b(raw, out, diags, true);
  for (std::size_t k = 0; k < count; ++k) {
    const Piece& p = pieces[k];
    std::string_view digits(s.data() + p.digitsPos, p.digitsLen);
    switch (p.kind) {
    case Piece::Skip:
      b.skip(p.pos, p.len, digits);
      break;
    case Piece::Sequence:
      b.sequence(p.pos, p.len, digits);
      break;
    case Piece::Comment:
      b.comment(p.pos, p.len);
      break;
    case Piece::Word:
      if (p.exact)
        b.literalWord(p.letter, p.pos, p.len, p.incremental, p.sign, digits, p.value);
      else
        b.literalWord(std::string_view(&p.letter, 1), p.pos, p.len, p.incremental, p.sign, digits);
      break;
    }
  }
  b.finish();
  return b.ok() ? FastResult::Parsed : FastResult::Failed;
}

} // namespace gcx::nct
