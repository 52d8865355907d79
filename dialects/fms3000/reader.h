// The FMS-3000 front end: bytes in, IR blocks out, one block at a time (streaming). A line is
// a `rem` comment, `endcont`, a macro-language line (rejected: not in the manual, §6.4) or an
// NC block for the grammar, whose words then pass the block rules (block_rules.h).
#pragma once
#include <istream>
#include <optional>

#include "dialects/fms3000/tree_builder.h"
#include "front/block_reader.h"

namespace gcx::fms3000 {

class Reader {
public:
  /// encoding: the file's; empty means the dialect's default (lexicalRules().encoding).
  Reader(std::istream& in, FileId file, diag::Engine& diags, front::ReaderLimits limits = {},
         std::optional<front::Encoding> encoding = {});

  /// The next well-formed block; blocks with errors are reported and skipped. False at the end.
  bool next(ir::Block& out);
  bool sawInput() const { return bytes_.sawAnyByte(); }
  std::size_t failedBlocks() const { return failed_; }

private:
  bool read(ir::Block& out);
  void reset(ir::Block& out) const;
  bool rejectForeignCharacters();

  front::BlockReader bytes_;
  diag::Engine& diags_;
  GrammarParser grammar_;
  front::RawBlock raw_;
  std::size_t failed_ = 0;
};

} // namespace gcx::fms3000
