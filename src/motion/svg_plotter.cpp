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

using Vec2 = Eigen::Vector2d;

Vec2 project(View v, const Vec3& p) {
  switch (v) {
  case View::XY:
    return {p.x(), p.y()};
  case View::XZ:
    return {p.x(), p.z()};
  case View::YZ:
    return {p.y(), p.z()};
  case View::Iso: // screen right = (1,1,0)/√2, screen up = (−1,1,2)/√6
    return {(p.x() + p.y()) / std::sqrt(2.0), (-p.x() + p.y() + 2 * p.z()) / std::sqrt(6.0)};
  }
  return {p.x(), p.y()};
}
} // namespace

std::optional<View> parseView(std::string_view name) {
  if (name == "xy") return View::XY;
  if (name == "xz") return View::XZ;
  if (name == "yz") return View::YZ;
  if (name == "iso") return View::Iso;
  return std::nullopt;
}

const char* viewName(View v) {
  switch (v) {
  case View::XY:
    return "XY";
  case View::XZ:
    return "XZ";
  case View::YZ:
    return "YZ";
  case View::Iso:
    return "isometric";
  }
  return "XY";
}

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

  std::vector<std::vector<Vec2>> lines(runs_.size());
  Eigen::AlignedBox2d box2;
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
    for (const Vec3& p : pts) {
      lines[r].push_back(project(opt_.view, p));
      box2.extend(lines[r].back());
    }
  }
  if (box2.isEmpty()) box2.extend(Vec2(0, 0));

  const double size = std::max(box2.sizes().maxCoeff(), size3 * 1e-3);
  const int dec = std::clamp(5 - static_cast<int>(std::floor(std::log10(size))), 3, 12);
  auto num = [dec](double v) { return formatDecimal(v, dec); };
  const double margin = opt_.margin * size;
  const double font = size / 40;
  const double band = 3.5 * font; // title and legend above the drawing
  // y is flipped: a view point (u, v) is drawn at (u, −v).
  const double x0 = box2.min().x() - margin, y0 = -box2.max().y() - margin - band;
  const double w = box2.sizes().x() + 2 * margin, h = box2.sizes().y() + 2 * margin + band;
  const double feedWidth = size / 400, rapidWidth = size / 600;
  const std::string title = xmlEscape(opt_.title + " (" + viewName(opt_.view) + ")");

  std::string s;
  s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" "
                   "viewBox=\"{} {} {} {}\">\n",
                   num(opt_.widthPx), num(opt_.widthPx * h / w), num(x0), num(y0), num(w), num(h));
  s += "<title>" + title + "</title>\n";
  s += "<g fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
  for (std::size_t r = 0; r < runs_.size(); ++r) {
    const bool rapid = runs_[r].rapid;
    s += rapid ? fmt::format("<path class=\"rapid\" stroke=\"{}\" stroke-width=\"{}\" "
                             "stroke-dasharray=\"{} {}\" d=\"",
                             kRapidColour, num(rapidWidth), num(size / 100), num(size / 150))
               : fmt::format("<path class=\"feed\" stroke=\"{}\" stroke-width=\"{}\" d=\"",
                             kFeedColour, num(feedWidth));
    for (std::size_t i = 0; i < lines[r].size(); ++i) {
      s += i == 0 ? "M" : i == 1 ? "L" : " ";
      s += num(lines[r][i].x()) + ' ' + num(-lines[r][i].y());
    }
    s += "\"/>\n";
  }
  s += "</g>\n";

  // Legend: a sample stroke and a label for each style, under the title.
  const double tx = x0 + margin, ty = y0 + margin + font, ly = ty + 1.5 * font;
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
