// The program-frame view of a work-frame motion stream: every point taken back through the
// programmable transformations (rotation, scaling, mirror) in force when the event was emitted,
// so the path reads as the program wrote it. An arc's radii are divided by the scale and its
// direction turns back under a mirror. Placed after WorkFrame, which removes the offsets, it
// completes the chain machine → work → program frame (docs/machine-model.md).
#pragma once
#include <Eigen/Geometry>
#include <functional>

#include "motion/event.h"

namespace gcx::motion {

class TransformFrame : public Sink {
public:
  /// transform: program point -> transformed point, as in force now (asked once per event).
  TransformFrame(Sink& next, std::function<Eigen::Affine3d()> transform)
      : next_(next), transform_(std::move(transform)) {}
  void event(const Event& e) override;
  void finish() override { next_.finish(); }

private:
  Sink& next_;
  std::function<Eigen::Affine3d()> transform_;
};

} // namespace gcx::motion
