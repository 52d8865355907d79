// Arc, helix and spiral geometry of an Arc event, shared by every consumer (stats, sampling,
// traces, pictures, equivalence), so they all agree on what an arc is.
//
// Conventions (RS274/NGC): a plane names its (first, second, normal) axes, always a right-handed
// triple, and counter-clockwise is positive seen from the positive normal axis:
//   XY (G17): (X, Y, Z)   ZX (G18): (Z, X, Y)   YZ (G19): (Y, Z, X)
// The swept angle is the directed angle from start to end in the plane, in (0, 2π] (2π when the
// two directions coincide, e.g. start == end), plus 2π per extra turn. The radius varies linearly
// with the angle from |start−centre| to |end−centre| (a planar spiral when they differ), and the
// normal component linearly from start to end (a helix). Both radii are measured from the points,
// not taken from Event::startRadius/endRadius, so point(1) is exactly the event's end.
#pragma once
#include <Eigen/Geometry>

#include "motion/event.h"

namespace gcx::motion {

using Box3 = Eigen::AlignedBox3d;

/// Indices into Vec3 of a plane's first, second and normal axis.
struct PlaneAxes {
  int first, second, normal;
};
/// Inline: the interpreter asks it several times for every move.
inline PlaneAxes axesOf(Plane p) {
  switch (p) {
  case Plane::XY:
    return {0, 1, 2};
  case Plane::ZX:
    return {2, 0, 1};
  case Plane::YZ:
    return {1, 2, 0};
  }
  return {0, 1, 2};
}
/// The RS274/NGC code selecting the plane: "G17", "G18", "G19".
const char* planeCode(Plane p);

/// The distances of an Arc event's start and end from its centre in its plane: the radii
/// ArcGeometry holds, without the angles (a writer asks for them to tell a spiral by).
struct ArcRadii {
  double start, end;
};
ArcRadii arcRadii(const Event& arc);

class ArcGeometry {
public:
  explicit ArcGeometry(const Event& arc);

  double sweep() const { return sweep_; }   // total swept angle, radians, >= 0
  double startAngle() const { return a0_; } // direction of start from centre, radians
  double startRadius() const { return r0_; }
  double endRadius() const { return r1_; }
  double rise() const { return rise_; } // end − start along the normal axis
  bool clockwise() const { return sign_ < 0; }
  bool isSpiral() const { return r0_ != r1_; }
  PlaneAxes axes() const { return ax_; }

  /// The point at parameter t in [0, 1] (angle, radius and height all linear in t).
  Vec3 point(double t) const;
  /// Unit tangent in the direction of travel at t (zero for a degenerate arc).
  Vec3 tangent(double t) const;
  /// Path length: closed form for circles, helices, spirals and conical helices.
  double length() const;
  /// Exact axis-aligned bounds of the whole path (not just the end points).
  Box3 bounds() const;
  /// Largest |d²p/dθ²| along the arc; bounds the chord error of a polyline (interpolator).
  double maxSecondDerivative() const;

private:
  Vec3 start_, end_;
  PlaneAxes ax_;
  double c1_, c2_; // centre in plane coordinates
  double a0_ = 0, sweep_ = 0, r0_ = 0, r1_ = 0, rise_ = 0;
  double sign_ = 1; // +1 counter-clockwise, −1 clockwise

  double pitchB() const; // dr/dθ
};

/// Swept angle of an Arc event (radians).
double sweptAngle(const Event& arc);
/// Length of the path an event moves along: line length, arc length, 0 for non-motion events.
double pathLength(const Event& e);
/// Whether the event moves the tool (Rapid, Feed, Arc).
bool isMotion(const Event& e);
/// Exact bounds of a motion event's path (empty box for non-motion events).
Box3 pathBounds(const Event& e);

} // namespace gcx::motion
