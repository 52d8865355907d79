#include "front/block_reader.h"

#include <algorithm>
#include <fmt/format.h>

#include "diag/codes.h"
#include "front/plain_run.h"
#include "front/utf8.h"

namespace gcx::front {

namespace {
// A loop, not find_first_not_of: that calls memchr for every byte it looks at, and a block's
// first byte is nearly always the one that answers.
bool isBlank(const std::string& text) {
  for (const char c : text)
    if (c != ' ' && c != '\t' && c != '\r') return false;
  return true;
}

bool isPlainChar(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == ' ' || c == '.' || c == '+' ||
         c == '-' || c == '/';
}

bool isLetter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

std::string aliasWarning(const SignAlias& a) {
  const std::string what = a.codePoint < 0x80
                               ? fmt::format("'{}'", static_cast<char>(a.codePoint))
                               : fmt::format("U+{:04X}", static_cast<unsigned>(a.codePoint));
  return fmt::format("{} read as a {} sign '{}'{}", what, a.sign == '-' ? "minus" : "plus", a.sign,
                     a.why);
}
} // namespace

BlockReader::BlockReader(std::istream& in, FileId file, diag::Engine& diags,
                         const LexicalRules& rules, Encoding encoding, ReaderLimits limits)
    : input_(in, encoding), encoding_(encoding), file_(file), diags_(diags), rules_(rules),
      limits_(limits) {
  curBegin_ = SourceLoc{file_, 1, 1, 0};
  classes_.fill(Plain);
  for (char c : rules_.lineCommentMarkers)
    classes_[static_cast<unsigned char>(c)] = LineMarker;
  if (rules_.bracketComment) {
    classes_[static_cast<unsigned char>(rules_.bracketComment->open)] = Open;
    classes_[static_cast<unsigned char>(rules_.bracketComment->close)] = Close;
  }
  classes_['\n'] = LineFeed;
  classes_['\0'] = Nul;
  asciiAlias_.fill(-1);
  for (std::size_t k = 0; k < rules_.signAliases.size(); ++k)
    if (rules_.signAliases[k].codePoint < 0x80)
      asciiAlias_[rules_.signAliases[k].codePoint] = static_cast<signed char>(k);
  classifyForLexText();
}

// What each byte asks of normalize(); later assignments override earlier ones.
void BlockReader::classifyForLexText() {
  for (unsigned c = 0; c < 256; ++c) {
    const char ch = static_cast<char>(c);
    lexClasses_[c] = c >= 0x80                ? NonAscii
                     : c < 0x20 || c == 0x7F  ? Control
                     : isPlainChar(ch)        ? PlainText
                     : ch >= 'a' && ch <= 'z' ? Lower
                                              : OtherText;
  }
  lexClasses_['\t'] = lexClasses_['\r'] = Blank;
  for (unsigned c = 0; c < 128; ++c)
    if (asciiAlias_[c] >= 0) lexClasses_[c] = Alias;
  for (char c : rules_.lineCommentMarkers)
    lexClasses_[static_cast<unsigned char>(c)] = LineCommentMarker;
  if (rules_.dotStartsMessage) lexClasses_['.'] = MessageDot;
  if (rules_.bracketComment) {
    lexClasses_[static_cast<unsigned char>(rules_.bracketComment->open)] = CommentOpen;
    lexClasses_[static_cast<unsigned char>(rules_.bracketComment->close)] = CommentClose;
  }
  for (unsigned c = 0; c < 256; ++c)
    scanClasses_[c] = static_cast<unsigned char>(classes_[c] | (lexClasses_[c] == PlainText ? 0
                                                                : c == '\r' ? kCarriageReturn
                                                                            : kLexWork));
  runPlain_ = true;
  for (unsigned c = 0; c < 256; ++c)
    if (isRunPlain(static_cast<unsigned char>(c)) && scanClasses_[c] != 0) runPlain_ = false;
}

bool BlockReader::fill() {
  pos_ = 0;
  rawLine_ = 0;
  switch (input_.read(buf_)) {
  case DecodingInput::Status::Data:
    return true;
  case DecodingInput::Status::End:
    buf_.clear();
    return false;
  case DecodingInput::Status::Invalid:
  case DecodingInput::Status::Unavailable:
    break;
  }
  buf_.clear();
  const SourceLoc here{file_, line_, static_cast<std::uint32_t>(offset_ - lineStart_ + 1),
                       offset_ + offsetShift_};
  if (input_.converts())
    diags_.error(diag::code::InvalidEncodedByte, SourceRange{here, 1},
                 fmt::format("byte 0x{:02X} is not valid {} text; choose the file's encoding "
                             "with --encoding",
                             input_.invalidByte(), encodingName(encoding_)));
  else
    diags_.error(diag::code::InvalidEncodedByte, SourceRange{here, 1},
                 fmt::format("this system's iconv cannot read {} (glibc's gconv modules are "
                             "missing)",
                             encodingName(encoding_)));
  fatal_ = true;
  return false;
}

void BlockReader::newLine() {
  ++line_;
  lineStart_ = offset_;
  if (input_.converts()) offsetShift_ = input_.rawLineStarts()[rawLine_++] - offset_;
}

void BlockReader::startAt(std::uint64_t offset, std::uint32_t line) {
  offset_ = lineStart_ = offset;
  line_ = line;
  curBegin_ = SourceLoc{file_, line_, 1, offset_};
}

void BlockReader::stopAt(std::uint64_t offset) {
  stopAt_ = offset == 0 ? UINT64_MAX : offset;
  stopped_ = false;
}

std::optional<SourceLoc> BlockReader::stoppedAt() const {
  if (!stopped_ || fatal_) return std::nullopt;
  return curBegin_;
}

void BlockReader::shiftLines(std::int64_t delta) {
  line_ = static_cast<std::uint32_t>(line_ + delta);
  curBegin_.line = static_cast<std::uint32_t>(curBegin_.line + delta);
}

bool BlockReader::next(RawBlock& out) {
  for (;;) {
    if (fatal_ || stopped_) return false;
    if (pos_ >= buf_.size() && !fill()) {
      if (fatal_) return false;
      if (inComment_) {
        diags_.error(diag::code::UnterminatedComment, SourceRange{commentLoc_, 1},
                     fmt::format("comment is not closed: '{}' without '{}' before the end of the "
                                 "file",
                                 rules_.bracketComment->open, rules_.bracketComment->close));
        inComment_ = false;
        fatal_ = true;
        return false;
      }
      if (cur_.empty() && !overflow_) return false;
      if (finishBlock(out)) return true;
      return false;
    }
    const char* data = buf_.data();
    const std::size_t size = buf_.size();
    while (pos_ < size) {
      // the bulk of a program: a run of bytes without meaning to the reader, copied at once;
      // their classes ORed eight at a time while none of the eight means something
      const auto* bytes = reinterpret_cast<const unsigned char*>(data);
      const unsigned char* scan = scanClasses_.data();
      std::size_t run = pos_;
      unsigned char lex = 0;
      // sixteen plain bytes at a time where the dialect lets all of them be (plain_run.h), and
      // one byte that is not; then eight, then one at a time
      bool atCutter = false;
      while (runPlain_) {
        run = plainRunEnd(bytes, run, size);
        if (run + 16 > size) break;
        const unsigned char k = scan[bytes[run]];
        atCutter = k & kCutter;
        if (atCutter) break;
        lex |= k;
        ++run;
      }
      for (; !atCutter && run + 8 <= size; run += 8) {
        const unsigned char eight = scan[bytes[run]] | scan[bytes[run + 1]] | scan[bytes[run + 2]] |
                                    scan[bytes[run + 3]] | scan[bytes[run + 4]] |
                                    scan[bytes[run + 5]] | scan[bytes[run + 6]] |
                                    scan[bytes[run + 7]];
        if (eight & kCutter) break;
        lex |= eight;
      }
      for (; !atCutter && run < size && !(scan[bytes[run]] & kCutter); ++run)
        lex |= scan[bytes[run]];
      curLex_ |= lex;
      if (run > pos_) {
        append(data + pos_, run - pos_);
        offset_ += run - pos_;
        pos_ = run;
        if (pos_ == size) break;
      }
      const char c = data[pos_++];
      const ByteClass k = classes_[static_cast<unsigned char>(c)];
      ++offset_;
      {
        const SourceLoc here{file_, line_, static_cast<std::uint32_t>(offset_ - lineStart_),
                             offset_ - 1 + offsetShift_};
        if (k == Nul) {
          diags_.error(diag::code::BinaryFile, SourceRange{here, 1},
                       "binary data (NUL byte): this is not a program text");
          fatal_ = true;
          return false;
        }
        const bool endsBlock = k == LineFeed && (!inComment_ || !rules_.bracketComment->spansLines);
        if (k == LineFeed) newLine();
        if (endsBlock) {
          inComment_ = inLineComment_ = false;
          const bool got = finishBlock(out);
          curBegin_ = SourceLoc{file_, line_, 1, offset_ + offsetShift_};
          stopped_ = offset_ >= stopAt_; // the next block begins at or after the cut
          if (got) return true;
          if (stopped_) return false;
          continue;
        }
        if (k == LineFeed) {
          curBreaks_.push_back(static_cast<std::uint32_t>(cur_.size()));
          curLineOffsets_.push_back(offset_ + offsetShift_);
        } else if (inComment_) {
          if (k == Close) inComment_ = false;
        } else if (k == Open && !inLineComment_) {
          inComment_ = true;
          commentLoc_ = here;
        } else if (k == LineMarker) {
          inLineComment_ = true;
        }
      }
      append(&c, 1);
      curLex_ |= kLexWork; // a byte of meaning to the cutter means something to normalize() too
    }
  }
}

void BlockReader::append(const char* bytes, std::size_t n) {
  const std::size_t room = limits_.maxBlockBytes - std::min(cur_.size(), limits_.maxBlockBytes);
  cur_.append(bytes, std::min(n, room));
  if (n > room) overflow_ = true;
}

bool BlockReader::finishBlock(RawBlock& out) {
  auto reset = [&] {
    cur_.clear();
    curBreaks_.clear();
    curLineOffsets_.clear();
    overflow_ = false;
    curLex_ = 0;
  };
  if (overflow_) {
    diags_.error(
        diag::code::BlockTooLong, SourceRange{curBegin_, 1},
        fmt::format("block is longer than {} bytes; it was skipped", limits_.maxBlockBytes));
    reset();
    return false;
  }
  if (!cur_.empty() && cur_.back() == '\r') cur_.pop_back();
  // a CR other than the final one of CR LF is work (a lone CR)
  const bool lexWork =
      (curLex_ & kLexWork) || ((curLex_ & kCarriageReturn) && cur_.find('\r') != std::string::npos);
  if (isBlank(cur_)) {
    reset();
    return false;
  }
  out.text.swap(cur_);
  out.begin = curBegin_;
  out.lineBreaks.swap(curBreaks_);
  out.lineOffsets.swap(curLineOffsets_);
  out.plain = true;
  out.failed = false;
  out.lineCommentAt = std::string::npos;
  reset();
  // the checks below are calls only where they have work: the usual block has none
  if ((rules_.maxBlockChars || rules_.warnBlockChars) && !checkDialectLength(out)) return true;
  if (lexWork || !rules_.commentLineKeywords.empty())
    normalize(out, lexWork);
  else
    out.lexText.assign(out.text); // every byte PlainText: nothing to change
  // a line of only ignored characters (a stray ')', a byte order mark) is a blank line too;
  // without lex work lexText is text, which is not blank
  return out.failed || !lexWork || !isBlank(out.lexText);
}

// The dialect's own limit on a block's length, in characters (FMS-3000 254 with CR LF, WL4 80).
bool BlockReader::checkDialectLength(RawBlock& b) {
  std::size_t chars = 0;
  for (char c : b.text)
    chars += (static_cast<unsigned char>(c) & 0xC0) != 0x80; // UTF-8 continuation bytes
  if (rules_.maxBlockChars && chars > rules_.maxBlockChars) {
    diags_.error(diag::code::BlockTooLong, b.rangeAt(0, 1),
                 fmt::format("block of {} characters; the dialect allows at most {}", chars,
                             rules_.maxBlockChars));
    b.lexText.assign(b.text.size(), ' ');
    b.failed = true;
    return false;
  }
  if (rules_.warnBlockChars && chars > rules_.warnBlockChars)
    diags_.warning(diag::code::LongBlock, b.rangeAt(0, 1),
                   fmt::format("block of {} characters; the dialect's manual allows {}", chars,
                               rules_.warnBlockChars));
  return true;
}

bool BlockReader::keywordAt(const std::string& text, std::size_t i,
                            const std::vector<std::string>& words) const {
  if (i > 0 && isLetter(text[i - 1])) return false;
  for (const std::string& w : words)
    if (text.compare(i, w.size(), w) == 0 &&
        (i + w.size() == text.size() || !isLetter(text[i + w.size()])))
      return true;
  return false;
}

// lexWork false: every byte is PlainText, which no state of the loop below changes or reports
// (nor does it make the block less plain), so only the comment keyword is looked for.
void BlockReader::normalize(RawBlock& b, bool lexWork) {
  b.lexText.assign(b.text);
  std::string& t = b.lexText;
  bool comment = false;     // inside a bracket comment
  bool lineComment = false; // to the end of the block
  bool message = false;     // a WL4 message: any character to the end of the block (§1.6)
  bool loneCr = false;      // a CR inside a block: the final one of CR LF is already gone
  if (!rules_.commentLineKeywords.empty()) {
    const std::size_t first = t.find_first_not_of(" \t");
    if (first != std::string::npos && keywordAt(t, first, rules_.commentLineKeywords)) {
      lineComment = true;
      b.lineCommentAt = first;
    }
  }
  if (!lexWork) return;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const auto uc = static_cast<unsigned char>(t[i]);
    const LexClass k = lexClasses_[uc];
    if (k == PlainText) continue; // the bulk of a program: nothing to do in any state
    if (k == NonAscii) {
      normalizeNonAscii(b, i, comment || lineComment || message);
      if (fatal_) return;
      continue;
    }
    if (lineComment || message) continue;
    if (comment) {
      if (k == CommentClose) comment = false;
      continue;
    }
    switch (k) {
    case Lower:
      if (!rules_.lowerCaseKeywords.empty() && keywordAt(t, i, rules_.lowerCaseKeywords)) {
        while (i + 1 < t.size() && t[i + 1] >= 'a' && t[i + 1] <= 'z')
          ++i; // kept as written
        b.plain = false;
        continue;
      }
      if (rules_.letterCase == LetterCase::Fold) {
        t[i] = static_cast<char>(uc - 'a' + 'A');
      } else if (rules_.letterCase == LetterCase::ErrorOutsideComments) {
        diags_.error(diag::code::SyntaxError, b.rangeAt(i, 1),
                     fmt::format("lower-case letter '{}' outside a comment", t[i]));
        b.failed = true;
      }
      break;
    case CommentOpen:
      comment = true; // comments are allowed on the fast path
      continue;
    case CommentClose:
      diags_.warning(diag::code::StrayParen, b.rangeAt(i, 1),
                     fmt::format("'{}' without '{}' ignored", rules_.bracketComment->close,
                                 rules_.bracketComment->open));
      t[i] = ' ';
      break;
    case LineCommentMarker:
      lineComment = true;
      b.lineCommentAt = i;
      b.plain = false;
      continue;
    case Alias: {
      const SignAlias& a = rules_.signAliases[static_cast<std::size_t>(asciiAlias_[uc])];
      diags_.warning(diag::code::SignAlias, b.rangeAt(i, 1), aliasWarning(a));
      t[i] = a.sign;
      break;
    }
    case Blank:
      if (uc == '\r' && !loneCr && rules_.warnLoneCarriageReturn) {
        loneCr = true;
        diags_.warning(diag::code::LoneCarriageReturn, b.rangeAt(i, 1),
                       "carriage return without a line feed: blocks end at LF; a file with "
                       "CR-only line ends (old Macintosh) must be converted to LF or CR LF");
      }
      t[i] = ' ';
      break;
    case Control:
      diags_.error(diag::code::SyntaxError, b.rangeAt(i, 1),
                   fmt::format("unexpected control character 0x{:02X}", uc));
      b.failed = true;
      t[i] = ' ';
      break;
    case MessageDot: {
      // a '.' beside a digit belongs to a number; elsewhere the parser reads a message from it
      // where a word would start, and its text may be Cyrillic (wl4.md §1.6)
      const auto digit = [&](std::size_t j) { return j < t.size() && t[j] >= '0' && t[j] <= '9'; };
      if (!(i > 0 && digit(i - 1)) && !digit(i + 1)) {
        message = true;
        b.plain = false;
      }
      break;
    }
    case OtherText:
    case PlainText:
    case NonAscii:
      break;
    }
    if (!isPlainChar(t[i])) b.plain = false;
  }
}

