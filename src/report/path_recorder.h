// One side's tool path kept for drawing (the equivalence report), in memory bounded whatever the
// program's length: a polyline of at most `maxVertices` vertices in the machine frame.
//
// Each vertex remembers how the path arrives at it: by a rapid, by a feed (lines and sampled
// arcs), or not at all (the path starts there: the first point, or a jump). Straight pieces of
// one style are merged as they come (a line cut into collinear pieces takes one vertex). When
// the polyline outgrows its cap, every second vertex is dropped and from then on only every
// second incoming vertex is kept (and so on, doubling): the drawing coarsens evenly along the
// path, its first and last points stay exact, and a merged piece counts as a feed if any part
// of it was one (a cut matters more than a traverse), as a jump if any part was.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "motion/event.h"
#include "motion/geometry.h"
#include "motion/svg_drawing.h"

namespace gcx::report {

class PathRecorder : public motion::Sink {
public:
  enum class Pen : std::uint8_t { Up, Rapid, Feed }; // how the path arrives at a vertex
  struct Vertex {
    motion::Vec3 p;
    Pen pen;
  };

  explicit PathRecorder(std::size_t maxVertices = 200'000);
  void event(const motion::Event& e) override;

  const std::vector<Vertex>& vertices() const { return v_; }
  /// Exact bounds of every move (arcs included), in the machine frame; empty before any.
  const motion::Box3& bounds() const { return bounds_; }
  /// How many input vertices one stored vertex stands for now (1 until the cap is reached).
  std::size_t stride() const { return stride_; }
  /// The runs of the path in a view, for motion::SvgCanvas::paths.
  std::vector<motion::Polyline> polylines(motion::View view) const;

private:
  void add(const motion::Vec3& p, Pen pen);
  void compact();

  std::size_t max_;
  std::vector<Vertex> v_;
  std::size_t stride_ = 1, folded_ = 0; // inputs folded into the last vertex
  motion::Box3 bounds_;
  std::vector<motion::Vec3> scratch_;
};

} // namespace gcx::report
