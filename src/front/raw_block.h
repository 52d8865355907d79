// A block as cut out of the byte stream, before parsing.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "ir/source.h"

namespace gcx::front {

struct RawBlock {
  std::string text;    // the text as written, in UTF-8 (CR of CR LF removed)
  std::string lexText; // same length, ASCII: case folded outside comments, sign aliases -> '-'
  SourceLoc begin;     // first byte of the block (always column 1)
  std::vector<std::uint32_t> lineBreaks;  // positions of LFs inside the block (inside comments)
  std::vector<std::uint64_t> lineOffsets; // file offset of the line after each of lineBreaks
  std::size_t lineCommentAt = std::string::npos; // where a comment to the end of the line starts
  bool plain = true;   // only letters, digits, `. + - /`, blanks and comments: fast-path candidate
  bool failed = false; // an error was already reported for this block; do not parse it

  SourceLoc locAt(std::size_t pos) const {
    SourceLoc l = begin;
    l.offset += pos;
    std::size_t lineStart = 0;
    for (std::size_t k = 0; k < lineBreaks.size(); ++k) {
      if (lineBreaks[k] >= pos) break;
      ++l.line;
      lineStart = lineBreaks[k] + 1;
      l.offset = lineOffsets[k] + (pos - lineStart);
    }
    l.col = static_cast<std::uint32_t>(pos - lineStart + 1);
    return l;
  }
  SourceRange rangeAt(std::size_t pos, std::size_t len) const {
    return SourceRange{locAt(pos), static_cast<std::uint32_t>(len)};
  }
  /// to = rangeAt(pos, len), stored field by field: a whole SourceRange built in a temporary and
  /// copied makes the copy's wide loads wait for the temporary's narrow stores, for every word.
  void writeRange(SourceRange& to, std::size_t pos, std::size_t len) const {
    if (!lineBreaks.empty()) {
      to = rangeAt(pos, len);
      return;
    }
    to.begin.file = begin.file;
    to.begin.line = begin.line;
    to.begin.col = static_cast<std::uint32_t>(pos + 1);
    to.begin.offset = begin.offset + pos;
    to.length = static_cast<std::uint32_t>(len);
  }
  std::uint32_t lastLine() const {
    return begin.line + static_cast<std::uint32_t>(lineBreaks.size());
  }
};

} // namespace gcx::front
