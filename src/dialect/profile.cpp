#include "dialect/profile.h"

#include <algorithm>
#include <cmath>

namespace gcx {

void Profile::index() {
  letters_.fill(0);
  for (std::size_t i = 0; i < addresses.size(); ++i) {
    const std::string& a = addresses[i].address;
    if (a.size() == 1 && a[0] >= 'A' && a[0] <= 'Z') letters_[a[0] - 'A'] = static_cast<int>(i + 1);
  }
  wholeGCodes_.fill(0);
  for (std::size_t i = gcodes.size(); i-- > 0;) // the first row of a code wins, as in gcode()
    if (const int t = gcodes[i].code10; t >= 0 && t % 10 == 0 && t / 10 < 256)
      wholeGCodes_[static_cast<std::size_t>(t / 10)] = static_cast<int>(i + 1);
  actions_.fill(0);
  for (const GCodeSpec& g : gcodes) {
    const auto bit = static_cast<unsigned>(g.action);
    actions_[bit / 64] |= std::uint64_t{1} << (bit % 64);
  }
  wholeMacroCalls_.fill(0);
  for (const int t : macroCallGCodes10)
    if (t >= 0 && t % 10 == 0 && t / 10 < 256)
      wholeMacroCalls_[static_cast<unsigned>(t / 10) / 64] |= std::uint64_t{1} << (t / 10 % 64);
  indexed_ = true;
}

const AddressSpec* Profile::addressNamed(std::string_view a) const {
  for (const AddressSpec& s : addresses)
    if (s.address == a) return &s;
  return nullptr;
}

const CycleMacro* Profile::cycleMacro(std::int64_t program) const {
  for (const CycleMacro& c : cycleMacros)
    if (c.program == program) return &c;
  return nullptr;
}

std::optional<int> gcodeTenths(double value) {
  if (value >= 0 && value <= 1e6 && value == static_cast<int>(value)) // a whole code: no rounding
    return static_cast<int>(value) * 10;
  const double t = value * 10.0;
  const double r = std::round(t);
  if (std::fabs(t - r) > 1e-6 || r < 0 || r > 1e7) return std::nullopt;
  return static_cast<int>(r);
}

bool Profile::macroCallByTenths(double value) const {
  const auto t = gcodeTenths(value);
  return t && std::find(macroCallGCodes10.begin(), macroCallGCodes10.end(), *t) !=
                  macroCallGCodes10.end();
}

const GCodeSpec* Profile::gcodeByTenths(double value) const {
  auto t = gcodeTenths(value);
  if (!t) return nullptr;
  for (const GCodeSpec& g : gcodes)
    if (g.code10 == *t) return &g;
  return nullptr;
}

} // namespace gcx
