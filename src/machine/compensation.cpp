#include "machine/compensation.h"

#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"
#include "motion/geometry.h"

namespace gcx::machine {

using comp::Path2;
using comp::Vec2;
using motion::Kind;

namespace {

constexpr double kEps = 1e-9;

bool isMove(const motion::Event& e) {
  return e.kind == Kind::Rapid || e.kind == Kind::Feed || e.kind == Kind::Arc;
}

/// Swept angle from a to b about c in the arc's direction, in (0, 2π].
double sweep(const Vec2& a, const Vec2& b, const Vec2& c, bool ccw) {
  double s = std::atan2(comp::cross(a - c, b - c), (a - c).dot(b - c));
  if (!ccw) s = -s;
  if (s <= kEps) s += 2 * M_PI;
  return s;
}

} // namespace

Vec2 CompensationStage::planar(const motion::Vec3& v) const {
  const motion::PlaneAxes ax = motion::axesOf(plane_);
  return {v[ax.first], v[ax.second]};
}

motion::Vec3 CompensationStage::spatial(const Vec2& p, double normal) const {
  const motion::PlaneAxes ax = motion::axesOf(plane_);
  motion::Vec3 v;
  v[ax.first] = p.x(), v[ax.second] = p.y(), v[ax.normal] = normal;
  return v;
}

bool CompensationStage::inPlane(const motion::Event& e) const {
  return e.kind == Kind::Arc || (isMove(e) && (planar(e.end) - planar(e.start)).norm() > kEps);
}

Path2 CompensationStage::pathOf(const motion::Event& e) const {
  return {e.kind == Kind::Arc, planar(e.start), planar(e.end), planar(e.center), !e.clockwise};
}

bool CompensationStage::fail(const char* code, const motion::Provenance& at, std::string message) {
  if (!failure_) failure_ = CompensationFailure{code, at, std::move(message)};
  return false;
}

void CompensationStage::send(const motion::Event& e, motion::Sink& out) {
  out.event(e);
  tool_ = e.end;
  toolExtra_ = e.extraEnd;
  toolKnown_ = true;
}

bool CompensationStage::beginBlock(motion::Sink& out) {
  if (failure_) return false;
  ++blockIndex_;
  // a cancel block without plane motion: the waiting element ends on its perpendicular
  if (cancelPending_ && blockIndex_ > cancelBlock_) {
    cancelPending_ = false;
    if (!releaseAlone(false, out)) return false;
  }
  if (pending_ && ++waiting_ > options_.lookAheadBlocks)
    return fail(diag::code::CompBufferFull, pending_->e.from,
                fmt::format("radius compensation cannot continue: no motion in the plane within "
                            "{} blocks after this one, the look-ahead buffer is full",
                            options_.lookAheadBlocks));
  return true;
}

void CompensationStage::setMode(motion::Plane plane, int side, double radius,
                                const std::optional<Vec2>& direction) {
  plane_ = plane;
  if (side_ == 0 && side != 0) {
    startPending_ = true;
    startBlock_ = blockIndex_;
  }
  if (side_ != 0 && side == 0) {
    startPending_ = restart_ = false;
    if (pending_) {
      cancelPending_ = true;
      cancelBlock_ = blockIndex_;
    }
  }
  side_ = side;
  radius_ = radius;
  direction_ = direction;
}

void CompensationStage::breakLookAhead(motion::Sink& out) {
  if (failure_) return;
  if (pending_) releaseAlone(true, out);
  emitHeld(out);
  cancelPending_ = false;
  if (side_ != 0) restart_ = true, startPending_ = false;
  suspendedBlock_ = blockIndex_;
}

bool CompensationStage::event(const motion::Event& e, motion::Sink& out) {
  if (failure_) return false;
  if (!engaged() && !restart_) {
    send(e, out);
    return true;
  }
  if (blockIndex_ == suspendedBlock_) { // a breaker's own moves: uncompensated
    passAtTool(e, out);
    return true;
  }
  if (e.kind == Kind::End || e.kind == Kind::Stop) {
    // a G40 block without plane motion still ends the waiting element on its perpendicular
    if (pending_ && !releaseAlone(!cancelPending_, out)) return false;
    emitHeld(out);
    cancelPending_ = false;
    if (side_ != 0) restart_ = true;
    passAtTool(e, out);
    return true;
  }
  if (inPlane(e)) return element(e, out);
  if (cancelPending_ && isMove(e)) { // G40 with motion only outside the plane
    cancelPending_ = false;
    if (!releaseAlone(false, out)) return false;
  }
  if (pending_)
    held_.push_back(e);
  else
    passAtTool(e, out);
  return true;
}

bool CompensationStage::cornerArcTowards(const Vec2& direction, motion::Sink& out) {
  if (failure_ || !pending_) return false;
  const Element& a = *pending_;
  const Vec2 corner = a.path.b;
  return release({corner + a.d * comp::leftOf(comp::tangentAt(a.path, true)),
                  corner + a.d * comp::leftOf(direction.normalized())},
                 true, out);
}

bool CompensationStage::endWaitingAt(const motion::Vec3& end) {
  if (!pending_) return false;
  const motion::PlaneAxes ax = motion::axesOf(plane_);
  motion::Event& e = pending_->e;
  e.end[ax.first] = end[ax.first], e.end[ax.second] = end[ax.second];
  if (e.kind == Kind::Arc) e.endRadius = (planar(e.end) - planar(e.center)).norm();
  pending_->path = pathOf(e);
  return true;
}

bool CompensationStage::element(const motion::Event& e, motion::Sink& out) {
  const Path2 path = pathOf(e);
  const double d = side_ * radius_;
  if (cancelPending_) {
    cancelPending_ = false;
    if (pending_ && blockIndex_ == cancelBlock_ && !options_.cancelPerpendicular) {
      const auto c = comp::corner(pending_->path, path, pending_->d, pending_->d,
                                  comp::Join::Cancel, options_.outer, direction_);
      if (!release(c.points, c.arcAbout, out)) return false;
    } else if (!releaseAlone(false, out)) {
      return false;
    }
    passAtTool(e, out);
    return true;
  }
  if (side_ == 0) {
    passAtTool(e, out);
    return true;
  }
  if (path.arc && std::fabs(d) > 0 && !comp::offsetPath(path, d))
    return fail(diag::code::CompRadiusTooLarge, e.from,
                fmt::format("the tool radius {:g} is not smaller than the radius {:g} of this arc "
                            "on the side of the tool",
                            radius_, (path.a - path.c).norm()));
  if (pending_) {
    Element& a = *pending_;
    comp::Join join = comp::Join::Normal;
    double dSecond = a.d;
    if (a.startUp)
      join = comp::Join::StartUp;
    else if (zeroMove_)
      join = comp::Join::Perpendicular;
    else if (a.d * d < 0) // G41 <-> G42 or the sign of D changes (nct.md §3.17.4)
      join = comp::Join::Direction, dSecond = d;
    const auto rule = cornerArc_ ? comp::OuterCorner::Arc : options_.outer;
    auto c = comp::corner(a.path, path, a.d, dSecond, join, rule, a.virtualDir);
    if (c.arcAbout && c.points.size() == 2 &&
        (c.points[1] - c.points[0]).norm() <= options_.arcGapLimit) // a nearly smooth corner
      c = comp::corner(a.path, path, a.d, dSecond, join, comp::OuterCorner::TypeC, a.virtualDir);
    if (!c.arcAbout && options_.mergeDistance > 0) { // nct.md §3.17.1, 000:7700-7712
      // an inserted vector closer than DELTV on both axes to the one before is skipped; the
      // first element's end and the second's start stay
      std::vector<Vec2> kept;
      for (std::size_t i = 0; i < c.points.size(); ++i) {
        const Vec2 gap = kept.empty() ? Vec2::Zero() : Vec2((c.points[i] - kept.back()).cwiseAbs());
        if (kept.empty() || i + 1 == c.points.size() || gap.x() >= options_.mergeDistance ||
            gap.y() >= options_.mergeDistance)
          kept.push_back(c.points[i]);
      }
      c.points = kept;
    }
    if (a.startUp && options_.startUpPerpendicular && !a.virtualDir)
      c = comp::CornerResult{
          {path.a + d * comp::leftOf(comp::tangentAt(path, false))}, false, false};
    if (a.hold) // G38: the start vector again at the end (nct.md §3.17.5)
      c = comp::CornerResult{{a.path.b + (a.start - a.path.a)}, false, false};
    if (c.noIntersection)
      return fail(diag::code::CompNoIntersection, a.e.from,
                  "no intersection point of the compensated paths at the end of this block "
                  "(G41, G42)");
    std::optional<Vec2> centre;
    if (c.shiftedArc) { // nct.md §3.17.4: the programmed radius about a shifted centre
      centre = comp::shiftedCentre(planar(tool_), c.points.front(), (a.path.a - a.path.c).norm(),
                                   a.path.c);
      if (!centre)
        return fail(diag::code::CompNoIntersection, a.e.from,
                    "the direction of compensation cannot change at the end of this arc: no "
                    "intersection point, and no arc of its radius reaches the next block's "
                    "perpendicular (G41, G42)");
    }
    if (!release(c.points, c.arcAbout, out, centre)) return false;
  } else if (!(startPending_ && blockIndex_ == startBlock_) && !restart_) {
    // the start-up block had no plane motion: first a move of r perpendicular to the start of
    // this element, in its motion mode (nct.md §3.17.2)
    if (!toolKnown_) tool_ = e.start, toolExtra_ = e.extraStart, toolKnown_ = true;
    emitLine(e, path.a + d * comp::leftOf(comp::tangentAt(path, false)), out);
  }
  const bool startUp = !pending_ && ((startPending_ && blockIndex_ == startBlock_) || restart_);
  if (!toolKnown_) tool_ = e.start, toolExtra_ = e.extraStart, toolKnown_ = true;
  pending_ = Element{e,
                     path,
                     d,
                     startUp,
                     startUp ? direction_ : std::nullopt,
                     holdBlock_ == blockIndex_,
                     planar(tool_)};
  startPending_ = restart_ = zeroMove_ = cornerArc_ = false;
  waiting_ = 0;
  return true;
}

bool CompensationStage::release(const std::vector<Vec2>& points, bool arcAbout, motion::Sink& out,
                                const std::optional<Vec2>& centre) {
  const motion::PlaneAxes ax = motion::axesOf(plane_);
  const Element a = *pending_;
  pending_.reset();
  if (points.empty()) return true;
  const Vec2 from = planar(tool_), to = points.front();
  const Vec2 about = centre ? *centre : a.path.c;
  motion::Event m = a.e;
  m.start = tool_;
  m.extraStart = toolExtra_;
  m.end = spatial(to, a.e.end[ax.normal]);
  if (a.path.arc) {
    m.center = spatial(about, tool_[ax.normal]);
    m.startRadius = (from - about).norm();
    m.endRadius = (to - about).norm();
    // a full circle whose compensated end lies past its start still makes its whole turn
    // first (000:8034-8040)
    if (a.path.a == a.path.b && (to - from).norm() > kEps &&
        sweep(from, to, about, a.path.ccw) < M_PI)
      m.turns = a.e.turns + 1;
  }
  if (options_.interferenceCheck && !a.startUp && (to - from).norm() > kEps) {
    // the compensated move runs against the programmed one (nct.md §3.17.6)
    bool against = false;
    if (!a.path.arc) {
      against = (to - from).dot(a.path.b - a.path.a) < 0;
    } else {
      const double programmed = sweep(a.path.a, a.path.b, a.path.c, a.path.ccw);
      double compensated = sweep(from, to, about, a.path.ccw);
      if (programmed > 2 * M_PI - 1e-6 && compensated < M_PI) compensated += 2 * M_PI;
      against = std::fabs(compensated - programmed) > M_PI;
    }
    if (against)
      return fail(diag::code::CompInterference, a.e.from,
                  "interference: the compensated path of this block runs against its programmed "
                  "direction (the tool would cut into the contour)");
  }
  send(m, out);
  const Vec2 corner = a.path.b;
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (!arcAbout) {
      emitLine(a.e, points[i], out);
      continue;
    }
    motion::Event arc = a.e;
    arc.kind = Kind::Arc;
    arc.start = tool_;
    arc.extraStart = arc.extraEnd = toolExtra_;
    arc.end = spatial(points[i], tool_[ax.normal]);
    arc.center = spatial(corner, tool_[ax.normal]);
    arc.plane = plane_;
    arc.clockwise = comp::cross(points[i - 1] - corner, points[i] - corner) < 0;
    arc.turns = 0;
    arc.startRadius = arc.endRadius = (points[i - 1] - corner).norm();
    send(arc, out);
  }
  displaced_ = (planar(tool_) - a.path.b).norm() > kEps;
  emitHeld(out);
  return true;
}

