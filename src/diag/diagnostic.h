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

  /// While a Divert lives, what its thread reports to (and asks of) `from` goes to `to`
  /// instead. A pipeline stage collects its own diagnostics this way, and the caller hands
  /// them on in source order, so a threaded run reports exactly what a sequential one does.
  class Divert {
  public:
    Divert(const Engine& from, Engine& to);
    ~Divert();
    Divert(const Divert&) = delete;
    Divert& operator=(const Divert&) = delete;

  private:
    const Engine* savedFrom_;
    Engine* savedTo_;
  };

  void report(Diagnostic d);
  void error(const char* code, SourceRange where, std::string message);
  void warning(const char* code, SourceRange where, std::string message);

  std::size_t errorCount() const { return self().errors_; }
  std::size_t warningCount() const { return self().warnings_; }
  bool hasErrors() const { return self().errors_ != 0; }
  bool limitReached() const { return self().errors_ >= errorLimit_; }
  std::size_t errorLimit() const { return errorLimit_; }
  const std::vector<Diagnostic>& all() const { return self().list_; }
  /// The last error reported, to chain notes under it (the call chain of a macro run), or null.
  Diagnostic* lastError();
  void clear() {
    Engine& e = self();
    e.list_.clear(), e.errors_ = e.warnings_ = 0;
  }

private:
  const Engine& self() const;
  Engine& self();

  std::size_t errorLimit_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
  std::vector<Diagnostic> list_;
};

/// Prints a problem that has no place in a program (a file that cannot be opened, a usage
/// error) on standard error: `gcx: error: message`.
void reportUsage(const std::string& message);

/// `file:line:col: error: message [code]`, the source line and a caret under the column.
std::string renderText(const Diagnostic& d, const SourceManager& sm);
/// A JSON array of all diagnostics, for tools (`--json`).
std::string renderJson(const std::vector<Diagnostic>& list, const SourceManager& sm);

} // namespace gcx::diag
