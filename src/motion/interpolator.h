// Sampling arcs into polylines at a chord tolerance: no point of the arc is farther than the
// tolerance from the polyline. Lines are their own samples (error 0).
#pragma once
#include <cstddef>
#include <vector>

#include "motion/event.h"
#include "motion/geometry.h"

namespace gcx::motion {

/// Segments (of equal swept angle) needed for tolerance tol > 0. At least one per quarter turn,
/// so an arc looks like one even at a coarse tolerance; at most kMaxArcSegments.
std::size_t arcSegments(const ArcGeometry& arc, double tol);
inline constexpr std::size_t kMaxArcSegments = 10'000'000;
/// The chord tolerance (mm) at which canonical output writes spirals as lines.
inline constexpr double kDefaultChordTolerance = 1e-3;

/// Appends the arc's points at t = i/n for i = 1..n (the start is left out so consecutive moves
/// chain without duplicates; the last point is exactly the end).
void appendArcPoints(const ArcGeometry& arc, double tol, std::vector<Vec3>& out);

/// The sample points of one event, start and end included: {start, end} for Rapid and Feed,
/// the arc's polyline for Arc, nothing for non-motion events.
std::vector<Vec3> samplePoints(const Event& e, double tol);

/// An arc linearizer stage: every Arc becomes consecutive Feed events (same provenance, feed and
/// perRevolution) along its polyline, the extra axes interpolated linearly; all other events pass
/// through unchanged.
class ArcLinearizer : public Sink {
public:
  /// Throws std::invalid_argument unless tol > 0.
  ArcLinearizer(Sink& next, double tol);
  void event(const Event& e) override;
  void finish() override { next_.finish(); }

private:
  Sink& next_;
  double tol_;
  std::vector<Vec3> points_; // reused between arcs
};

} // namespace gcx::motion
