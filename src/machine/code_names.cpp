#include "machine/code_names.h"

#include <fmt/format.h>

#include "emit/number.h"
#include "machine/settings.h"

namespace gcx::machine {

std::string gName(const ir::Word& w) {
  return std::string("G").append(emit::formatNumber(w.number));
}

std::string codeName(const Profile& profile, GAction action) {
  const GCodeSpec* g = codeOf(profile, action);
  return g ? "G" + emit::formatNumber(g->code10 / 10.0) : std::string();
}

std::string mCodeList(const std::vector<int>& codes) {
  std::string list;
  for (std::size_t i = 0; i < codes.size(); ++i)
    list += fmt::format("{}M{}", i == 0 ? "" : i + 1 == codes.size() ? " and " : ", ", codes[i]);
  return list;
}

} // namespace gcx::machine
