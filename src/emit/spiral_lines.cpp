#include "emit/spiral_lines.h"

#include <cmath>

#include "motion/interpolator.h"

namespace gcx::emit {

bool isSpiral(const motion::Event& arc) {
  const motion::ArcRadii r = motion::arcRadii(arc);
  return r.start != r.end && std::fabs(r.start - r.end) > 1e-9;
}

std::vector<LinePoint> spiralLines(const motion::Event& e, const motion::ArcGeometry& arc,
                                   double chord) {
  std::vector<motion::Vec3> pts;
  motion::appendArcPoints(arc, chord, pts);
  // Point i is at t = (i+1)/n; the extra axes move linearly in t like the height.
  const double n = static_cast<double>(pts.size());
  std::vector<LinePoint> lines;
  lines.reserve(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    lines.push_back(
        {pts[i], i + 1 == pts.size()
                     ? e.extraEnd
                     : motion::Extra(e.extraStart + (e.extraEnd - e.extraStart) * ((i + 1) / n))});
  return lines;
}

} // namespace gcx::emit
