// One side's motion as geometric pieces for the equivalence walk: a straight line or an
// arc/helix/spiral (motion/geometry.h), parametrised by t in [0, 1], with the machine state
// that holds while it moves (feed, spindle, coolant, tool). Rapids merged into a run keep
// only their end points (docs/equivalence.md).
#pragma once
#include <optional>
#include <vector>

#include "motion/event.h"
#include "motion/geometry.h"

namespace gcx::equiv {

using motion::Vec3;

/// The state attached to a motion segment. Spindle speed counts only while it turns.
struct MotionState {
  bool rapid = false;
  double feed = 0; // mm/min or mm/rev (feeds only)
  bool perRevolution = false;
  double lead = 0; // spindle-synchronised feed (thread, rigid tap)
  double spindleSpeed = 0;
  int spindleDirection = 0; // +1 CW, -1 CCW, 0 stopped
  bool mist = false, flood = false;
  int tool = 0;
  // where the spindle and coolant state was last set (reports only, never compared)
  SourceLoc spindleSetAt, coolantSetAt;
};

class Piece {
public:
  /// A straight Rapid/Feed or an Arc event.
  Piece(const motion::Event& e, const MotionState& state);
  /// A run of rapids compared by its end points only: from `first`'s start to `last`'s end.
  static Piece rapidRun(const motion::Event& first, const motion::Event& last,
                        const MotionState& state);

  const motion::Event& event() const { return event_; } // the last event of a rapid run
  /// The first event of a rapid run (the piece's event otherwise): where its state starts.
  const motion::Event& firstEvent() const { return run_ ? first_ : event_; }
  const MotionState& state() const { return state_; }
  bool isArc() const { return arc_.has_value(); }
  bool isRapidRun() const { return run_; }
  const Vec3& start() const { return start_; }
  const Vec3& end() const { return end_; }
  /// Length in axis space: the XYZ path (mm) and the extra axes' travel together, so a move of
  /// the extra axes alone has a length (docs/equivalence.md, "Extra axes").
  double length() const { return lengthFrom(0); }
  /// Axis-space length from t to the end (a spiral's length is not linear in t).
  double lengthFrom(double t) const;

  Vec3 point(double t) const;
  /// The extra axes (A B C U V W) at t: linear along the piece.
  motion::Extra extra(double t) const;
  /// The parameter in [lo, hi] of the point nearest to p. Where several are within `tol` of p
  /// (a full circle's start and end, a helix's turns), the one closest to `hint`.
  /// A line measures the distance in axis space when `px` (the extra axes at p) is given.
  double nearest(const Vec3& p, double lo, double hi, double hint, double tol,
                 const motion::Extra* px = nullptr) const;
  /// Points of the sub-piece [lo, hi] that bound its distance to another piece: the ends for a
  /// line, enough points for an arc that the largest deviation from a line or another circle is
  /// seen to well within the tolerance (always including the middle).
  std::vector<double> samples(double lo, double hi) const;
  /// Whether both pieces lie on one circle (or line): then the end points decide.
  bool sameCarrier(const Piece& o, double tol) const;

private:
  double pathLengthFrom(double t) const; // XYZ only

  motion::Event event_;
  motion::Event first_; // rapid runs only
  MotionState state_;
  std::optional<motion::ArcGeometry> arc_;
  Vec3 start_, end_;
  motion::Extra extraStart_, extraEnd_;
  double length_ = 0;      // XYZ path
  double extraLength_ = 0; // travel of the extra axes
  bool run_ = false;
};

} // namespace gcx::equiv
