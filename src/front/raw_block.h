// A block as cut out of the byte stream, before parsing.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "ir/source.h"

namespace gcx::front {

struct RawBlock {
  std::string text;    // the bytes as written (CR of CR LF removed)
  std::string lexText; // same length, ASCII: upper case outside comments, sign aliases -> '-'
  SourceLoc begin;     // first byte of the block (always column 1)
  std::vector<std::uint32_t> lineBreaks; // positions of LFs inside the block (inside comments)
  bool plain = true;   // only letters, digits, `. + - /`, blanks and comments: fast-path candidate
  bool failed = false; // an error was already reported for this block; do not parse it

  SourceLoc locAt(std::size_t pos) const {
    SourceLoc l = begin;
    l.offset += pos;
    std::size_t lineStart = 0;
    for (std::uint32_t br : lineBreaks) {
      if (br >= pos) break;
      ++l.line;
      lineStart = br + 1;
    }
    l.col = static_cast<std::uint32_t>(pos - lineStart + 1);
    return l;
  }
  SourceRange rangeAt(std::size_t pos, std::size_t len) const {
    return SourceRange{locAt(pos), static_cast<std::uint32_t>(len)};
  }
  std::uint32_t lastLine() const {
    return begin.line + static_cast<std::uint32_t>(lineBreaks.size());
  }
};

} // namespace gcx::front
