// A dialect as the rest of gcx sees it: its profile, a streaming block source and a printer.
#pragma once
#include <functional>
#include <istream>
#include <memory>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "dialect/profile.h"
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
};

struct Dialect {
  std::string name;
  std::vector<std::string> extensions; // ".nct"
  const Profile& (*profile)();
  std::function<std::unique_ptr<BlockSource>(std::istream&, FileId, diag::Engine&)> open;
  std::string (*print)(const ir::Block&);
};

const std::vector<Dialect>& dialects();
const Dialect* findDialect(const std::string& name);
/// The dialect a file name's extension implies, or null.
const Dialect* dialectForPath(const std::string& path);

} // namespace gcx
