#include "equiv/piece.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gcx::equiv {

namespace {
constexpr double kTwoPi = 2 * std::numbers::pi;
} // namespace

Piece::Piece(const motion::Event& e, const MotionState& state)
    : event_(e), state_(state), start_(e.start), end_(e.end), extraStart_(e.extraStart),
      extraEnd_(e.extraEnd) {
  if (e.kind == motion::Kind::Arc) arc_.emplace(e);
  length_ = motion::pathLength(e);
  extraLength_ = (extraEnd_ - extraStart_).norm();
}

Piece Piece::rapidRun(const motion::Event& first, const motion::Event& last,
                      const MotionState& state) {
  Piece p(last, state);
  p.start_ = first.start;
  p.extraStart_ = first.extraStart;
  p.length_ = (p.end_ - p.start_).norm();
  p.extraLength_ = (p.extraEnd_ - p.extraStart_).norm();
  p.run_ = true;
  p.first_ = first;
  return p;
}

double Piece::lengthFrom(double t) const {
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(pathLengthFrom(t), (1 - t) * extraLength_);
}

double Piece::pathLengthFrom(double t) const {
  if (!arc_ || !arc_->isSpiral()) return (1 - t) * length_;
  // |dp/dt|² = (sweep·r(t))² + (r1 − r0)² + rise², r linear in t: Simpson on 32 intervals
  const motion::ArcGeometry& a = *arc_;
  auto speed = [&](double u) {
    const double r = a.startRadius() + (a.endRadius() - a.startRadius()) * u;
    const double dr = a.endRadius() - a.startRadius();
    return std::sqrt(a.sweep() * a.sweep() * r * r + dr * dr + a.rise() * a.rise());
  };
  constexpr int n = 32;
  const double h = (1 - t) / n;
  double sum = speed(t) + speed(1);
  for (int i = 1; i < n; ++i)
    sum += (i % 2 ? 4 : 2) * speed(t + i * h);
  return sum * h / 3;
}

Vec3 Piece::point(double t) const {
  if (arc_) return arc_->point(t);
  return start_ + std::clamp(t, 0.0, 1.0) * (end_ - start_);
}

motion::Extra Piece::extra(double t) const {
  return extraStart_ + std::clamp(t, 0.0, 1.0) * (extraEnd_ - extraStart_);
}

double Piece::nearest(const Vec3& p, double lo, double hi, double hint, double tol,
                      const motion::Extra* px) const {
  const bool axisSpace = px && !arc_;
  auto distance = [&](double t) {
    const double dxyz = (point(t) - p).norm();
    return axisSpace ? std::hypot(dxyz, (extra(t) - *px).norm()) : dxyz;
  };
  double best = lo, bestDist = distance(lo);
  auto consider = [&](double t) {
    if (t < lo || t > hi) return;
    const double dist = distance(t);
    const bool bothClose = dist <= tol && bestDist <= tol;
    if (bothClose ? std::abs(t - hint) < std::abs(best - hint) : dist < bestDist) {
      best = t;
      bestDist = dist;
    }
  };
  if (!arc_) {
    const Vec3 d = end_ - start_;
    double along = (p - start_).dot(d), len2 = d.squaredNorm();
    if (axisSpace) {
      const motion::Extra de = extraEnd_ - extraStart_;
      along += (*px - extraStart_).dot(de);
      len2 += de.squaredNorm();
    }
    if (len2 > 0) consider(std::clamp(along / len2, lo, hi));
    return best;
  }
  // The angle of p about the centre gives one candidate per turn; the normal coordinate and
  // the radius are linear in t, so near an arc the nearest point is at (or next to) one of them.
  consider(hi);
  const motion::PlaneAxes ax = arc_->axes();
  const Vec3 c = event_.center;
  const double phi = std::atan2(p[ax.second] - c[ax.second], p[ax.first] - c[ax.first]);
  const double sign = arc_->clockwise() ? -1 : 1;
  double d = std::fmod(sign * (phi - arc_->startAngle()), kTwoPi);
  if (d < 0) d += kTwoPi;
  const double sweep = arc_->sweep();
  if (sweep <= 0) return best;
  // The polar angle is exact for circles; on a helix or spiral the nearest point lies a little
  // off it (the path is not perpendicular to the radius): two tangent steps from there.
  const bool refine = arc_->isSpiral() || arc_->rise() != 0;
  for (double a = d; a <= sweep + 1e-12; a += kTwoPi) {
    double t = std::min(a / sweep, 1.0);
    for (int i = 0; refine && i < 2; ++i) {
      const double r = arc_->startRadius() + (arc_->endRadius() - arc_->startRadius()) * t;
      const double dr = arc_->endRadius() - arc_->startRadius();
      const double speed = std::sqrt(sweep * sweep * r * r + dr * dr + arc_->rise() * arc_->rise());
      if (speed > 0) t = std::clamp(t + (p - point(t)).dot(arc_->tangent(t)) / speed, 0.0, 1.0);
    }
    consider(t);
  }
  if (d > kTwoPi - 1e-9) consider(0); // just before the start direction: the start itself
  return best;
}

std::vector<double> Piece::samples(double lo, double hi) const {
  if (!arc_) return {lo, hi};
  // 64 intervals per turn keep the sampling error of a sagitta under 0.12 % of it.
  const double sweep = arc_->sweep() * (hi - lo);
  int n = 2 * static_cast<int>(std::ceil(sweep / (kTwoPi / 64) / 2)) + 2;
  n = std::clamp(n, 4, 4096);
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) // n even: the middle is a sample
    out.push_back(lo + (hi - lo) * i / n);
  return out;
}

bool Piece::sameCarrier(const Piece& o, double tol) const {
  if (!arc_ && !o.arc_) return true; // lines: the distance to a line is convex along a line
  if (!arc_ || !o.arc_) return false;
  const motion::ArcGeometry &a = *arc_, &b = *o.arc_;
  if (event_.plane != o.event_.plane || a.clockwise() != b.clockwise() || a.isSpiral() ||
      b.isSpiral())
    return false;
  const motion::PlaneAxes ax = a.axes();
  const Vec3 d = event_.center - o.event_.center;
  if (std::abs(d[ax.first]) > tol || std::abs(d[ax.second]) > tol) return false;
  if (std::abs(a.startRadius() - b.startRadius()) > tol) return false;
  // a helix: the same rise per radian
  const double ra = a.rise() / a.sweep(), rb = b.rise() / b.sweep();
  return std::abs(ra - rb) * kTwoPi <= tol;
}

} // namespace gcx::equiv
