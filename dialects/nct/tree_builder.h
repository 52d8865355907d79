// The ANTLR path: parses one block with the NCT grammar and turns the tree into IR. One lexer and
// one parser are reused for every block (a whole-file tree would cost gigabytes, DESIGN.md).
#pragma once
#include <memory>

#include "dialects/nct/block_builder.h"

namespace gcx::nct {

class GrammarParser {
public:
  GrammarParser();
  ~GrammarParser();
  GrammarParser(const GrammarParser&) = delete;
  GrammarParser& operator=(const GrammarParser&) = delete;

  /// Parses raw into out; false if the block has errors (they are reported).
  bool parse(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace gcx::nct
