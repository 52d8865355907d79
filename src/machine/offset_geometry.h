// Plane geometry of cutter radius compensation (docs/compensation.md): a programmed element
// (line or circular arc) in the coordinates of the selected plane, its offset by the tool
// radius, and the tool-centre points joining two offset elements at a corner.
#pragma once
#include <Eigen/Core>
#include <optional>
#include <vector>

namespace gcx::machine::comp {

using Vec2 = Eigen::Vector2d;

/// A line a→b, or an arc a→b about c (counter-clockwise when ccw), in plane coordinates.
struct Path2 {
  bool arc = false;
  Vec2 a = Vec2::Zero(), b = Vec2::Zero(), c = Vec2::Zero();
  bool ccw = true;
};

inline Vec2 leftOf(const Vec2& t) {
  return {-t.y(), t.x()};
}
inline double cross(const Vec2& u, const Vec2& v) {
  return u.x() * v.y() - u.y() * v.x();
}

/// Unit direction of travel at the start or the end (zero for a point).
Vec2 tangentAt(const Path2& p, bool atEnd);
/// The element shifted by d to the left of its travel (d < 0: right): a parallel line, or the
/// concentric arc; nullopt when the arc's radius would reach zero or below.
std::optional<Path2> offsetPath(const Path2& p, double d);
/// Intersections of the carriers (whole lines, whole circles) of two elements.
std::vector<Vec2> intersections(const Path2& x, const Path2& y);

/// How the corner between two elements is joined.
enum class Join {
  Normal,        // both compensated on the same side (inner: intersection; outer: the rule)
  StartUp,       // the first element is the start-up block from the uncompensated point
  Cancel,        // the second element is the cancel block to the uncompensated point
  Perpendicular, // a zero move lies between them: perpendicular vectors joined by a line
  Direction,     // the side changes: intersection, else perpendicular vectors
};

/// How an outer corner (the tool on the outside of the turn) is passed.
enum class OuterCorner {
  TypeC, // obtuse: intersection of the offsets; acute: extended vectors, three lines (nct.md)
  Arc,   // an arc of the tool radius about the corner (LinuxCNC, G39)
};

struct CornerResult {
  /// Tool-centre points from the first element's compensated end to the second element's
  /// compensated start, joined by straight lines (or one arc about the corner: `arcAbout`).
  std::vector<Vec2> points;
  bool arcAbout = false;       // points = {end of first, start of second}, an arc about the corner
  bool noIntersection = false; // an inner corner whose offsets do not meet (alarm)
  /// A direction change after an arc whose offsets do not meet: the arc itself runs from its
  /// compensated start to points.front() on its programmed radius about a shifted centre
  /// (shiftedCentre; 000:8083-8100).
  bool shiftedArc = false;
};

/// The corner at the end of `first` (= start of `second`). dFirst, dSecond: signed offsets
/// (left positive). `virtualDir`: the start-up's or cancel's I J K direction (nct.md §3.17.2-3).
CornerResult corner(const Path2& first, const Path2& second, double dFirst, double dSecond,
                    Join join, OuterCorner rule, const std::optional<Vec2>& virtualDir = {});

/// The centre of an arc of radius `radius` from `from` to `to` (a direction change after an
/// arc, 000:8083-8100): of the two, the one nearer the programmed centre `programmed` [I: the
/// figure is lost]; nullopt when the chord is longer than the diameter (the alarm's case).
std::optional<Vec2> shiftedCentre(const Vec2& from, const Vec2& to, double radius,
                                  const Vec2& programmed);

/// A chamfer or rounding between two elements meeting at a corner (nct.md §4.1): the first
/// element ends at `endFirst`, a line (or an arc about `centre`) joins `startSecond`.
struct Blend {
  Vec2 endFirst = Vec2::Zero(), startSecond = Vec2::Zero(), centre = Vec2::Zero();
  bool arc = false, ccw = true;
  bool fits = true; // false: the chamfer or rounding is too big for the elements
};
/// Chamfer: `c` from the corner on each element (on an arc, the chord from the corner).
Blend chamfer(const Path2& first, const Path2& second, double c);
/// Rounding: an arc of radius r tangent to both elements, on the inside of the turn.
Blend rounding(const Path2& first, const Path2& second, double r);

} // namespace gcx::machine::comp
