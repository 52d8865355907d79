#include "report/path_recorder.h"

#include <algorithm>

#include "motion/interpolator.h"

namespace gcx::report {

using motion::Vec3;

namespace {
constexpr double kContinuity = 1e-9;   // mm, as in the plotter
constexpr double kStraight = 1e-7;     // mm: a middle point this close to the chord is dropped
constexpr double kArcTolerance = 1e-3; // chord error, as a fraction of the arc's radius

PathRecorder::Pen combine(PathRecorder::Pen a, PathRecorder::Pen b) {
  return std::min(a, b) == PathRecorder::Pen::Up ? PathRecorder::Pen::Up : std::max(a, b);
}

// Whether b lies on the segment a→c (going on in the same direction).
bool between(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, bc = c - b, ac = c - a;
  const double len = ac.norm();
  return len > 0 && ab.dot(bc) > 0 && ab.cross(ac).norm() / len <= kStraight;
}
} // namespace

PathRecorder::PathRecorder(std::size_t maxVertices) : max_(std::max<std::size_t>(maxVertices, 4)) {}

void PathRecorder::event(const motion::Event& e) {
  if (!motion::isMotion(e) || motion::pathLength(e) == 0) return;
  bounds_.extend(motion::pathBounds(e));
  if (v_.empty() || (e.start - v_.back().p).norm() > kContinuity) add(e.start, Pen::Up);
  if (e.kind != motion::Kind::Arc) {
    add(e.end, e.kind == motion::Kind::Rapid ? Pen::Rapid : Pen::Feed);
    return;
  }
  const motion::ArcGeometry arc(e);
  const double r = std::max(arc.startRadius(), arc.endRadius());
  scratch_.clear();
  motion::appendArcPoints(arc, std::max(kArcTolerance * r, 1e-6), scratch_);
  for (const Vec3& p : scratch_)
    add(p, Pen::Feed);
}

void PathRecorder::add(const Vec3& p, Pen pen) {
  const std::size_t n = v_.size();
  if (pen != Pen::Up && n >= 2 && v_[n - 1].pen == pen && folded_ == stride_ &&
      between(v_[n - 2].p, v_[n - 1].p, p)) {
    v_.back().p = p; // extends a straight piece
    return;
  }
  if (folded_ < stride_ && n > 1) {
    v_.back() = Vertex{p, combine(v_.back().pen, pen)};
    ++folded_;
  } else {
    v_.push_back(Vertex{p, pen});
    folded_ = 1;
  }
  if (v_.size() > max_) compact();
}

void PathRecorder::compact() {
  // Keep vertex 0, then the second of each pair (1,2), (3,4), ...; a lone last one stays.
  std::size_t out = 1;
  for (std::size_t i = 1; i < v_.size(); i += 2) {
    if (i + 1 < v_.size())
      v_[out++] = Vertex{v_[i + 1].p, combine(v_[i].pen, v_[i + 1].pen)};
    else
      v_[out++] = v_[i];
  }
  v_.resize(out);
  stride_ *= 2;
  folded_ = stride_; // the last vertex is complete: the next input starts a new one
}

std::vector<motion::Polyline> PathRecorder::polylines(motion::View view) const {
  std::vector<motion::Polyline> runs;
  for (std::size_t i = 1; i < v_.size(); ++i) {
    if (v_[i].pen == Pen::Up) continue;
    const bool rapid = v_[i].pen == Pen::Rapid;
    if (v_[i - 1].pen == Pen::Up || runs.empty() || runs.back().rapid != rapid) {
      runs.push_back(motion::Polyline{rapid, {}});
      runs.back().points.push_back(motion::project(view, v_[i - 1].p));
    }
    runs.back().points.push_back(motion::project(view, v_[i].p));
  }
  return runs;
}

} // namespace gcx::report
