#include "machine/helix.h"

#include <cmath>
#include <fmt/format.h>

namespace gcx::machine {

std::variant<HelixPlan, std::string> planHelix(double s1, double s2, double e1, double e2,
                                               double c1, double c2, bool clockwise, double travel,
                                               double pitch, double tolerance) {
  if (pitch == 0) return std::string("a helix of pitch 0");
  const double n = travel / pitch; // turns the travel asks for
  if (n <= 0)
    return fmt::format("the pitch {} has not the sign of the linear travel {}", pitch, travel);
  const double twoPi = 2 * M_PI;
  const double a0 = std::atan2(s2 - c2, s1 - c1), a1 = std::atan2(e2 - c2, e1 - c1);
  double sweep = clockwise ? a0 - a1 : a1 - a0;
  sweep = std::fmod(sweep, twoPi);
  if (sweep < 0) sweep += twoPi;
  if (std::hypot(e1 - s1, e2 - s2) < 1e-9 || sweep < 1e-12) sweep = twoPi; // ends where it began
  const double fraction = sweep / twoPi;
  const double k = std::round(n - fraction);
  if (k < 0 || std::fabs(n - (k + fraction)) * std::fabs(pitch) > tolerance)
    return fmt::format("the helix does not fit: the travel {} at pitch {} is {} turns, the arc "
                       "sweeps {} degrees in its plane",
                       travel, pitch, n, sweep * 180 / M_PI);
  return HelixPlan{static_cast<int>(k), sweep};
}

} // namespace gcx::machine
