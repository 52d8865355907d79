#include "dialects/wl4/system_programs.h"

namespace gcx::wl4 {

std::optional<std::string_view> systemProgram(const std::string& unit) {
  for (const SystemProgramText& p : systemProgramTexts())
    if (unit == p.unit) return std::string_view(p.text);
  return std::nullopt;
}

} // namespace gcx::wl4
