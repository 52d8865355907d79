// Helpers shared by the tests: parse text or files through the real front end and the static
// checks, and find corpus files.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "front/encoding.h"
#include "ir/block.h"

namespace gcx::test {

namespace fs = std::filesystem;

struct Parsed {
  SourceManager sources;
  diag::Engine diags{1000};
  std::vector<ir::Block> blocks;
  std::size_t fastPathBlocks = 0;

  /// "line:col CODE" of every error, in order.
  std::vector<std::string> errors() const;
  std::vector<std::string> warnings() const;
  /// All diagnostics rendered as text, for failure messages.
  std::string rendered() const;
};

struct ParseOptions {
  bool fastPath = true;
  bool staticChecks = true;
  std::string name = "test.nct";
  std::optional<front::Encoding> encoding = std::nullopt; // empty: NCT's own
};

/// Parses NCT text (as a file named opt.name) and runs the static checks.
Parsed parseNct(const std::string& text, const ParseOptions& opt = {});
Parsed parseNctFile(const fs::path& path, const ParseOptions& opt = {});

std::string readFile(const fs::path& p);
fs::path sourceDir();
/// Files under dir (recursive) whose extension is one of exts, sorted.
std::vector<fs::path> filesUnder(const fs::path& dir, const std::vector<std::string>& exts);

} // namespace gcx::test
