#include "motion/svg_drawing.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "motion/decimal.h"
#include "motion/xml_text.h"

namespace gcx::motion {

namespace {
constexpr const char* kGridColour = "#e2e2e2";
constexpr const char* kAxisColour = "#9a9a9a";
constexpr const char* kScaleColour = "#555";
constexpr const char* kOriginColour = "#2a8a2a";
constexpr double kLabelCharWidth = 0.6; // of the font size, for sans-serif digits

/// The smallest of 1, 2, 5 times a power of ten that is at least `raw`.
double niceStep(double raw) {
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw * (1 - 1e-9)) return m * p;
  return 10 * p;
}

/// The grid positions k·step inside [lo, hi].
std::vector<double> ticks(double lo, double hi, double step) {
  std::vector<double> out;
  for (double k = std::ceil(lo / step - 1e-9); k <= std::floor(hi / step + 1e-9); ++k)
    out.push_back(k * step);
  return out;
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

Vec2 project(View v, const Vec3& p) {
  switch (v) {
  case View::XY:
    return {p.x(), p.y()};
  case View::XZ: // lathe convention: the spindle axis Z horizontal, X up
    return {p.z(), p.x()};
  case View::YZ:
    return {p.y(), p.z()};
  case View::Iso: // screen right = (1,1,0)/√2, screen up = (−1,1,2)/√6
    return {(p.x() + p.y()) / std::sqrt(2.0), (-p.x() + p.y() + 2 * p.z()) / std::sqrt(6.0)};
  }
  return {p.x(), p.y()};
}

std::string rightAxisName(View v) {
  return v == View::XY ? "X" : v == View::XZ ? "Z" : v == View::YZ ? "Y" : "";
}
std::string upAxisName(View v) {
  return v == View::XY ? "Y" : v == View::XZ ? "X" : v == View::YZ ? "Z" : "";
}

SvgCanvas::SvgCanvas(View view, const Box2& box, double minSize, double margin, double bandFonts,
                     bool grid)
    : view_(view) {
  Box2 b = box;
  if (b.isEmpty()) b.extend(Vec2(0, 0));
  size_ = std::max(b.sizes().maxCoeff(), minSize);
  decimals_ = std::clamp(5 - static_cast<int>(std::floor(std::log10(size_))), 3, 12);
  margin_ = margin * size_;
  font_ = size_ / 40;
  area_ = Box2(b.min() - Vec2(margin_, margin_), b.max() + Vec2(margin_, margin_));
  double left = 0, bottom = 0, right = 0;
  if (grid && view != View::Iso) {
    step_ = niceStep(size_ / 10);
    std::size_t chars = 1;
    for (double v : ticks(area_.min().y(), area_.max().y(), step_))
      chars = std::max(chars, tickLabel(v).size());
    left = (kLabelCharWidth * static_cast<double>(chars) + 2) * font_; // labels + axis name
    bottom = 2.8 * font_;                                              // labels + axis name
    right = 1.5 * font_;                                               // half of the last label
  }
  const double band = bandFonts * font_;
  x0_ = area_.min().x() - left;
  y0_ = -area_.max().y() - band;
  w_ = area_.sizes().x() + left + right;
  h_ = area_.sizes().y() + band + bottom;
}

std::string SvgCanvas::num(double v) const {
  return formatDecimal(v, decimals_);
}

std::string SvgCanvas::viewBox() const {
  return fmt::format("{} {} {} {}", num(x0_), num(y0_), num(w_), num(h_));
}

std::string SvgCanvas::tickLabel(double v) const {
  const int d = std::max(0, -static_cast<int>(std::floor(std::log10(step_) + 1e-9)));
  if (std::abs(v) < step_ * 1e-6) v = 0;
  return fmt::format("{:.{}f}", v, d);
}

std::string SvgCanvas::grid() const {
  if (step_ == 0) return {};
  const double left = area_.min().x(), right = area_.max().x();
  const double top = -area_.max().y(), bottom = -area_.min().y();
  const auto xs = ticks(left, right, step_);
  const auto ys = ticks(area_.min().y(), area_.max().y(), step_);
  std::string s = fmt::format("<g class=\"grid\" stroke=\"{}\" stroke-width=\"{}\">\n", kGridColour,
                              num(size_ / 1000));
  auto line = [&](double x1, double y1, double x2, double y2) {
    s += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>\n", num(x1), num(y1), num(x2),
                     num(y2));
  };
  for (double x : xs)
    line(x, top, x, bottom);
  for (double y : ys)
    line(left, -y, right, -y);
  s += "</g>\n";
  // The axes through the origin, where the drawing area contains it.
  s += fmt::format("<g class=\"axes\" stroke=\"{}\" stroke-width=\"{}\">\n", kAxisColour,
                   num(size_ / 500));
  if (left <= 0 && 0 <= right) line(0, top, 0, bottom);
  if (top <= 0 && 0 <= bottom) line(left, 0, right, 0);
  s += "</g>\n";
  s += fmt::format("<g class=\"scale\" font-family=\"sans-serif\" font-size=\"{}\" fill=\"{}\">\n",
                   num(font_), kScaleColour);
  for (double x : xs)
    s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", num(x),
                     num(bottom + 1.1 * font_), tickLabel(x));
  for (double y : ys)
    s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>\n",
                     num(left - 0.4 * font_), num(-y + 0.35 * font_), tickLabel(y));
  // Axis names: the right axis under its labels, the up axis turned, left of its labels.
  const std::string unit = view_ == View::XZ ? " (mm, radius)" : " (mm)";
  s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{} (mm)</text>\n",
                   num((left + right) / 2), num(bottom + 2.4 * font_), rightAxisName(view_));
  const double ux = x0_ + font_, uy = (top + bottom) / 2;
  s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" "
                   "transform=\"rotate(-90 {} {})\">{}{}</text>\n",
                   num(ux), num(uy), num(ux), num(uy), upAxisName(view_), unit);
  s += "</g>\n";
  return s;
}

