// Numbered source lines around a location, for a report: bounded work whatever the file (reading
// stops after the last line wanted; a long line is cut, never held whole).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace gcx::report {

struct ExcerptLine {
  int number = 0;   // 1-based
  std::string text; // without the line end; cut to the byte limit
};

/// Lines line−context .. line+context of the file, those that exist; empty when the file cannot
/// be read or line < 1. Each line keeps at most maxBytes bytes (then "…").
std::vector<ExcerptLine> readExcerpt(const std::string& path, int line, int context = 5,
                                     std::size_t maxBytes = 240);

} // namespace gcx::report
