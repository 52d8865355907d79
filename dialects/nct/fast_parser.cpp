#include "dialects/nct/fast_parser.h"

#include <array>
#include <cstdint>
#include <string_view>

namespace gcx::nct {

namespace {

// One piece of a block, as the scan finds it; no member initializers: the scan sets every field
// a piece of its kind uses, and a block's buffer of pieces is left uninitialised.
struct Piece {
  enum Kind : unsigned char { Skip, Sequence, Word, Comment } kind;
  char letter;
  bool incremental;
  bool exact;        // Word: at most 15 digits, value set
  char sign;         // '-', '+' or none
  std::uint32_t pos; // first byte of the piece
  std::uint32_t len;
  std::uint32_t digitsPos;
  std::uint32_t digitsLen;
  double value; // Word: the digits' value, when exact
};

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
// wraps; it is not used then.
const char* scanNumber(const char* p, double& value, bool& exact) {
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
  const char* const s = raw.lexText.c_str(); // NUL-terminated: every scan below stops at it
  // A block rarely has more than a dozen words; a fixed buffer keeps the fast path allocation-free.
  std::array<Piece, 48> pieces;
  std::size_t count = 0;
  bool anyWord = false;
  const char* p = skipBlanks(s);
  const auto at = [&](const char* q) { return static_cast<std::uint32_t>(q - s); };
  // leading comments may precede '/': the grammar hides comments, so `(c) /2 X1` is legal too
  // a comment's ')' is in the block: an LF inside a comment does not end it
  auto comment = [&] {
    Piece& c = pieces[count++];
    const char* close = p;
    while (*close != ')' && *close)
      ++close;
    c.kind = Piece::Comment;
    c.pos = at(p);
    c.len = at(close) - c.pos + 1;
    p = *close ? skipBlanks(close + 1) : nullptr;
    return p != nullptr;
  };
  while (*p == '(')
    if (count == pieces.size() || !comment()) return FastResult::Declined;
  if (*p == '/') {
    if (count == pieces.size()) return FastResult::Declined;
    Piece& k = pieces[count++];
    k.kind = Piece::Skip;
    k.pos = at(p);
    p = skipBlanks(p + 1);
    k.digitsPos = at(p);
    if (isDigit(*p) || *p == '.') {
      double unused = 0;
      bool exact = false;
      p = scanNumber(p, unused, exact);
      if (!p) return FastResult::Declined;
    }
    k.digitsLen = at(p) - k.digitsPos;
    k.len = at(p) - k.pos;
  }
  for (p = skipBlanks(p); *p; p = skipBlanks(p)) {
    if (count == pieces.size()) return FastResult::Declined;
    if (*p == '(') {
      if (!comment()) return FastResult::Declined;
      continue;
    }
    const char c = *p;
    if (!isLetter(c)) return FastResult::Declined;
    Piece& w = pieces[count++];
    w.kind = Piece::Word;
    w.letter = c;
    w.pos = at(p);
    p = skipBlanks(p + 1);
    w.incremental = *p == 'I';
    if (w.incremental) p = skipBlanks(p + 1);
    w.sign = 0;
    if (*p == '-' || *p == '+') {
      w.sign = *p;
      p = skipBlanks(p + 1);
    }
    w.digitsPos = at(p);
    if (!(isDigit(*p) || *p == '.')) return FastResult::Declined;
    p = scanNumber(p, w.value, w.exact);
    if (!p) return FastResult::Declined;
    w.digitsLen = at(p) - w.digitsPos;
    w.len = at(p) - w.pos;
    // the grammar's `sequenceNumber : N PLUS? NUMBER` takes an N before any word, without a
    // minus (a `+` is discarded, nct.md §1.2 rule 3)
    if (c == 'N' && !anyWord && !w.incremental && w.sign != '-') w.kind = Piece::Sequence;
    anyWord = true;
  }

  BlockBuilder b(raw, out, diags, true);
  for (std::size_t k = 0; k < count; ++k) {
    const Piece& piece = pieces[k];
    const std::string_view digits(s + piece.digitsPos, piece.digitsLen);
    switch (piece.kind) {
    case Piece::Word:
      // exact, with its sign (if any) right before the digits: the text as written is one view
      if (piece.exact && (!piece.sign || s[piece.digitsPos - 1] == piece.sign))
        b.literalWord(piece.letter, piece.pos, piece.len, piece.incremental, piece.sign == '-',
                      std::string_view(digits.data() - (piece.sign ? 1 : 0),
                                       digits.size() + (piece.sign ? 1 : 0)),
                      piece.value);
      else
        b.literalWord(std::string_view(&piece.letter, 1), piece.pos, piece.len, piece.incremental,
                      piece.sign, digits);
      break;
    case Piece::Skip:
      b.skip(piece.pos, piece.len, digits);
      break;
    case Piece::Sequence:
      b.sequence(piece.pos, piece.len, digits);
      break;
    case Piece::Comment:
      b.comment(piece.pos, piece.len);
      break;
    }
  }
  b.finish();
  return b.ok() ? FastResult::Parsed : FastResult::Failed;
}

} // namespace gcx::nct
