// What every command needs to read one program: the file, its dialect, diagnostics and their
// printing in text or JSON.
#pragma once
#include <fstream>
#include <memory>
#include <optional>
#include <string>

#include "cli/commands.h"
#include "diag/diagnostic.h"
#include "dialect/dialect.h"

namespace gcx::cli {

class Session {
public:
  explicit Session(const CommonOptions& opt) : opt_(opt), diags_(opt.maxErrors) {}

  /// Opens a program file and picks its dialect; false (with a message on stderr) if it cannot.
  bool open(const std::string& path);
  BlockSource& source() { return *source_; }
  /// The dialect, reading the encoding --encoding chose (for the programs it calls too).
  const Dialect& dialect() const { return *dialect_; }
  const std::string& path() const { return path_; }

  FileId file() const { return file_; }
  diag::Engine& diags() { return diags_; }
  SourceManager& sources() { return sources_; }

  /// Prints the collected diagnostics (text on stderr, or JSON on stdout) and forgets them.
  void flushDiagnostics();

private:
  CommonOptions opt_;
  SourceManager sources_;
  diag::Engine diags_;
  std::ifstream in_;
  std::optional<Dialect> dialect_;
  std::string path_;
  FileId file_ = 0;
  std::unique_ptr<BlockSource> source_;
};

using diag::reportUsage; // an I/O or usage problem, in the diagnostics' format

} // namespace gcx::cli
