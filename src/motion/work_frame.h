// The work-frame view of a motion stream: every point of every event re-expressed relative to
// the work origin in force when the interpreter emitted it — the machine position of program
// zero with all offsets (work offset G54..., the common shift, G92, G52, the active tool length
// and turning offsets), without rotation or scaling. So a picture shows the coordinates the
// program was written in; where an offset changes between two moves, the path jumps there.
#pragma once
#include <functional>

#include "motion/event.h"

namespace gcx::motion {

class WorkFrame : public Sink {
public:
  /// origin: the current work origin in the machine frame (asked once per event).
  WorkFrame(Sink& next, std::function<Vec3()> origin) : next_(next), origin_(std::move(origin)) {}
  void event(const Event& e) override;
  void finish() override { next_.finish(); }

private:
  Sink& next_;
  std::function<Vec3()> origin_;
};

} // namespace gcx::motion
