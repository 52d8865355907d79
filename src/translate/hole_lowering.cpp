#include "translate/hole_lowering.h"

namespace gcx::xlate {

std::optional<int> gcodeFor(const Profile& p, GAction action, int arg) {
  for (const GCodeSpec& g : p.gcodes)
    if (g.action == action && (arg < 0 || g.arg == arg)) return g.code10;
  return std::nullopt;
}

bool sameWritten(const BlockOut& out, double a, double b) {
  return out.rounded(a) == out.rounded(b);
}

} // namespace gcx::xlate