// A character beyond ASCII at t[i] (UTF-8, the internal encoding): allowed in comments, a sign
// alias or a byte order mark elsewhere, an error otherwise. Leaves i on its last byte.
void BlockReader::normalizeNonAscii(RawBlock& b, std::size_t& i, bool comment) {
  std::string& t = b.lexText;
  const std::string& src = b.text;
  char32_t cp = 0;
  const std::size_t len = decodeUtf8(src.data() + i, src.size() - i, cp);
  if (len == 0) {
    diags_.error(diag::code::InvalidUtf8, b.rangeAt(i, 1),
                 fmt::format("invalid UTF-8 byte 0x{:02X}; programs must be ASCII or UTF-8 text",
                             static_cast<unsigned char>(t[i])));
    b.failed = true;
    fatal_ = true;
    return;
  }
  const SignAlias* alias = nullptr;
  for (const SignAlias& a : rules_.signAliases)
    if (a.codePoint == cp) alias = &a;
  if (comment) {
    for (std::size_t k = 0; k < len; ++k)
      t[i + k] = 'x';
  } else if (alias) {
    diags_.warning(diag::code::SignAlias, b.rangeAt(i, 1), aliasWarning(*alias));
    t[i] = alias->sign;
    for (std::size_t k = 1; k < len; ++k)
      t[i + k] = ' ';
  } else if (cp == 0xFEFF && b.begin.offset + i == 0) {
    for (std::size_t k = 0; k < len; ++k)
      t[i + k] = ' '; // byte order mark
  } else {
    diags_.error(
        diag::code::SyntaxError, b.rangeAt(i, 1),
        fmt::format("unexpected character U+{:04X} outside a comment", static_cast<unsigned>(cp)));
    b.failed = true;
    for (std::size_t k = 0; k < len; ++k)
      t[i + k] = ' ';
  }
  i += len - 1;
}

} // namespace gcx::front
