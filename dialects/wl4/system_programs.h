// The programs WL4 ships with the dialect (wl4.md §5.2): the canned cycles %81-%89 as the
// manual prints them, signs restored. Their text lives in dialects/wl4/programs/*.wl4 and is
// compiled in (scripts/embed_wl4_programs.cmake); a user's own %nn beside the program wins.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gcx::wl4 {

struct SystemProgramText {
  const char* unit; // "81"
  const char* text; // the whole file: `%81` ... `%`
};

const std::vector<SystemProgramText>& systemProgramTexts();
/// The text of the file holding system program `unit`, if WL4 ships one.
std::optional<std::string_view> systemProgram(const std::string& unit);

} // namespace gcx::wl4
