#include "motion/geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gcx::motion {

namespace {
constexpr double kTwoPi = 2 * std::numbers::pi;
// End directions closer than this (mm along the arc) to the start direction mean "the same
// direction": a full turn, not a vanishing arc. Interpreters produce start == end exactly for
// full circles; this only absorbs rounding in the centre arithmetic.
constexpr double kSameDirection = 1e-9;
} // namespace

const char* planeCode(Plane p) {
  switch (p) {
  case Plane::XY:
    return "G17";
  case Plane::ZX:
    return "G18";
  case Plane::YZ:
    return "G19";
  }
  return "G17";
}

ArcRadii arcRadii(const Event& arc) {
  const PlaneAxes ax = axesOf(arc.plane);
  const double c1 = arc.center[ax.first], c2 = arc.center[ax.second];
  return {std::hypot(arc.start[ax.first] - c1, arc.start[ax.second] - c2),
          std::hypot(arc.end[ax.first] - c1, arc.end[ax.second] - c2)};
}

ArcGeometry::ArcGeometry(const Event& arc)
    : start_(arc.start), end_(arc.end), ax_(axesOf(arc.plane)), c1_(arc.center[ax_.first]),
      c2_(arc.center[ax_.second]), sign_(arc.clockwise ? -1 : 1) {
  const double s1 = start_[ax_.first] - c1_, s2 = start_[ax_.second] - c2_;
  const double e1 = end_[ax_.first] - c1_, e2 = end_[ax_.second] - c2_;
  const ArcRadii radii = arcRadii(arc);
  r0_ = radii.start;
  r1_ = radii.end;
  rise_ = end_[ax_.normal] - start_[ax_.normal];
  // A spiral that starts or ends at the centre takes its direction from the other end.
  double aStart = std::atan2(s2, s1), aEnd = std::atan2(e2, e1);
  if (r0_ == 0) aStart = aEnd;
  if (r1_ == 0) aEnd = aStart;
  a0_ = aStart;
  double delta = std::fmod(sign_ * (aEnd - aStart), kTwoPi);
  if (delta < 0) delta += kTwoPi;
  if (delta * std::max(r0_, r1_) <= kSameDirection) delta = kTwoPi;
  sweep_ = delta + kTwoPi * std::max(0, arc.turns);
}

double ArcGeometry::pitchB() const {
  return (r1_ - r0_) / sweep_;
}

Vec3 ArcGeometry::point(double t) const {
  if (t <= 0) return start_;
  if (t >= 1) return end_;
  const double phi = a0_ + sign_ * t * sweep_;
  const double r = r0_ + (r1_ - r0_) * t;
  Vec3 p;
  p[ax_.first] = c1_ + r * std::cos(phi);
  p[ax_.second] = c2_ + r * std::sin(phi);
  p[ax_.normal] = start_[ax_.normal] + t * rise_;
  return p;
}

Vec3 ArcGeometry::tangent(double t) const {
  t = std::clamp(t, 0.0, 1.0);
  const double phi = a0_ + sign_ * t * sweep_;
  const double r = r0_ + (r1_ - r0_) * t;
  const double b = pitchB(), c = std::cos(phi), s = std::sin(phi);
  // d/dθ of centre + r·(cos φ, sin φ) + height·n, with φ = a0 + sign·θ
  Vec3 d;
  d[ax_.first] = b * c - sign_ * r * s;
  d[ax_.second] = b * s + sign_ * r * c;
  d[ax_.normal] = rise_ / sweep_;
  const double n = d.norm();
  return n > 0 ? Vec3(d / n) : Vec3::Zero();
}

double ArcGeometry::length() const {
  // |dp/dθ|² = r² + b² + c² with r = r0 + bθ, b = dr/dθ, c = dh/dθ.
  if (r0_ == r1_) return std::hypot(r0_ * sweep_, rise_);
  const double b = pitchB(), c = rise_ / sweep_;
  const double k2 = b * b + c * c;
  auto f = [k2](double r) { return std::sqrt(r * r + k2); };
  if (std::abs(r1_ - r0_) <= 1e-3 * std::max(r0_, r1_)) {
    // The closed form below cancels badly for nearly equal radii; Simpson is exact to ~1e-16
    // there because the integrand hardly varies.
    return sweep_ / 6 * (f(r0_) + 4 * f(0.5 * (r0_ + r1_)) + f(r1_));
  }
  const double k = std::sqrt(k2);
  auto F = [k, k2](double r) { return 0.5 * (r * std::sqrt(r * r + k2) + k2 * std::asinh(r / k)); };
  return (F(r1_) - F(r0_)) / b;
}

double ArcGeometry::maxSecondDerivative() const {
  // d²p/dθ² = 2·b·sign·w − r·u (u radial, w its perpendicular): |·| = √(r² + 4b²).
  const double b = pitchB(), r = std::max(r0_, r1_);
  return std::sqrt(r * r + 4 * b * b);
}

Box3 ArcGeometry::bounds() const {
  Box3 box(start_);
  box.extend(end_);
  if (std::max(r0_, r1_) == 0) return box;
  // The in-plane coordinates have extrema where ψ(θ) = φ + atan2(sign·r, b) crosses a multiple of
  // π/2 (odd: first axis, even: second axis); ψ is strictly monotone, rate sign·(1 + b²/(b²+r²)).
  // The normal coordinate is linear, so its extremes are the end points.
  const double b = pitchB();
  auto psi = [&](double th) {
    const double r = r0_ + b * th;
    return a0_ + sign_ * th + std::atan2(sign_ * r, b);
  };
  auto solve = [&](double tau, double lo, double hi) {
    if (b == 0) return sign_ * (tau - psi(0));
    for (int i = 0; i < 100 && hi - lo > 1e-15 * sweep_; ++i) {
      const double mid = 0.5 * (lo + hi);
      (sign_ * (psi(mid) - tau) < 0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  // Extreme values of one kind grow with r (|value| = r²/√(r²+b²)) and every kind recurs within
  // each turn, so only the first and the last turn can hold the extremes.
  auto scan = [&](double lo, double hi) {
    const double pa = psi(lo), pb = psi(hi);
    const double step = std::numbers::pi / 2;
    const double mFirst = std::ceil(std::min(pa, pb) / step),
                 mLast = std::floor(std::max(pa, pb) / step);
    for (double m = mFirst; m <= mLast; ++m) {
      const double th = std::clamp(solve(m * step, lo, hi), lo, hi);
      box.extend(point(th / sweep_));
    }
  };
  if (sweep_ <= 2 * kTwoPi) {
    scan(0, sweep_);
  } else {
    scan(0, kTwoPi);
    scan(sweep_ - kTwoPi, sweep_);
  }
  return box;
}

double sweptAngle(const Event& arc) {
  return ArcGeometry(arc).sweep();
}

bool isMotion(const Event& e) {
  return e.kind == Kind::Rapid || e.kind == Kind::Feed || e.kind == Kind::Arc;
}

double pathLength(const Event& e) {
  switch (e.kind) {
  case Kind::Rapid:
  case Kind::Feed:
    return (e.end - e.start).norm();
  case Kind::Arc:
    return ArcGeometry(e).length();
  default: // every other kind moves nothing (isMotion)
    break;
  }
  return 0;
}

Box3 pathBounds(const Event& e) {
  switch (e.kind) {
  case Kind::Rapid:
  case Kind::Feed: {
    Box3 box(e.start);
    box.extend(e.end);
    return box;
  }
  case Kind::Arc:
    return ArcGeometry(e).bounds();
  default: // every other kind moves nothing (isMotion)
    break;
  }
  return Box3();
}

} // namespace gcx::motion
