#include "machine/contour_corners.h"

#include <fmt/format.h>

#include "diag/codes.h"
#include "motion/geometry.h"

namespace gcx::machine {

using Move = motion::Kind;

namespace {

bool isMove(const motion::Event& e) {
  return e.kind == Move::Rapid || e.kind == Move::Feed || e.kind == Move::Arc;
}

} // namespace

comp::Vec2 ContourCornerStage::planar(const motion::Vec3& v) const {
  const motion::PlaneAxes ax = motion::axesOf(plane_);
  return {v[ax.first], v[ax.second]};
}

comp::Path2 ContourCornerStage::pathOf(const motion::Event& e) const {
  return {e.kind == Move::Arc, planar(e.start), planar(e.end), planar(e.center), !e.clockwise};
}

bool ContourCornerStage::fail(const char* code, const motion::Provenance& at, std::string message) {
  if (!failure_) failure_ = CompensationFailure{code, at, std::move(message)};
  return false;
}

void ContourCornerStage::request(Kind kind, double size, motion::Plane plane) {
  request_ = Request{kind, size};
  plane_ = plane;
}

bool ContourCornerStage::endWaitingAt(const motion::Vec3& end) {
  if (!held_) return false;
  const motion::PlaneAxes ax = motion::axesOf(plane_);
  held_->end[ax.first] = end[ax.first], held_->end[ax.second] = end[ax.second];
  if (held_->kind == Move::Arc)
    held_->endRadius = (planar(held_->end) - planar(held_->center)).norm();
  return true;
}

bool ContourCornerStage::event(const motion::Event& e, motion::Sink& out) {
  if (failure_) return false;
  if (!held_ && !request_) { // no chamfer or rounding asked for or waiting: the usual move
    out.event(e);
    return true;
  }
  const bool planeMove =
      isMove(e) && (e.kind == Move::Arc || (planar(e.end) - planar(e.start)).norm() > 1e-9);
  if (!held_) {
    if (!planeMove) {
      out.event(e);
      return true;
    }
    if (e.kind == Move::Rapid)
      return fail(diag::code::IllegalChamfer, e.from,
                  "a chamfer or rounding follows a G1, G2 or G3 block, not a rapid move");
    held_ = e;
    heldRequest_ = *request_;
    request_.reset();
    return true;
  }
  if (!isMove(e) && e.kind != Move::End && e.kind != Move::Stop) {
    between_.push_back(e);
    return true;
  }
  if (!planeMove || e.kind == Move::Rapid)
    return fail(diag::code::IllegalChamfer, held_->from,
                "illegal chamfer or rounding: the next move is not a G1, G2 or G3 move in the "
                "selected plane");
  const motion::PlaneAxes ax = motion::axesOf(plane_);
  const comp::Path2 first = pathOf(*held_), second = pathOf(e);
  const bool chamfer = heldRequest_.kind == Kind::Chamfer;
  const comp::Blend b = chamfer ? comp::chamfer(first, second, heldRequest_.size)
                                : comp::rounding(first, second, heldRequest_.size);
  if (!b.fits)
    return fail(diag::code::ChamferTooBig, held_->from,
                fmt::format("the {} of {:g} does not fit on this block and the next",
                            chamfer ? "chamfer" : "rounding", heldRequest_.size));
  auto at = [&](const comp::Vec2& p, double normal) {
    motion::Vec3 v;
    v[ax.first] = p.x(), v[ax.second] = p.y(), v[ax.normal] = normal;
    return v;
  };
  motion::Event a = *held_;
  held_.reset();
  a.end = at(b.endFirst, a.end[ax.normal]);
  if (a.kind == Move::Arc) a.endRadius = (b.endFirst - first.c).norm();
  out.event(a);
  motion::Event blend;
  blend.kind = b.arc ? Move::Arc : Move::Feed;
  blend.from = a.from;
  blend.start = a.end;
  blend.end = at(b.startSecond, a.end[ax.normal]);
  blend.extraStart = blend.extraEnd = a.extraEnd;
  blend.feed = a.feed;
  blend.perRevolution = a.perRevolution;
  if (b.arc) {
    blend.center = at(b.centre, a.end[ax.normal]);
    blend.plane = plane_;
    blend.clockwise = !b.ccw;
    blend.startRadius = blend.endRadius = (b.endFirst - b.centre).norm();
  }
  out.event(blend);
  for (const motion::Event& x : between_) {
    motion::Event moved = x;
    moved.start = moved.end = blend.end;
    out.event(moved);
  }
  between_.clear();
  motion::Event next = e;
  next.start = blend.end;
  if (next.kind == Move::Arc) {
    next.startRadius = (b.startSecond - second.c).norm();
    next.center[ax.normal] = blend.end[ax.normal];
  }
  return event(next, out); // it may end in a chamfer or rounding of its own
}

} // namespace gcx::machine
