#include "motion/interpolator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gcx::motion {

namespace {
void checkTolerance(double tol) {
  if (!(tol > 0) || !std::isfinite(tol))
    throw std::invalid_argument("chord tolerance must be a positive number");
}
} // namespace

double arcChordCount(const ArcGeometry& arc, double tol) {
  checkTolerance(tol);
  // A chord over Δθ lies within Δθ²/8 · max|p''| of the curve (linear interpolation error,
  // which also bounds helices and spirals); for a circle this is just below the sagitta.
  double step = std::numbers::pi / 2;
  if (const double m = arc.maxSecondDerivative(); m > 0)
    step = std::min(step, std::sqrt(8 * tol / m));
  return std::max(1.0, std::ceil(arc.sweep() / step));
}

std::size_t arcSegments(const ArcGeometry& arc, double tol) {
  return static_cast<std::size_t>(
      std::min(arcChordCount(arc, tol), static_cast<double>(kMaxArcSegments)));
}

void appendArcPoints(const ArcGeometry& arc, double tol, std::vector<Vec3>& out) {
  const std::size_t n = arcSegments(arc, tol);
  out.reserve(out.size() + n);
  for (std::size_t i = 1; i <= n; ++i)
    out.push_back(arc.point(static_cast<double>(i) / n));
}

std::vector<Vec3> samplePoints(const Event& e, double tol) {
  switch (e.kind) {
  case Kind::Rapid:
  case Kind::Feed:
    return {e.start, e.end};
  case Kind::Arc: {
    std::vector<Vec3> pts{e.start};
    appendArcPoints(ArcGeometry(e), tol, pts);
    return pts;
  }
  default: // every other kind moves nothing (isMotion)
    break;
  }
  return {};
}

ArcLinearizer::ArcLinearizer(Sink& next, double tol) : next_(next), tol_(tol) {
  checkTolerance(tol);
}

void ArcLinearizer::event(const Event& e) {
  if (e.kind != Kind::Arc) {
    next_.event(e);
    return;
  }
  points_.clear();
  appendArcPoints(ArcGeometry(e), tol_, points_);
  Event piece;
  piece.kind = Kind::Feed;
  piece.from = e.from;
  piece.feed = e.feed;
  piece.perRevolution = e.perRevolution;
  piece.start = e.start;
  piece.extraStart = e.extraStart;
  // Point i is at t = (i+1)/n; the extra axes move linearly in t like the helix height.
  const double n = static_cast<double>(points_.size());
  for (std::size_t i = 0; i < points_.size(); ++i) {
    piece.end = points_[i];
    piece.extraEnd = i + 1 == points_.size()
                         ? e.extraEnd
                         : Extra(e.extraStart + (e.extraEnd - e.extraStart) * ((i + 1) / n));
    next_.event(piece);
    piece.start = piece.end;
    piece.extraStart = piece.extraEnd;
  }
}

} // namespace gcx::motion
