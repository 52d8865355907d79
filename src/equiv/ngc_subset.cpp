#include "equiv/ngc_subset.h"

#include <fmt/format.h>

#include <cctype>
#include <cstdlib>

#include "diag/codes.h"

namespace gcx::equiv {

namespace {

/// Why the word (letter, upper-cased, and the text after it) is beyond the subset, or null.
const char* beyond(char letter, std::string_view rest, bool arcBlock) {
  if (letter == 'O') return "O-word subroutines and control flow";
  if (letter == 'P' && arcBlock) return "arc turns (P on G2/G3)"; // NCT counts turns with L
  if (letter == 'G') {
    const double g = std::strtod(std::string(rest.substr(0, 8)).c_str(), nullptr);
    if (g == 41 || g == 42 || g == 41.1 || g == 42.1) return "cutter radius compensation";
    if (((g >= 73 && g <= 89) && g != 80) || (g >= 70 && g <= 72) || g == 33.1)
      return "canned cycles";
  }
  return nullptr;
}

/// The line without comments, upper-cased.
std::string code(std::string_view line) {
  std::string out;
  bool comment = false;
  for (char c : line) {
    if (comment) {
      comment = c != ')';
      out += ' ';
      continue;
    }
    if (c == '(') comment = true;
    if (c == ';') break;
    out += comment ? ' ' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

bool isArcBlock(const std::string& s) {
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    if (s[i] != 'G') continue;
    const double g = std::strtod(s.c_str() + i + 1, nullptr);
    if (g == 2 || g == 3) return true;
  }
  return false;
}

} // namespace

bool checkCanonicalSubset(std::string_view text, FileId file, diag::Engine& diags) {
  std::uint32_t lineNo = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t eol = std::min(text.find('\n', pos), text.size());
    const std::string line = code(text.substr(pos, eol - pos));
    pos = eol + 1;
    ++lineNo;
    const bool arc = isArcBlock(line);
    for (std::size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      const char* why = nullptr;
      if (c == '#' || c == '[')
        why = "parameters and expressions";
      else if (std::isalpha(static_cast<unsigned char>(c)))
        why = beyond(c, std::string_view(line).substr(i + 1), arc);
      if (why == nullptr) continue;
      diags.error(diag::code::NeedsRs274,
                  SourceRange{SourceLoc{file, lineNo, static_cast<std::uint32_t>(i + 1)}, 1},
                  fmt::format("{} need LinuxCNC's own interpreter rs274, which is not installed; "
                              "install it with `apt-get install linuxcnc-uspace` (without it gcx "
                              "reads only the canonical RS274/NGC it writes, less arc turns)",
                              why));
      return false;
    }
  }
  return true;
}

} // namespace gcx::equiv