bool CompensationStage::releaseAlone(bool onProgrammedPoint, motion::Sink& out) {
  if (!pending_) {
    emitHeld(out);
    return true;
  }
  const Element& a = *pending_;
  const Vec2 end = onProgrammedPoint
                       ? a.path.b
                       : Vec2(a.path.b + a.d * comp::leftOf(comp::tangentAt(a.path, true)));
  return release({end}, false, out);
}

void CompensationStage::emitHeld(motion::Sink& out) {
  std::vector<motion::Event> held;
  held.swap(held_);
  for (const motion::Event& e : held)
    passAtTool(e, out);
}

void CompensationStage::passAtTool(motion::Event e, motion::Sink& out) {
  if (!toolKnown_) tool_ = e.start, toolExtra_ = e.extraStart, toolKnown_ = true;
  const motion::PlaneAxes ax = motion::axesOf(plane_);
  const Vec2 programmedEnd = planar(e.end);
  const bool planeMove = inPlane(e);
  e.start = tool_;
  if (!isMove(e)) {
    e.end = tool_;
  } else if (!planeMove) { // out of the plane: where the tool stands in it
    e.end[ax.first] = tool_[ax.first];
    e.end[ax.second] = tool_[ax.second];
  } else if (e.kind == Kind::Arc) {
    e.startRadius = (planar(tool_) - planar(e.center)).norm();
    e.center[ax.normal] = tool_[ax.normal];
  }
  if (!isMove(e)) {
    out.event(e);
    return;
  }
  send(e, out);
  displaced_ = (planar(tool_) - programmedEnd).norm() > kEps;
}

void CompensationStage::emitLine(const motion::Event& like, const Vec2& to, motion::Sink& out) {
  const motion::PlaneAxes ax = motion::axesOf(plane_);
  if ((planar(tool_) - to).norm() <= kEps) return;
  motion::Event m;
  m.kind = like.kind == Kind::Arc ? Kind::Feed : like.kind;
  m.from = like.from;
  m.start = tool_;
  m.end = spatial(to, tool_[ax.normal]);
  m.extraStart = m.extraEnd = toolExtra_;
  m.feed = like.feed;
  m.perRevolution = like.perRevolution;
  send(m, out);
}

} // namespace gcx::machine
