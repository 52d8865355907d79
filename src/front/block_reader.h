// Cuts a byte stream into blocks, streaming, by a dialect's lexical rules (front/lexical_rules.h):
// LF ends a block unless it stands inside a comment that may span lines (nct.md §1.5). Decodes
// the file's encoding to UTF-8, validates the text (binary data, encoding, block length) and
// prepares the ASCII text the parsers read. Holds one block in memory at a time.
#pragma once
#include <array>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>

#include "diag/diagnostic.h"
#include "front/encoding.h"
#include "front/lexical_rules.h"
#include "front/raw_block.h"

namespace gcx::front {

struct ReaderLimits {
  std::size_t maxBlockBytes = 1 << 20; // a real block is < 1 KB; multi-line comments may be long
};

class BlockReader {
public:
  BlockReader(std::istream& in, FileId file, diag::Engine& diags, const LexicalRules& rules,
              Encoding encoding, ReaderLimits limits = {});

  /// The next non-blank block; false at end of input or after a fatal input error.
  bool next(RawBlock& out);
  bool sawAnyByte() const { return input_.sawAnyByte(); }

  /// Reading a part of the file (BlockSource::startAt): the stream stands at byte `offset`, the
  /// start of line `line`, before any block. Not for converted text (converts()).
  void startAt(std::uint64_t offset, std::uint32_t line);
  /// next() returns false at the first block boundary at or after `offset` (0: none).
  void stopAt(std::uint64_t offset);
  /// After next() returned false: the boundary it stopped at, or nothing at the end or an error.
  std::optional<SourceLoc> stoppedAt() const;
  /// After a stop: the lines are numbered delta further from here on (BlockSource::shiftLines).
  void shiftLines(std::int64_t delta);
  bool converts() const { return input_.converts(); }

private:
  // what a byte means to the block cutter
  enum ByteClass : unsigned char { Plain, Nul, LineFeed, Open, Close, LineMarker };

  // what a byte asks of normalize(), outside comments
  enum LexClass : unsigned char {
    PlainText, // kept, and fit for the fast path: A-Z 0-9 space . + - /
    OtherText, // kept: the parser decides (# [ ] = ...)
    Lower,
    CommentOpen,
    CommentClose,
    LineCommentMarker,
    Alias,
    Blank, // tab, CR: read as a space
    Control,
    NonAscii,
    MessageDot // WL4: a '.' outside a number starts a message to the end of the line
  };

  void classifyForLexText();
  bool fill();
  void newLine();
  bool finishBlock(RawBlock& out);
  /// Appends to the block being read, up to the block length limit (then marks the overflow).
  void append(const char* bytes, std::size_t n);
  /// The dialect's limits on a block's length (LexicalRules::maxBlockChars, warnBlockChars), where
  /// it has any: false if the block is too long (reported, marked failed).
  bool checkDialectLength(RawBlock& b);
  void normalize(RawBlock& b, bool lexWork);
  void normalizeNonAscii(RawBlock& b, std::size_t& i, bool comment);
  bool keywordAt(const std::string& text, std::size_t i,
                 const std::vector<std::string>& words) const;

  DecodingInput input_;
  Encoding encoding_;
  FileId file_;
  diag::Engine& diags_;
  const LexicalRules& rules_;
  ReaderLimits limits_;
  std::array<ByteClass, 256> classes_{};
  std::array<signed char, 128> asciiAlias_{}; // index into rules_.signAliases, or -1
  std::array<LexClass, 256> lexClasses_{};
  // classes_ with kLexWork set where the byte is not PlainText (kCarriageReturn for a CR): the
  // cutting loop ORs them, so a block without any skips normalize()'s pass over its bytes
  static constexpr unsigned char kLexWork = 0x80;
  static constexpr unsigned char kCarriageReturn = 0x40; // a CR at the block's end is no work
  static constexpr unsigned char kCutter = 0x3F;         // the ByteClass bits
  std::array<unsigned char, 256> scanClasses_{};
  bool runPlain_ = false; // every byte plainRunEnd skips is one of scanClasses_ 0

  std::string buf_;
  std::size_t pos_ = 0;
  bool fatal_ = false;
  std::uint64_t stopAt_ = UINT64_MAX; // stopAt()
  bool stopped_ = false;

  // position of the next byte to consume, in the decoded text
  std::uint64_t offset_ = 0;
  std::uint32_t line_ = 1;
  std::uint64_t lineStart_ = 0;
  // file offset minus text offset at the current line's start (0 unless the text is converted);
  // SourceLoc::offset is a file offset, so a diagnostic can show the line as written
  std::uint64_t offsetShift_ = 0;
  std::size_t rawLine_ = 0; // next entry of input_.rawLineStarts()

  // block under construction
  std::string cur_;
  SourceLoc curBegin_;
  std::vector<std::uint32_t> curBreaks_;
  std::vector<std::uint64_t> curLineOffsets_;
  bool inComment_ = false;     // between bracket comment's open and close
  bool inLineComment_ = false; // after a line-comment marker
  SourceLoc commentLoc_;
  bool overflow_ = false;
  unsigned char curLex_ = 0; // scanClasses_ of cur_'s bytes ORed: what normalize() may change
};

} // namespace gcx::front
