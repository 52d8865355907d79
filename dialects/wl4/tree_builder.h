// The grammar path of the WL4 front end: one block parsed with grammar/WL4.g4 and its tree turned
// into the IR the hand parser (block_parser.h, the fast path) builds, with the same first error at
// the same place. One lexer and one parser are reused for every block.
#pragma once
#include <memory>

#include "diag/diagnostic.h"
#include "front/raw_block.h"
#include "ir/block.h"

namespace gcx::wl4 {

class GrammarParser {
public:
  GrammarParser();
  ~GrammarParser();
  GrammarParser(const GrammarParser&) = delete;
  GrammarParser& operator=(const GrammarParser&) = delete;

  /// Parses raw into out; false after reporting a located error (the block is then dropped).
  bool parse(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace gcx::wl4
