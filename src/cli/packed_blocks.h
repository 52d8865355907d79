// Blocks in the few bytes that cross from the reading thread to the executing one. A block of
// one-letter literal words on one line (what CAM output is made of) is kept here as 40 bytes a
// word and 80 a block, where its ir::Block spreads over some thirty cache lines (an ir::Word
// alone is ~250 bytes). Moving a cache line between two cores of a VM costs ~10 ns: whole blocks
// crossing cost more than the second core gave (bench/README.md, Threads). Each thread builds its
// blocks in an ir::Block of its own, which stays in its cache.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ir/block.h"

namespace gcx::cli {

class UnpackedBlock;

class PackedBlocks {
public:
  /// Appends b if it has the packed form: a block (of any kind) whose words are one-letter
  /// literals with a new expression and at most kMaxText characters of text, written on the
  /// block's first line, and that has no statements, comments or program name. False, and
  /// nothing appended, if not.
  bool pack(const ir::Block& b);
  /// Block i as it was packed, written into out; out's words are reused in place.
  void unpack(std::size_t i, UnpackedBlock& out) const;
  std::size_t size() const { return blocksUsed_; }
  void clear() { blocksUsed_ = wordsUsed_ = 0; }

  static constexpr std::size_t kMaxText = 15; // a word's or sequence number's text

private:
  struct Word {
    double number;
    std::uint32_t col, length; // range.begin.col and range.length; line and file are the block's
    std::uint32_t order;
    char letter;
    bool incremental;
    std::uint8_t textLength;
    char text[kMaxText];
  };
  static_assert(sizeof(Word) <= 40, "a packed word fits the size the comment above gives");
  struct Block {
    SourceRange range;
    std::int64_t sequence;
    std::uint32_t lastLine;
    std::uint32_t firstWord;                   // in words_
    std::uint32_t sequenceCol, sequenceLength; // the sequence number's range
    std::uint8_t wordCount;
    ir::BlockKind kind;
    std::int8_t skipLevel;
    bool hasSequence;
    std::uint8_t sequenceTextLength;
    char sequenceText[kMaxText];
  };
  static_assert(sizeof(Block) <= 80, "a packed block fits the size the comment above gives");

  // Both grow and never shrink; the first blocksUsed_ / wordsUsed_ hold this batch's.
  std::vector<Block> blocks_;
  std::vector<Word> words_;
  std::size_t blocksUsed_ = 0, wordsUsed_ = 0;
};

/// The block the executing thread rebuilds packed blocks in. Only PackedBlocks::unpack writes
/// it, so what every packed block has in common (no statements, comments or program name; words
/// with a new expression and no axis index, literal) is never undone and not written again: a
/// new word slot has it from its constructor.
class UnpackedBlock {
public:
  const ir::Block& block() const { return block_; }

private:
  friend class PackedBlocks;
  ir::Block block_;
};

} // namespace gcx::cli
