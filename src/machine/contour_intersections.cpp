// Intersection calculations of the automatic contour geometry (nct.md §4.3, 000:8967-9406): an
// over-determined line (both plane coordinates and ,A) or circle (absolute centre I J K and R)
// ends the element of the block before at their intersection and starts there. That element
// has been emitted already and waits in the corner or the compensation stage (intersections
// run only under G41/G42), which moves its end; a line by its direction alone waits here.
#include <cmath>
#include <fmt/format.h>
#include <utility>

#include "diag/codes.h"
#include "machine/interpreter.h"
#include "machine/intersection_geometry.h"
#include "motion/geometry.h"

namespace gcx::machine {

using motion::Kind;

void Interpreter::rememberPlaneMove(const motion::Event& e) {
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  const comp::Vec2 a(e.start[ax.first], e.start[ax.second]), b(e.end[ax.first], e.end[ax.second]);
  if (e.kind != Kind::Arc && (b - a).norm() <= 1e-9) return;
  comp::Path2 p{e.kind == Kind::Arc, a, b, {e.center[ax.first], e.center[ax.second]}, !e.clockwise};
  lastPlaneMove_ = PlaneMove{p, blockSerial_};
}

bool Interpreter::intersection(const BlockWords& w, Vec3& to, bool& over) {
  over = false;
  // the usual block: neither marker of an over-determined element, and no line waiting for one
  if (!w.angle && !w.r && !directionLine_) return true;
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  const bool line = state_.motion == GAction::Rapid || state_.motion == GAction::Linear;
  const bool arc = state_.motion == GAction::ArcCW || state_.motion == GAction::ArcCCW;
  const ir::Word *i = w.ijk[ax.first], *j = w.ijk[ax.second];
  const bool chapter17 = !profile_.machine.contour.angle.empty();
  const bool overLine =
      chapter17 && line && w.angle && axisGiven(w, ax.first) && axisGiven(w, ax.second);
  // outside G41/G42, R with I J is the arc error of nct.md Q20
  const bool overArc =
      chapter17 && arc && w.r && (i || j) && state_.radiusComp != GAction::RadiusCompOff;
  if (!overLine && !overArc) {
    if (directionLine_)
      return fail(diag::code::IntersectionElement, blockRange_,
                  "the line given by its direction alone (,A) in the block before needs an "
                  "over-determined line (both plane coordinates and ,A) or circle (I J and R) "
                  "here (nct.md §4.3)");
    return true;
  }
  const ir::Word* marker = overLine ? w.angle : w.r;
  const char* what = overLine ? "line" : "circle";
  if (state_.radiusComp == GAction::RadiusCompOff)
    return fail(diag::code::IntersectionElement, marker->range,
                "a line with both plane coordinates and ,A is an intersection calculation, which "
                "runs only under G41/G42 (D0 for no offset) (nct.md §4.3)");
  if (overArc && !(i && j))
    return fail(diag::code::ArcDefinition, (i ? i : j)->range,
                "an over-determined circle gives both coordinates of its centre (nct.md §4.3)");
  // the end point and the centre of an over-determined element are absolute (000:9043-9044)
  Vec3 end = to, centre = to;
  for (int a : {ax.first, ax.second})
    if (const ir::Word* x = w.axis[a] ? w.axis[a] : w.uvw[a]) end[a] = coordinate(a, *x);
  const Eigen::Matrix3d lin = transforms_.matrix().linear();
  auto planar = [&](const Vec3& v) { return comp::Vec2(v[ax.first], v[ax.second]); };
  const comp::Vec2 endM = planar(toMachine(end));
  comp::Path2 second;
  if (overLine) {
    const double a = w.angle->number * M_PI / 180;
    Vec3 d = Vec3::Zero();
    d[ax.first] = std::cos(a), d[ax.second] = std::sin(a);
    second = {false, endM - planar(lin * d), endM};
  } else {
    centre[ax.first] = coordinate(ax.first, *i);
    centre[ax.second] = coordinate(ax.second, *j);
    const double radius = std::fabs(mm(w.r->number));
    if (radius < 1e-9) return fail(diag::code::ArcZeroRadius, w.r->range, "arc of radius R0");
    const double onCircle =
        std::hypot(end[ax.first] - centre[ax.first], end[ax.second] - centre[ax.second]);
    if (std::fabs(onCircle - radius) > radiusTolerance_)
      return fail(diag::code::ArcRadiusMismatch, w.r->range,
                  fmt::format("the end point lies {:g} from the centre, not on the circle of R{:g} "
                              "(nct.md §4.3)",
                              onCircle, radius));
    const double det = lin(ax.first, ax.first) * lin(ax.second, ax.second) -
                       lin(ax.first, ax.second) * lin(ax.second, ax.first);
    const comp::Vec2 c = planar(toMachine(centre));
    const comp::Vec2 b = c + radius * std::sqrt(std::fabs(det)) * (endM - c).normalized();
    second = {true, b, b, c, (state_.motion == GAction::ArcCCW) == (det > 0)};
  }
  // the element it ends: a line by its direction alone, or the plane move of the block before
  comp::Path2 first;
  if (directionLine_) {
    const double a = directionLine_->degrees * M_PI / 180;
    Vec3 d = Vec3::Zero();
    d[ax.first] = std::cos(a), d[ax.second] = std::sin(a);
    first.a = planar(machine_);
    first.b = first.a + planar(lin * d);
  } else if (lastPlaneMove_ && lastPlaneMove_->block + 1 == blockSerial_) {
    first = lastPlaneMove_->path;
  } else {
    return fail(diag::code::IntersectionElement, marker->range,
                fmt::format("an over-determined {} ends the line or arc of the block before at "
                            "their intersection, and the block before has none in the plane "
                            "(nct.md §4.3)",
                            what));
  }
  const comp::IntersectionChoice choice =
      comp::chooseIntersection(first, second, w.q ? w.q->number : 0.0);
  if (choice.needsQ)
    return fail(diag::code::IntersectionChoice, w.q ? w.q->range : marker->range,
                "the elements meet in two points: Q<0 takes the nearer, Q>0 the farther along "
                "the line (between two circles the first or the second along the first arc) "
                "(nct.md §4.3)");
  if (!choice.point)
    return fail(diag::code::CompNoIntersection, marker->range,
                "the elements do not meet: no intersection point (nct.md §4.3)");
  Vec3 meet = machine_;
  meet[ax.first] = choice.point->x(), meet[ax.second] = choice.point->y();
  if (directionLine_) { // it moves now, with its own provenance, feed and mode
    const DirectionLine d = *std::exchange(directionLine_, std::nullopt);
    const motion::Provenance here = std::exchange(from_, d.from);
    emitLine(d.motion == GAction::Rapid ? Kind::Rapid : Kind::Feed, meet, extra_, d.feed);
    from_ = here;
  } else if (!corners_.endWaitingAt(meet) && !comp_.endWaitingAt(meet)) {
    return fail(diag::code::IntersectionElement, marker->range,
                "the element of the block before has left the compensation already (a "
                "look-ahead breaker, or compensation kept for the target): no intersection "
                "calculation (nct.md §4.3)");
  }
  machine_ = meet;
  reexpress();
  to = end;
  if (overArc) overCentre_ = centre;
  over = true;
  return true;
}

} // namespace gcx::machine
