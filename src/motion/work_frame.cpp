#include "motion/work_frame.h"

#include "motion/geometry.h"

namespace gcx::motion {

void WorkFrame::event(const Event& e) {
  if (!isMotion(e)) {
    next_.event(e);
    return;
  }
  const Vec3 o = origin_();
  Event w = e;
  w.start -= o;
  w.end -= o;
  w.center -= o;
  next_.event(w);
}

} // namespace gcx::motion
