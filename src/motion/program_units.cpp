#include "motion/program_units.h"

#include "motion/geometry.h"

namespace gcx::motion {

namespace {
constexpr double kMmPerInch = 25.4;
constexpr int kFirstLinearExtra = 3; // U V W; A B C are degrees in either unit
} // namespace

void ProgramUnits::event(const Event& e) {
  if (e.kind == Kind::UnitsChange) inch_ = e.value == 20;
  if (!inch_ || !isMotion(e)) {
    next_.event(e);
    return;
  }
  Event p = e;
  p.start /= kMmPerInch;
  p.end /= kMmPerInch;
  p.center /= kMmPerInch;
  p.extraStart.tail<6 - kFirstLinearExtra>() /= kMmPerInch;
  p.extraEnd.tail<6 - kFirstLinearExtra>() /= kMmPerInch;
  p.startRadius /= kMmPerInch;
  p.endRadius /= kMmPerInch;
  p.feed /= kMmPerInch;
  p.lead /= kMmPerInch;
  next_.event(p);
}

} // namespace gcx::motion
