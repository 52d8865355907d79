// The NCT front end: bytes in, IR blocks out, one block at a time (streaming).
#pragma once
#include <istream>
#include <memory>
#include <optional>

#include "dialect/profile.h"
#include "dialects/nct/tree_builder.h"
#include "front/block_reader.h"

namespace gcx::nct {

struct ReaderStats {
  std::size_t blocks = 0;
  std::size_t fastPath = 0; // blocks parsed without the grammar
  std::size_t grammar = 0;
  std::size_t failed = 0;
};

class Reader {
public:
  /// encoding: the file's; empty means NCT's default (lexicalRules().encoding).
  Reader(std::istream& in, FileId file, diag::Engine& diags, front::ReaderLimits limits = {},
         std::optional<front::Encoding> encoding = {});

  /// The next well-formed block; blocks with errors are reported and skipped. False at the end.
  bool next(ir::Block& out);
  const ReaderStats& stats() const { return stats_; }
  bool sawInput() const { return bytes_.sawAnyByte(); }
  /// Reading a part of the file (BlockSource::startAt and the rest).
  bool canReadInParts() const { return !bytes_.converts(); }
  void startAt(std::uint64_t offset, std::uint32_t line) { bytes_.startAt(offset, line); }
  void stopAt(std::uint64_t offset) { bytes_.stopAt(offset); }
  std::optional<SourceLoc> stoppedAt() const { return bytes_.stoppedAt(); }
  void shiftLines(std::int64_t delta) { bytes_.shiftLines(delta); }
  /// No G10 data records open: reading on is reading a new source from here.
  bool stateless() const { return !dataMode_; }
  /// Disable the fast path (tests compare both paths).
  void setFastPath(bool on) { fastPath_ = on; }

private:
  void updateDataMode(ir::Block& b);

  front::BlockReader bytes_;
  diag::Engine& diags_;
  const Profile& profile_;
  GrammarParser grammar_;
  front::RawBlock raw_;
  ReaderStats stats_;
  bool fastPath_ = true;
  bool dataMode_ = false;
};

} // namespace gcx::nct
