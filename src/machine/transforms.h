// Programmable transformations (nct.md §3.15): rotation G68, scaling G51, mirror G51.1. They act on
// the programmed point before the offsets; the last activated is applied first, and mirror,
// which may only be switched on in G50+G69 state, is always outermost.
#pragma once
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "motion/event.h"

namespace gcx::machine {

using Vec3 = Eigen::Vector3d;
using Affine = Eigen::Affine3d;

class Transforms {
public:
  enum class Kind { Rotate, Scale };

  bool rotating() const { return has(Kind::Rotate); }
  bool scaling() const { return has(Kind::Scale); }
  bool mirroring() const { return mirrorAxes_ != 0; }
  /// Mirrored axes: bit 0 = X, 1 = Y, 2 = Z.
  unsigned mirrorAxes() const { return mirrorAxes_; }
  bool identity() const { return layers_.empty() && !mirroring(); }
  /// The layer switched on last (on/off pairs must nest, nct.md §3.15 ordering rules).
  std::optional<Kind> innermost() const;

  void rotate(motion::Plane plane, const Vec3& centre, double degrees);
  void scale(const Vec3& centre, const Vec3& factors);
  void cancel(Kind k);
  /// Mirror about `position` on the axes in mask (bit 0 = X); cancel clears them.
  void mirror(unsigned mask, const Vec3& position);
  void cancelMirror(unsigned mask);
  void clear();

  /// Program point -> transformed point.
  const Affine& matrix() const { return total_; }
  Vec3 apply(const Vec3& p) const { return total_ * p; }
  Vec3 applyInverse(const Vec3& p) const { return total_.inverse() * p; }
  /// Rotation angle of an active G68 (degrees), for a following incremental G68 R.
  double rotationDegrees() const { return rotationDegrees_; }

private:
  struct Layer {
    Kind kind;
    Affine m;
  };
  bool has(Kind k) const;
  void rebuild();

  std::vector<Layer> layers_; // activation order
  unsigned mirrorAxes_ = 0;
  Vec3 mirrorPosition_ = Vec3::Zero();
  double rotationDegrees_ = 0;
  Affine total_ = Affine::Identity();
};

} // namespace gcx::machine
