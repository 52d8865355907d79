// The ANTLR path of the FMS-3000 front end: one NC block parsed with grammar/FMS3000.g4 and
// turned into IR (words in source order, their texts as written). One lexer and one parser are
// reused for every block.
#pragma once
#include <memory>

#include "diag/diagnostic.h"
#include "front/raw_block.h"
#include "ir/block.h"

namespace gcx::fms3000 {

class GrammarParser {
public:
  GrammarParser();
  ~GrammarParser();
  GrammarParser(const GrammarParser&) = delete;
  GrammarParser& operator=(const GrammarParser&) = delete;

  /// Parses raw into out (whose kind, range and vectors the caller has reset); false if the
  /// block has errors (the first one is reported, located).
  bool parse(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace gcx::fms3000
