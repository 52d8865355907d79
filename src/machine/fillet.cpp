// A quarter-circle fillet (WL4 G12/G13, wl4.md §3.5): a 90° arc between two points that bound
// one quadrant, its radius the common leg, its centre one of the two corners (a0, b1) or
// (a1, b0): the one that makes the arc run in the programmed direction.
#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"
#include "emit/number.h"
#include "machine/interpreter.h"
#include "motion/geometry.h"

namespace gcx::machine {

bool Interpreter::fillet(const Vec3& end, const motion::Extra& extraEnd) {
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  const bool cw = state_.motion == GAction::FilletCW;
  const Vec3 start = program_;
  const double da = end[ax.first] - start[ax.first], db = end[ax.second] - start[ax.second];
  if (da == 0 || db == 0 || std::fabs(std::fabs(da) - std::fabs(db)) > radiusTolerance_)
    return fail(diag::code::ArcDefinition, blockRange_,
                fmt::format("fillet end point not on a quarter circle: it moves {} and {} in the "
                            "plane; both legs must be equal and not 0 (wl4.md §3.5)",
                            emit::formatNumber(da), emit::formatNumber(db)));
  if (state_.feed <= 0) return fail(diag::code::MissingData, blockRange_, "fillet without F");
  // about (a0, b1) the arc turns counter-clockwise iff da*db > 0; about (a1, b0) iff da*db < 0
  const bool startCorner = cw ? da * db < 0 : da * db > 0;
  Vec3 centre = start;
  centre[ax.first] = startCorner ? start[ax.first] : end[ax.first];
  centre[ax.second] = startCorner ? end[ax.second] : start[ax.second];
  return arcTo(end, centre, cw, 1, extraEnd, state_.feed);
}

} // namespace gcx::machine
