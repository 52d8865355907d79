#include "front/block_reader.h"

#include <fmt/format.h>

#include "diag/codes.h"
#include "front/utf8.h"

namespace gcx::front {

namespace {
bool isBlank(const std::string& text) {
  return text.find_first_not_of(" \t\r") == std::string::npos;
}

constexpr std::size_t kChunk = 1 << 16;

bool isPlainChar(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == ' ' || c == '.' || c == '+' ||
         c == '-' || c == '/';
}
} // namespace

BlockReader::BlockReader(std::istream& in, FileId file, diag::Engine& diags, ReaderLimits limits)
    : in_(in), file_(file), diags_(diags), limits_(limits) {
  curBegin_ = SourceLoc{file_, 1, 1, 0};
}

bool BlockReader::fill() {
  if (eof_) return false;
  buf_.resize(kChunk);
  in_.read(buf_.data(), static_cast<std::streamsize>(kChunk));
  buf_.resize(static_cast<std::size_t>(in_.gcount()));
  pos_ = 0;
  if (buf_.empty())
    eof_ = true;
  else
    sawAnyByte_ = true;
  return !buf_.empty();
}

bool BlockReader::next(RawBlock& out) {
  for (;;) {
    if (fatal_) return false;
    if (pos_ >= buf_.size() && !fill()) {
      if (inComment_) {
        diags_.error(diag::code::UnterminatedComment, SourceRange{commentLoc_, 1},
                     "comment is not closed: '(' without ')' before the end of the file");
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
      const char c = data[pos_++];
      const SourceLoc here{file_, line_, static_cast<std::uint32_t>(offset_ - lineStart_ + 1),
                           offset_};
      ++offset_;
      if (c == '\0') {
        diags_.error(diag::code::BinaryFile, SourceRange{here, 1},
                     "binary data (NUL byte): this is not a program text");
        fatal_ = true;
        return false;
      }
      if (c == '\n') {
        ++line_;
        lineStart_ = offset_;
        if (!inComment_) {
          const bool got = finishBlock(out);
          curBegin_ = SourceLoc{file_, line_, 1, offset_};
          if (got) return true;
          continue;
        }
        curBreaks_.push_back(static_cast<std::uint32_t>(cur_.size()));
      } else if (inComment_) {
        if (c == ')') inComment_ = false;
      } else if (c == '(') {
        inComment_ = true;
        commentStart_ = cur_.size();
        commentLoc_ = here;
      }
      if (cur_.size() < limits_.maxBlockBytes)
        cur_.push_back(c);
      else
        overflow_ = true;
    }
  }
}

bool BlockReader::finishBlock(RawBlock& out) {
  auto reset = [&] {
    cur_.clear();
    curBreaks_.clear();
    overflow_ = false;
  };
  if (overflow_) {
    diags_.error(
        diag::code::BlockTooLong, SourceRange{curBegin_, 1},
        fmt::format("block is longer than {} bytes; it was skipped", limits_.maxBlockBytes));
    reset();
    return false;
  }
  if (!cur_.empty() && cur_.back() == '\r') cur_.pop_back();
  if (isBlank(cur_)) {
    reset();
    return false;
  }
  out.text.swap(cur_);
  out.begin = curBegin_;
  out.lineBreaks.swap(curBreaks_);
  out.plain = true;
  out.failed = false;
  reset();
  normalize(out);
  // a line of only ignored characters (a stray ')', a byte order mark) is a blank line too
  return out.failed || !isBlank(out.lexText);
}

void BlockReader::normalize(RawBlock& b) {
  b.lexText.assign(b.text);
  std::string& t = b.lexText;
  const std::string& src = b.text;
  bool comment = false;
  bool loneCr = false; // a CR inside a block: the final one of CR LF is already gone
  for (std::size_t i = 0; i < t.size(); ++i) {
    const char c = t[i];
    const auto uc = static_cast<unsigned char>(c);
    if (uc >= 0x80) {
      char32_t cp = 0;
      std::size_t len = decodeUtf8(src.data() + i, src.size() - i, cp);
      if (len == 0) {
        diags_.error(
            diag::code::InvalidUtf8, b.rangeAt(i, 1),
            fmt::format("invalid UTF-8 byte 0x{:02X}; programs must be ASCII or UTF-8 text", uc));
        b.failed = true;
        fatal_ = true;
        return;
      }
      if (comment) {
        for (std::size_t k = 0; k < len; ++k)
          t[i + k] = 'x';
      } else if (cp == 0x2013 || cp == 0x2212) {
        diags_.warning(diag::code::SignAlias, b.rangeAt(i, 1),
                       fmt::format("U+{:04X} read as a minus sign '-'", static_cast<unsigned>(cp)));
        t[i] = '-';
        for (std::size_t k = 1; k < len; ++k)
          t[i + k] = ' ';
      } else if (cp == 0xFEFF && b.begin.offset + i == 0) {
        for (std::size_t k = 0; k < len; ++k)
          t[i + k] = ' '; // byte order mark
      } else {
        diags_.error(diag::code::SyntaxError, b.rangeAt(i, 1),
                     fmt::format("unexpected character U+{:04X} outside a comment",
                                 static_cast<unsigned>(cp)));
        b.failed = true;
        for (std::size_t k = 0; k < len; ++k)
          t[i + k] = ' ';
      }
      i += len - 1;
      continue;
    }
    if (comment) {
      if (c == ')') comment = false;
      continue;
    }
    if (c >= 'a' && c <= 'z') {
      t[i] = static_cast<char>(c - 'a' + 'A');
    } else if (c == '(') {
      comment = true; // comments are allowed on the fast path
      continue;
    } else if (c == ')') {
      diags_.warning(diag::code::StrayParen, b.rangeAt(i, 1), "')' without '(' ignored");
      t[i] = ' ';
    } else if (c == '!') {
      diags_.warning(diag::code::SignAlias, b.rangeAt(i, 1),
                     "'!' read as a minus sign '-' (a symbol-font artefact, nct.md §0.1)");
      t[i] = '-';
    } else if (c == '\t' || c == '\r') {
      if (c == '\r' && !loneCr) {
        loneCr = true;
        diags_.warning(diag::code::LoneCarriageReturn, b.rangeAt(i, 1),
                       "carriage return without a line feed: blocks end at LF; a file with "
                       "CR-only line ends (old Macintosh) must be converted to LF or CR LF");
      }
      t[i] = ' ';
    } else if (uc < 0x20 || uc == 0x7F) {
      diags_.error(diag::code::SyntaxError, b.rangeAt(i, 1),
                   fmt::format("unexpected control character 0x{:02X}", uc));
      b.failed = true;
      t[i] = ' ';
    }
    if (!isPlainChar(t[i])) b.plain = false;
  }
}

} // namespace gcx::front
