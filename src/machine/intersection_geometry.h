// Intersection calculations of the automatic contour geometry (nct.md §4.3): which point of
// two carriers (whole lines, whole circles) ends the first element and starts the second, an
// over-determined one. Pure plane geometry.
#pragma once
#include <optional>

#include "machine/offset_geometry.h"

namespace gcx::machine::comp {

struct IntersectionChoice {
  std::optional<Vec2> point;
  bool needsQ = false; // two points and no Q < 0 or Q > 0 to choose between them
};

/// The intersection of `first` (a line a→b or an arc from a about c) with `second` (a line
/// a→b, or a circle about c through b). Two points: Q < 0 takes the nearer, Q > 0 the farther
/// along the direction of the line (of `first` when both are lines); between two circles, the
/// first or the second met along the first arc from its start (nct.md Q26).
IntersectionChoice chooseIntersection(const Path2& first, const Path2& second, double q);

} // namespace gcx::machine::comp
