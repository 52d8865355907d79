// The WL4 front end: bytes in, IR blocks out, one block at a time (streaming). A block with an
// error is reported and skipped; a label written twice in one program is an error (§1.8).
#pragma once
#include <istream>
#include <optional>
#include <set>

#include "dialect/dialect.h"
#include "front/block_reader.h"

namespace gcx::wl4 {

class Reader : public BlockSource {
public:
  Reader(std::istream& in, FileId file, diag::Engine& diags,
         std::optional<front::Encoding> encoding = {});

  bool next(ir::Block& out) override;
  bool sawInput() const override { return bytes_.sawAnyByte(); }
  std::size_t failedBlocks() const override { return failed_; }

private:
  bool duplicateLabel(const ir::Block& b);

  front::BlockReader bytes_;
  diag::Engine& diags_;
  front::RawBlock raw_;
  std::set<std::int64_t> labels_; // of the program being read
  std::size_t failed_ = 0;
};

} // namespace gcx::wl4
