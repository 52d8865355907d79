// The HTML report of `gcx equiv --report OUT.html`: one self-contained page (inline CSS and
// script, no network, no external fonts) with the verdict and a summary table, both paths
// overlaid in one SVG (A and B in two colours, rapids dashed, a legend) with the divergence
// marked, zoom (mouse wheel) and pan (drag) and "fit" / "zoom to divergence" buttons (opening
// OUT.html#at-divergence starts zoomed there), and the two source excerpts side by side with the
// divergent line highlighted.
//
// The drawing is in the machine frame (the frame the comparison works in) and reuses the
// plotter's pieces (motion/svg_drawing.h). Stable hooks: the SVG is #plot, the paths are in
// <g id="path-a"> and <g id="path-b">, the marker is <g id="divergence">, the excerpts are
// #excerpt-a and #excerpt-b with the divergent line in class "hit". Every text that comes from
// a program or a file name is escaped.
#pragma once
#include <ostream>

#include "motion/svg_drawing.h"
#include "report/equiv_page.h"
#include "report/path_recorder.h"

namespace gcx::report {

/// Colours of side A, side B and the divergence marker (#rrggbb), for tests that look at the
/// rendered page.
inline constexpr const char* kSideAColour = "#1f5fbf";
inline constexpr const char* kSideBColour = "#e8730c";
inline constexpr const char* kMarkerColour = "#d0109c";

/// XZ (the lathe convention) when neither path leaves one Y plane — a turning program — else XY.
motion::View defaultView(const PathRecorder& a, const PathRecorder& b);

void writeEquivHtml(std::ostream& out, const EquivPage& page, const PathRecorder& a,
                    const PathRecorder& b, motion::View view = motion::View::XY);

} // namespace gcx::report
