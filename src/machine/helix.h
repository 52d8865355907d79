// A helix given by its pitch (FMS-3000 G10, fms3000.md §3.6): the number of full turns that
// the linear travel and the in-plane sweep imply, or why they do not fit together.
#pragma once
#include <string>
#include <variant>

namespace gcx::machine {

struct HelixPlan {
  int fullTurns = 0; // whole turns before the in-plane sweep
  double sweep = 0;  // the in-plane sweep in radians, (0, 2π]
};

/// start, end, centre: in-plane coordinates (first, second axis); travel: the linear axis's
/// displacement; pitch: travel per turn, signed like the travel; tolerance: the arc radius
/// tolerance (mm). A plan, or the message of an error.
std::variant<HelixPlan, std::string> planHelix(double s1, double s2, double e1, double e2,
                                               double c1, double c2, bool clockwise, double travel,
                                               double pitch, double tolerance);

} // namespace gcx::machine
