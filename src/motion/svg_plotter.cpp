#include "motion/svg_plotter.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "motion/decimal.h"
#include "motion/geometry.h"
#include "motion/interpolator.h"
#include "motion/xml_text.h"

namespace gcx::motion {

namespace {
constexpr double kContinuity = 1e-9; // mm
constexpr const char* kFeedColour = "#1f5fbf";
constexpr const char* kRapidColour = "#d03030";
} // namespace

SvgPlotter::SvgPlotter(std::ostream& out, SvgOptions opt) : out_(out), opt_(std::move(opt)) {}

void SvgPlotter::event(const Event& e) {
  if (!isMotion(e) || pathLength(e) == 0) return;
  Event m;
  m.kind = e.kind;
  m.start = e.start;
  m.end = e.end;
  m.center = e.center;
  m.plane = e.plane;
  m.clockwise = e.clockwise;
  m.turns = e.turns;
  const bool rapid = e.kind == Kind::Rapid;
  if (runs_.empty() || runs_.back().rapid != rapid ||
      (e.start - moves_.back().end).norm() > kContinuity)
    runs_.push_back(Run{rapid, moves_.size()});
  moves_.push_back(std::move(m));
}

void SvgPlotter::finish() {
  write(out_);
  out_.flush();
}

void SvgPlotter::write(std::ostream& out) const {
  // The chord tolerance follows the 3-D size, so sampling does not depend on the view.
  Box3 box3;
  for (const Event& m : moves_)
    box3.extend(pathBounds(m));
  const double size3 = box3.isEmpty() ? 1.0 : std::max(box3.sizes().maxCoeff(), 1e-9);
  const double tol = opt_.relativeTolerance * size3;

  std::vector<Polyline> lines(runs_.size());
  Box2 box2;
  std::vector<Vec3> pts;
  for (std::size_t r = 0; r < runs_.size(); ++r) {
    const std::size_t end = r + 1 < runs_.size() ? runs_[r + 1].first : moves_.size();
    pts.assign(1, moves_[runs_[r].first].start);
    for (std::size_t i = runs_[r].first; i < end; ++i) {
      if (moves_[i].kind == Kind::Arc)
        appendArcPoints(ArcGeometry(moves_[i]), tol, pts);
      else
        pts.push_back(moves_[i].end);
    }
    lines[r].rapid = runs_[r].rapid;
    for (const Vec3& p : pts) {
      lines[r].points.push_back(project(opt_.view, p));
      box2.extend(lines[r].points.back());
    }
  }
  if (opt_.origin) box2.extend(project(opt_.view, *opt_.origin));

  const SvgCanvas c(opt_.view, box2, size3 * 1e-3, opt_.margin, 3.5, opt_.grid);
  auto num = [&c](double v) { return c.num(v); };
  const double size = c.size(), font = c.font();
  const double y0 = c.y0();
  const double feedWidth = size / 400, rapidWidth = size / 600;
  const std::string title = xmlEscape(opt_.title + " (" + viewName(opt_.view) + ")");

  std::string s;
  s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" "
                   "viewBox=\"{}\">\n",
                   num(opt_.widthPx), num(opt_.widthPx * c.height() / c.width()), c.viewBox());
  s += "<title>" + title + "</title>\n";
  s += c.grid();
  s += "<g fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
  s += c.paths(lines, PathStyle{"feed", kFeedColour, feedWidth},
               PathStyle{"rapid", kRapidColour, rapidWidth, size / 100, size / 150});
  s += "</g>\n";
  if (opt_.origin) s += c.originMarker(project(opt_.view, *opt_.origin), opt_.originLabel);

  // Legend: a sample stroke and a label for each style, under the title.
  // In the band above the drawing area.
  const double tx = c.areaLeft(), ty = y0 + 1.3 * font, ly = ty + 1.5 * font;
  s += fmt::format("<g font-family=\"sans-serif\" font-size=\"{}\" fill=\"#222\">\n", num(font));
  s += fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n", num(tx), num(ty), title);
  auto legend = [&](double x, const char* colour, double width, bool dashed, const char* label) {
    s += fmt::format(
        "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" "
        "stroke-width=\"{}\"{}/>\n",
        num(x), num(ly - font / 3), num(x + 2 * font), num(ly - font / 3), colour, num(width),
        dashed ? fmt::format(" stroke-dasharray=\"{} {}\"", num(font / 2), num(font / 3)) : "");
    s += fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n", num(x + 2.5 * font), num(ly), label);
  };
  legend(tx, kFeedColour, feedWidth, false, "feed");
  legend(tx + 6 * font, kRapidColour, rapidWidth, true, "rapid");
  s += "</g>\n</svg>\n";
  out.write(s.data(), static_cast<std::streamsize>(s.size()));
}

} // namespace gcx::motion
