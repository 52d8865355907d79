#include "motion/plane_similarity.h"

#include <cmath>

#include "motion/geometry.h"

namespace gcx::motion {

std::optional<PlaneSimilarity> planeSimilarity(const Eigen::Matrix3d& m, Plane plane) {
  const PlaneAxes ax = axesOf(plane);
  Eigen::Matrix2d a2;
  a2 << m(ax.first, ax.first), m(ax.first, ax.second), m(ax.second, ax.first),
      m(ax.second, ax.second);
  const Eigen::Matrix2d g = a2.transpose() * a2;
  const bool mixes =
      std::fabs(m(ax.normal, ax.first)) > 1e-12 || std::fabs(m(ax.normal, ax.second)) > 1e-12 ||
      std::fabs(m(ax.first, ax.normal)) > 1e-12 || std::fabs(m(ax.second, ax.normal)) > 1e-12;
  if (mixes || std::fabs(g(0, 0) - g(1, 1)) > 1e-9 * g(0, 0) || std::fabs(g(0, 1)) > 1e-9 * g(0, 0))
    return std::nullopt;
  return PlaneSimilarity{std::sqrt(std::fabs(a2.determinant())), a2.determinant() < 0};
}

} // namespace gcx::motion
