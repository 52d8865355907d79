// A dialect as the rest of gcx sees it: its profile, its lexical rules, a streaming block source
// and a program-level emitter. dialects/registry.cpp lists them.
#pragma once
#include <cstdint>
#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "dialect/profile.h"
#include "emit/emitter.h"
#include "front/lexical_rules.h"
#include "ir/block.h"

namespace gcx {

class BlockSource {
public:
  virtual ~BlockSource() = default;
  /// The next well-formed block; false at the end of the input.
  virtual bool next(ir::Block& out) = 0;
  /// True if the input held at least one byte.
  virtual bool sawInput() const = 0;
  /// Blocks that had errors and were skipped.
  virtual std::size_t failedBlocks() const = 0;

  // Reading one file in parts on several threads (gcx check, cli/check_in_parts.h), for a source
  // that can: it starts at a block boundary and stops before a block that begins past a cut.
  virtual bool canReadInParts() const { return false; }
  /// Before the first next(): the stream stands at byte `offset`, the start of line `line`.
  virtual void startAt(std::uint64_t /*offset*/, std::uint32_t /*line*/) {}
  /// next() returns false at the first block boundary at or after `offset`; 0: at the end.
  virtual void stopAt(std::uint64_t /*offset*/) {}
  /// After next() returned false: where the block after the boundary it stopped at begins (its
  /// offset and line), or nothing when the input ended or failed.
  virtual std::optional<SourceLoc> stoppedAt() const { return std::nullopt; }
  /// After a stop: the lines are numbered delta further from here on. A part read from a
  /// provisional first line, once the lines before it are counted.
  virtual void shiftLines(std::int64_t /*delta*/) {}
  /// True when reading on from here reads what a new source started here would (no state, such
  /// as NCT's G10 data records, carries over).
  virtual bool stateless() const { return false; }
};

struct Dialect {
  std::string name;
  std::vector<std::string> extensions; // ".nct"
  const Profile& (*profile)();
  const front::LexicalRules& (*lexicalRules)();
  std::unique_ptr<BlockSource> (*openSource)(std::istream&, FileId, diag::Engine&, front::Encoding);
  std::unique_ptr<emit::ProgramEmitter> (*emitter)(std::ostream&);
  emit::Capabilities (*emits)(); // what emitter() can express, without making one
  /// The encoding open() reads; empty: the dialect's own (lexicalRules().encoding). A command
  /// copies the registry's row and sets it from --encoding.
  std::optional<front::Encoding> encoding;
  /// Translating to itself prints the program back (`gcx fmt`) with its variables, jumps, calls
  /// and programs kept, instead of the expansion's flat blocks (WL4, docs/translation.md).
  bool keepsStructureToItself = false;

  /// The encoding its programs are read and written in.
  front::Encoding textEncoding() const { return encoding.value_or(lexicalRules().encoding); }
  std::unique_ptr<BlockSource> open(std::istream& in, FileId file, diag::Engine& diags) const {
    return openSource(in, file, diags, textEncoding());
  }
};

const std::vector<Dialect>& dialects();
const Dialect* findDialect(const std::string& name);
/// The dialect a file name's extension implies, or null.
const Dialect* dialectForPath(const std::string& path);
std::vector<std::string> dialectNames();

} // namespace gcx
