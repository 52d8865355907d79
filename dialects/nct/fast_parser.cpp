#include "dialects/nct/fast_parser.h"

#include <array>

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
};

Piece newPiece(Piece::Kind kind, std::size_t pos) {
  Piece p;
  p.kind = kind;
  p.letter = p.sign = 0;
  p.incremental = false;
  p.pos = static_cast<std::uint32_t>(pos);
  p.len = p.digitsPos = p.digitsLen = 0;
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

// Scans a NUMBER token (grammar/NCT.g4): DIGIT+ ('.' DIGIT*)? | '.' DIGIT+
bool scanNumber(const std::string& s, std::size_t& i) {
  const std::size_t start = i;
  while (i < s.size() && isDigit(s[i]))
    ++i;
  if (i < s.size() && s[i] == '.') {
    ++i;
    const std::size_t frac = i;
    while (i < s.size() && isDigit(s[i]))
      ++i;
    if (frac == start + 1 && i == frac) return false; // a lone '.'
  }
  return i > start;
}

} // namespace

FastResult parseFast(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags) {
  if (!raw.plain) return FastResult::Declined;
  const std::string& s = raw.lexText;
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
      if (!scanNumber(s, i)) return FastResult::Declined;
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
    if (i >= n || !(isDigit(s[i]) || s[i] == '.') || !scanNumber(s, i)) return FastResult::Declined;
    p.digitsPos = static_cast<std::uint32_t>(d);
    p.digitsLen = static_cast<std::uint32_t>(i - d);
    p.len = static_cast<std::uint32_t>(i - p.pos);
    // the grammar's `sequenceNumber : N PLUS? NUMBER` takes an N before any word, without a
    // minus (a `+` is discarded, nct.md §1.2 rule 3)
    if (c == 'N' && !anyWord && !p.incremental && p.sign != '-') p.kind = Piece::Sequence;
    anyWord = true;
    if (!push(p)) return FastResult::Declined;
  }

  BlockBuilder b(raw, out, diags);
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
      b.literalWord(std::string_view(&p.letter, 1), p.pos, p.len, p.incremental, p.sign, digits);
      break;
    }
  }
  return b.ok() ? FastResult::Parsed : FastResult::Failed;
}

} // namespace gcx::nct
