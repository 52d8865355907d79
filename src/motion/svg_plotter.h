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
#pragma once
#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "motion/event.h"

namespace gcx::motion {

/// xy, xz, yz: plan and elevations (first axis right, second up). iso: isometric view from
/// (+1, −1, +1): X runs right-down, Y right-up, Z up.
enum class View { XY, XZ, YZ, Iso };
/// "xy", "xz", "yz", "iso" (case-sensitive); nullopt otherwise.
std::optional<View> parseView(std::string_view name);
const char* viewName(View v);

struct SvgOptions {
  View view = View::XY;
  std::string title = "gcx tool path"; // shown above the drawing with the view name
  double widthPx = 800;                // width attribute; height keeps the aspect ratio
  double relativeTolerance = 1e-3;     // arc chord tolerance, as a fraction of the path size
  double margin = 0.05;                // around the path, as a fraction of the drawing size
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
