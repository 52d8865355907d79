// Diagnostics as values: severity, stable code, message, location and chained notes (clang style).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "ir/source.h"

namespace gcx::diag {

enum class Severity { Note, Warning, Error };

struct Note {
  SourceRange range;
  std::string message;
};

struct Diagnostic {
  Severity severity = Severity::Error;
  std::string code;
  std::string message;
  SourceRange range;
  std::vector<Note> notes; // "in macro O9010 called from main.nct:12", ...
};

/// Collects diagnostics of one run. Stops collecting errors after a limit so a binary file
/// or a runaway generator cannot produce millions of lines.
class Engine {
public:
  explicit Engine(std::size_t errorLimit = 50) : errorLimit_(errorLimit) {}

  void report(Diagnostic d);
  void error(const char* code, SourceRange where, std::string message);
  void warning(const char* code, SourceRange where, std::string message);

  std::size_t errorCount() const { return errors_; }
  std::size_t warningCount() const { return warnings_; }
  bool hasErrors() const { return errors_ != 0; }
  bool limitReached() const { return errors_ >= errorLimit_; }
  const std::vector<Diagnostic>& all() const { return list_; }
  /// The last error reported, to chain notes under it (the call chain of a macro run), or null.
  Diagnostic* lastError();
  void clear() { list_.clear(), errors_ = warnings_ = 0; }

private:
  std::size_t errorLimit_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
  std::vector<Diagnostic> list_;
};

/// `file:line:col: error: message [code]`, the source line and a caret under the column.
std::string renderText(const Diagnostic& d, const SourceManager& sm);
/// A JSON array of all diagnostics, for tools (`--json`).
std::string renderJson(const std::vector<Diagnostic>& list, const SourceManager& sm);

} // namespace gcx::diag
