#include "dialect/profile.h"

#include <cmath>

namespace gcx {

const AddressSpec* Profile::address(std::string_view a) const {
  for (const AddressSpec& s : addresses)
    if (s.address == a) return &s;
  return nullptr;
}

std::optional<int> gcodeTenths(double value) {
  const double t = value * 10.0;
  const double r = std::round(t);
  if (std::fabs(t - r) > 1e-6 || r < 0 || r > 1e7) return std::nullopt;
  return static_cast<int>(r);
}

const GCodeSpec* Profile::gcode(double value) const {
  auto t = gcodeTenths(value);
  if (!t) return nullptr;
  for (const GCodeSpec& g : gcodes)
    if (g.code10 == *t) return &g;
  return nullptr;
}

} // namespace gcx
