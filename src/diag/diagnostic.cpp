#include "diag/diagnostic.h"

#include <fmt/format.h>
#include <iostream>
#include <nlohmann/json.hpp>

#include "diag/codes.h"

namespace gcx::diag {

namespace {
// One diversion per thread is all a pipeline stage needs.
thread_local const Engine* tDivertFrom = nullptr;
thread_local Engine* tDivertTo = nullptr;
} // namespace

Engine::Divert::Divert(const Engine& from, Engine& to)
    : savedFrom_(tDivertFrom), savedTo_(tDivertTo) {
  tDivertFrom = &from;
  tDivertTo = &to;
}

Engine::Divert::~Divert() {
  tDivertFrom = savedFrom_;
  tDivertTo = savedTo_;
}

const Engine& Engine::self() const {
  return tDivertFrom == this ? *tDivertTo : *this;
}

Engine& Engine::self() {
  return tDivertFrom == this ? *tDivertTo : *this;
}

void Engine::report(Diagnostic d) {
  if (tDivertFrom == this) {
    tDivertTo->report(std::move(d));
    return;
  }
  if (d.severity == Severity::Error) {
    if (errors_ >= errorLimit_) return;
    ++errors_;
    list_.push_back(std::move(d));
    if (errors_ == errorLimit_) {
      Diagnostic stop;
      stop.severity = Severity::Note;
      stop.code = code::TooManyErrors;
      stop.message = fmt::format("too many errors ({}), stopping", errorLimit_);
      list_.push_back(std::move(stop));
    }
    return;
  }
  if (d.severity == Severity::Warning) ++warnings_;
  list_.push_back(std::move(d));
}

void reportUsage(const std::string& message) {
  std::cerr << "gcx: error: " << message << '\n';
}

Diagnostic* Engine::lastError() {
  std::vector<Diagnostic>& list = self().list_;
  for (auto it = list.rbegin(); it != list.rend(); ++it)
    if (it->severity == Severity::Error) return &*it;
  return nullptr;
}

void Engine::error(const char* c, SourceRange where, std::string message) {
  report(Diagnostic{Severity::Error, c, std::move(message), where, {}});
}

void Engine::warning(const char* c, SourceRange where, std::string message) {
  report(Diagnostic{Severity::Warning, c, std::move(message), where, {}});
}

namespace {

const char* severityName(Severity s) {
  switch (s) {
  case Severity::Error:
    return "error";
  case Severity::Warning:
    return "warning";
  case Severity::Note:
    return "note";
  }
  return "?";
}

// The source line with tabs kept (so the caret lines up) and control bytes shown as '?'.
std::string printable(std::string line) {
  for (char& c : line)
    if (static_cast<unsigned char>(c) < 0x20 && c != '\t') c = '?';
  return line;
}

void appendLocated(std::string& out, Severity sev, const std::string& code,
                   const std::string& message, const SourceRange& r, const SourceManager& sm) {
  if (r.begin.valid())
    out += fmt::format("{}:{}:{}: ", sm.name(r.begin.file), r.begin.line, r.begin.col);
  out += fmt::format("{}: {}", severityName(sev), message);
  if (!code.empty()) out += fmt::format(" [{}]", code);
  out += '\n';
  if (!r.begin.valid()) return;
  const std::size_t shown = 160;
  std::string line = sm.lineText(r.begin, 4096);
  if (line.empty()) return;
  std::size_t col = r.begin.col - 1;
  std::size_t from = 0;
  if (col > shown) from = col - shown / 2; // long lines: show a window around the column
  std::string window = printable(line.substr(std::min(from, line.size()), shown));
  out += "  " + window + '\n';
  std::string caret(col - from, ' ');
  for (std::size_t i = 0; i < caret.size() && from + i < line.size(); ++i)
    if (line[from + i] == '\t') caret[i] = '\t';
  std::size_t len = r.length > 1 ? std::min<std::size_t>(r.length, line.size() - col) : 1;
  out += "  " + caret + '^' + std::string(len > 1 ? len - 1 : 0, '~') + '\n';
}

} // namespace

std::string renderText(const Diagnostic& d, const SourceManager& sm) {
  std::string out;
  appendLocated(out, d.severity, d.code, d.message, d.range, sm);
  for (const Note& n : d.notes)
    appendLocated(out, Severity::Note, "", n.message, n.range, sm);
  return out;
}

std::string renderJson(const std::vector<Diagnostic>& list, const SourceManager& sm) {
  nlohmann::json arr = nlohmann::json::array();
  auto where = [&](const SourceRange& r, nlohmann::json& j) {
    if (!r.begin.valid()) return;
    j["file"] = sm.name(r.begin.file);
    j["line"] = r.begin.line;
    j["column"] = r.begin.col;
    j["length"] = r.length;
  };
  for (const Diagnostic& d : list) {
    nlohmann::json j;
    j["severity"] = severityName(d.severity);
    j["code"] = d.code;
    j["message"] = d.message;
    where(d.range, j);
    nlohmann::json notes = nlohmann::json::array();
    for (const Note& n : d.notes) {
      nlohmann::json nj;
      nj["message"] = n.message;
      where(n.range, nj);
      notes.push_back(std::move(nj));
    }
    if (!notes.empty()) j["notes"] = std::move(notes);
    arr.push_back(std::move(j));
  }
  return arr.dump(2) + "\n";
}

} // namespace gcx::diag
