// A BlockWords for one block's execution whose lists keep their storage from one block to the
// next, so that sorting a block's words allocates nothing. Blocks run inside a block (a turning
// cycle's contour, a level cycle's parts) take another one: each thread keeps a stack of them.
#pragma once
#include <cstddef>

#include "machine/block_words.h"

namespace gcx::machine {

class ReusedBlockWords {
public:
  ReusedBlockWords();
  ~ReusedBlockWords();
  ReusedBlockWords(const ReusedBlockWords&) = delete;
  ReusedBlockWords& operator=(const ReusedBlockWords&) = delete;

  BlockWords& words() { return words_; }

private:
  BlockWords& words_;
};

} // namespace gcx::machine
