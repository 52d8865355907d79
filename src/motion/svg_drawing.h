// Drawing pieces shared by every SVG picture of a tool path (`gcx plot`, the equivalence
// report): the view projection, the layout of one picture in millimetres, the grid with its
// scale, the origin marker and the <path> elements of runs. One copy of each, so a plot and a
// report draw the same path the same way.
//
// Layout in SVG user units (mm): the drawing area is the path's box plus a margin; the grid
// covers it, the tick labels sit left of and below it, a band above it holds the title and
// legend. The SVG y axis points down, so a view point (u, v) is drawn at (u, −v).
#pragma once
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "motion/event.h"

namespace gcx::motion {

using Vec2 = Eigen::Vector2d;
using Box2 = Eigen::AlignedBox2d;

/// xy, xz, yz: plan and elevations; xz follows the lathe convention (Z right, X up). iso:
/// isometric view from (+1, −1, +1): X runs right-down, Y right-up, Z up.
enum class View { XY, XZ, YZ, Iso };
/// "xy", "xz", "yz", "iso" (case-sensitive); nullopt otherwise.
std::optional<View> parseView(std::string_view name);
const char* viewName(View v);

/// The point as the view shows it: (right, up).
Vec2 project(View v, const Vec3& p);
/// Names of the axes pointing right and up in the view ("Z", "X" for xz); empty for iso.
std::string rightAxisName(View v);
std::string upAxisName(View v);

/// A run: a connected polyline drawn in one style.
struct Polyline {
  bool rapid = false;
  std::vector<Vec2> points; // view coordinates
};

struct PathStyle {
  const char* cls;    // class attribute
  const char* colour; // stroke
  double width;       // stroke width: mm, or screen pixels when screenWidth
  double dash = 0;    // dash and gap lengths (same unit as width); 0: solid
  double gap = 0;
  bool screenWidth = false; // vector-effect="non-scaling-stroke": the width stays in pixels
};

/// The number of decimals, sizes and grid of one picture of the region `box` (view units).
class SvgCanvas {
public:
  /// minSize: the smallest size (mm) the picture assumes, for a box of zero size; margin:
  /// around the box as a fraction of its size; bandFonts: the height of the band above the
  /// drawing, in font sizes; grid: whether to draw the grid and scale (never in iso).
  SvgCanvas(View view, const Box2& box, double minSize, double margin, double bandFonts, bool grid);

  std::string num(double v) const;
  double size() const { return size_; }
  double font() const { return font_; }
  double margin() const { return margin_; }
  /// The whole picture: x y w h of the viewBox.
  double x0() const { return x0_; }
  double y0() const { return y0_; }
  double width() const { return w_; }
  double height() const { return h_; }
  std::string viewBox() const;
  /// Left and top edges of the drawing area (where the title band ends), SVG coordinates.
  double areaLeft() const { return area_.min().x(); }
  double areaTop() const { return -area_.max().y(); }
  /// Distance between grid lines: 1, 2 or 5 times a power of ten (mm); 0 without a grid.
  double gridStep() const { return step_; }

  /// <g class="grid">: grid lines, the axes through zero, tick labels and axis names.
  std::string grid() const;
  /// <g class="origin">: a circled cross at `at` (view coordinates) with a label.
  std::string originMarker(const Vec2& at, const std::string& label) const;
  /// One <path> per run, in order (see svg_plotter.h for what a run is).
  std::string paths(const std::vector<Polyline>& runs, const PathStyle& feed,
                    const PathStyle& rapid) const;

private:
  View view_;
  Box2 area_; // the drawing area in view coordinates
  double size_, margin_, font_, step_ = 0;
  int decimals_;
  double x0_, y0_, w_, h_;
  std::string tickLabel(double v) const;
};

} // namespace gcx::motion
