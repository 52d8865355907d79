// An SVG picture of the tool path (`gcx plot`): rapids dashed, feeds (lines and arcs) solid.
//
// Path elements: the drawing has exactly one <path> per *run*, and nothing else is a <path>
// (the legend uses <line> and <text>). A run is a maximal sequence of consecutive drawn moves
// of the same style, rapid (Rapid) or feed (Feed, Arc), in which each move starts where the
// previous one ended (within 1e-9 mm, in 3-D). Non-motion events (dwell, spindle, tool change,
// ...) are ignored and do not break a run; moves of zero length are not drawn and do not break
// a run either. So the count is the same in every view. Example:
//   G0 A→B, G0 B→C | G1 C→D, G2 D→E, G4, G1 E→F | G0 F→G | G1 H→I (H ≠ G)  →  4 paths.
// Coordinates are in mm; the SVG y axis is flipped so the vertical axis of the view points up.
// Behind the path (except in iso) a grid with a 1-2-5 step and a scale in mm, the axes through
// zero and their names (<line> and <text> only); the origin marker (<circle>, <line>, <text>)
// is drawn over it. The picture shows whatever frame its events are in: `gcx plot` hands it
// the work frame by default (motion/work_frame.h).
#pragma once
#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "motion/event.h"
#include "motion/svg_drawing.h"

namespace gcx::motion {

struct SvgOptions {
  View view = View::XY;
  std::string title = "gcx tool path"; // shown above the drawing with the view name
  double widthPx = 800;                // width attribute; height keeps the aspect ratio
  double relativeTolerance = 1e-3;     // arc chord tolerance, as a fraction of the path size
  double margin = 0.05;                // around the path, as a fraction of the drawing size
  bool grid = true;                    // grid, axes and scale (never in iso)
  /// Where the origin marker goes (in the events' frame), always inside the drawing; none if
  /// empty. The work frame's zero by default.
  std::optional<Vec3> origin = Vec3::Zero();
  std::string originLabel = "work zero";
};

class SvgPlotter : public Sink {
public:
  /// The SVG is written to out by finish().
  explicit SvgPlotter(std::ostream& out, SvgOptions opt = {});
  void event(const Event& e) override;
  void finish() override;

  void write(std::ostream& out) const;
  /// How many <path> elements write() produces (see the top of this file).
  std::size_t runCount() const { return runs_.size(); }

private:
  struct Run {
    bool rapid;
    std::size_t first; // index into moves_; the run ends where the next begins
  };
  std::ostream& out_;
  SvgOptions opt_;
  std::vector<Event> moves_; // geometry only, provenance dropped
  std::vector<Run> runs_;
};

} // namespace gcx::motion
