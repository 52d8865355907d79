// The WL4 probing move G38 (wl4.md §3.8): a G0-G3 block that runs toward its end point and
// back to its start along the same path; a touch would end the outbound move early. gcx has no
// probe model, so it takes the spec's static reading: no touch, the move runs to its end point
// and back (a warning says so), and the dialect's results hold that end point. The canonical
// output writes the two moves as they are: LinuxCNC's G38.2 would stop with an error without a
// touch, so it cannot say "no touch" (docs/wl4.md). A skip move (FMS-3000 G32, fms3000.md §3.17)
// takes the same reading without the way back: the move runs to its end point.
#include <fmt/format.h>

#include "diag/codes.h"
#include "machine/interpreter.h"
#include "motion/geometry.h"

namespace gcx::machine {

bool Interpreter::probeBack(const ir::Word& code, const Vec3& from) {
  probing_ = false;
  if (probePath_.empty()) return true; // no motion, nothing to probe
  diags_.warning(diag::code::Wl4ProbeWithoutTouch, code.range, profile_.machine.probeWithoutTouch);
  probe_.machine = machine_;
  probe_.work = program_;
  probe_.distance = program_ - from;
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  std::vector<motion::Event> path = std::move(probePath_);
  probePath_.clear();
  for (auto it = path.rbegin(); it != path.rend(); ++it) {
    motion::Event back = *it;
    std::swap(back.start, back.end);
    std::swap(back.extraStart, back.extraEnd);
    if (back.kind == motion::Kind::Arc) {
      std::swap(back.startRadius, back.endRadius);
      back.clockwise = !back.clockwise;
      back.center[ax.normal] = back.start[ax.normal]; // the centre at the new start's height
    }
    machine_ = back.end;
    extra_ = back.extraEnd;
    emit(std::move(back));
    if (stopped_) return false;
  }
  program_ = from;
  return true;
}

bool Interpreter::skipWithoutTouch(const ir::Word& code) {
  if (state_.radiusComp == GAction::RadiusCompLeft || state_.radiusComp == GAction::RadiusCompRight)
    return fail(diag::code::SkipUnderCompensation, code.range,
                fmt::format("{} under radius compensation: the compensated path cannot end at an "
                            "unknown point; cancel the compensation first",
                            fmt::format("{}{}", code.address, code.text)));
  diags_.warning(diag::code::SkipWithoutTouch, code.range,
                 fmt::format("{}: gcx has no probe model and assumes the touch signal never "
                             "comes: the move runs to its end point",
                             fmt::format("{}{}", code.address, code.text)));
  return true;
}

} // namespace gcx::machine