std::string SvgCanvas::originMarker(const Vec2& at, const std::string& label) const {
  const double r = 0.5 * font_, x = at.x(), y = -at.y();
  std::string s = fmt::format("<g class=\"origin\" stroke=\"{}\" stroke-width=\"{}\" "
                              "fill=\"none\">\n",
                              kOriginColour, num(size_ / 500));
  s += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\"/>\n", num(x), num(y), num(r));
  s += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>\n", num(x - 2 * r), num(y),
                   num(x + 2 * r), num(y));
  s += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>\n", num(x), num(y - 2 * r),
                   num(x), num(y + 2 * r));
  s += fmt::format("<text x=\"{}\" y=\"{}\" font-family=\"sans-serif\" font-size=\"{}\" "
                   "fill=\"{}\" stroke=\"none\">{}</text>\n",
                   num(x + 1.2 * r), num(y - 1.2 * r), num(0.8 * font_), kOriginColour,
                   xmlEscape(label));
  s += "</g>\n";
  return s;
}

std::string SvgCanvas::paths(const std::vector<Polyline>& runs, const PathStyle& feed,
                             const PathStyle& rapid) const {
  std::string s;
  for (const Polyline& run : runs) {
    const PathStyle& st = run.rapid ? rapid : feed;
    s += fmt::format("<path class=\"{}\" stroke=\"{}\" stroke-width=\"{}\"", st.cls, st.colour,
                     num(st.width));
    if (st.dash > 0) s += fmt::format(" stroke-dasharray=\"{} {}\"", num(st.dash), num(st.gap));
    if (st.screenWidth) s += " vector-effect=\"non-scaling-stroke\"";
    s += " d=\"";
    for (std::size_t i = 0; i < run.points.size(); ++i) {
      s += i == 0 ? "M" : i == 1 ? "L" : " ";
      s += num(run.points[i].x()) + ' ' + num(-run.points[i].y());
    }
    s += "\"/>\n";
  }
  return s;
}

} // namespace gcx::motion
