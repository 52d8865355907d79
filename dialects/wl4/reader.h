// The WL4 front end: bytes in, IR blocks out, one block at a time (streaming). A block with an
// error is reported and skipped; a label written twice in one program is an error (§1.8).
#pragma once
#include <istream>
#include <memory>
#include <optional>
#include <set>

#include "dialect/dialect.h"
#include "dialects/wl4/tree_builder.h"
#include "front/block_reader.h"

namespace gcx::wl4 {

class Reader : public BlockSource {
public:
  Reader(std::istream& in, FileId file, diag::Engine& diags,
         std::optional<front::Encoding> encoding = {});

  bool next(ir::Block& out) override;
  bool sawInput() const override { return bytes_.sawAnyByte(); }
  std::size_t failedBlocks() const override { return failed_; }
  /// Off: every block goes through the grammar (grammar/WL4.g4) instead of the hand parser, the
  /// fast path; both give the same IR and the same first error (tests compare them).
  void setFastPath(bool on) { fastPath_ = on; }

private:
  bool duplicateLabel(const ir::Block& b);
  bool parse(ir::Block& out);

  front::BlockReader bytes_;
  diag::Engine& diags_;
  front::RawBlock raw_;
  std::set<std::int64_t> labels_; // of the program being read
  std::size_t failed_ = 0;
  bool fastPath_ = true;
  std::unique_ptr<GrammarParser> grammar_; // made on first use
};

} // namespace gcx::wl4
