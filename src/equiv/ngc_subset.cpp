#include "equiv/ngc_subset.h"

#include <fmt/format.h>

#include <cctype>
#include <cstdlib>

#include "diag/codes.h"

namespace gcx::equiv {

namespace {

/// Why the word at text[i] (a letter, upper-cased) is beyond the subset, or null.
const char* beyond(char letter, std::string_view rest) {
  if (letter == 'O') return "O-word subroutines and control flow";
  if (letter == 'G') {
    const double g = std::strtod(std::string(rest.substr(0, 8)).c_str(), nullptr);
    if (g == 41 || g == 42 || g == 41.1 || g == 42.1) return "cutter radius compensation";
    if (((g >= 73 && g <= 89) && g != 80) || (g >= 70 && g <= 72) || g == 33.1)
      return "canned cycles";
  }
  return nullptr;
}

} // namespace

bool checkCanonicalSubset(std::string_view text, FileId file, diag::Engine& diags) {
  std::uint32_t line = 1, col = 1;
  bool comment = false;
  for (std::size_t i = 0; i < text.size(); ++i, ++col) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      col = 0;
      comment = false;
      continue;
    }
    if (comment) {
      if (c == ')') comment = false;
      continue;
    }
    if (c == '(') {
      comment = true;
      continue;
    }
    if (c == ';') { // the rest of the line is a comment
      while (i + 1 < text.size() && text[i + 1] != '\n')
        ++i;
      continue;
    }
    const char* why = nullptr;
    if (c == '#' || c == '[')
      why = "parameters and expressions";
    else if (std::isalpha(static_cast<unsigned char>(c)))
      why = beyond(static_cast<char>(std::toupper(static_cast<unsigned char>(c))),
                   text.substr(i + 1));
    if (why == nullptr) continue;
    diags.error(diag::code::NeedsRs274, SourceRange{SourceLoc{file, line, col}, 1},
                fmt::format("{} need LinuxCNC's own interpreter rs274, which is not installed; "
                            "install it with `apt-get install linuxcnc-uspace` (without it gcx "
                            "reads only the canonical RS274/NGC it writes)",
                            why));
    return false;
  }
  return true;
}

} // namespace gcx::equiv
