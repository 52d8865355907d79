// Cuts a byte stream into blocks, streaming: LF ends a block unless it stands inside a comment
// (nct.md §1.5). Validates the bytes (binary data, UTF-8, block length) and prepares the ASCII
// text the parsers read. Holds one block in memory at a time.
#pragma once
#include <istream>
#include <string>

#include "diag/diagnostic.h"
#include "front/raw_block.h"

namespace gcx::front {

struct ReaderLimits {
  std::size_t maxBlockBytes = 1 << 20; // a real block is < 1 KB; multi-line comments may be long
};

class BlockReader {
public:
  BlockReader(std::istream& in, FileId file, diag::Engine& diags, ReaderLimits limits = {});

  /// The next non-blank block; false at end of input or after a fatal input error.
  bool next(RawBlock& out);
  bool sawAnyByte() const { return sawAnyByte_; }

private:
  bool fill();
  bool finishBlock(RawBlock& out);
  void normalize(RawBlock& b);

  std::istream& in_;
  FileId file_;
  diag::Engine& diags_;
  ReaderLimits limits_;

  std::string buf_;
  std::size_t pos_ = 0;
  bool eof_ = false;
  bool fatal_ = false;
  bool sawAnyByte_ = false;

  // position of the next byte to consume
  std::uint64_t offset_ = 0;
  std::uint32_t line_ = 1;
  std::uint64_t lineStart_ = 0;

  // block under construction
  std::string cur_;
  SourceLoc curBegin_;
  std::vector<std::uint32_t> curBreaks_;
  bool inComment_ = false;
  std::size_t commentStart_ = 0;
  SourceLoc commentLoc_;
  bool overflow_ = false;
};

} // namespace gcx::front
