#include "motion/transform_frame.h"

#include "motion/geometry.h"
#include "motion/plane_similarity.h"

namespace gcx::motion {

void TransformFrame::event(const Event& e) {
  if (!isMotion(e)) {
    next_.event(e);
    return;
  }
  const Eigen::Affine3d t = transform_();
  const Eigen::Affine3d back = t.inverse();
  Event p = e;
  p.start = back * e.start;
  p.end = back * e.end;
  p.center = back * e.center;
  if (e.kind == Kind::Arc)
    // the interpreter emits only arcs that stay circles (planeSimilarity), so this holds
    if (const auto s = planeSimilarity(t.linear(), e.plane)) {
      p.startRadius = e.startRadius / s->scale;
      p.endRadius = e.endRadius / s->scale;
      p.clockwise = e.clockwise != s->mirrored;
    }
  next_.event(p);
}

} // namespace gcx::motion
