// How a linear map acts on one plane: as a similarity (a scale, a rotation and perhaps a mirror)
// or not. An arc stays a circle under the programmable transformations only when they are a
// similarity in its plane and do not mix the plane with its normal axis (nct.md §3.15, Q19).
#pragma once
#include <Eigen/Core>
#include <optional>

#include "motion/event.h"

namespace gcx::motion {

struct PlaneSimilarity {
  double scale = 1;      // lengths in the plane are multiplied by this
  bool mirrored = false; // orientation reversed: clockwise becomes counter-clockwise
};

/// nullopt when `linear` turns a circle in `plane` into something else.
std::optional<PlaneSimilarity> planeSimilarity(const Eigen::Matrix3d& linear, Plane plane);

} // namespace gcx::motion
