// G76.7 multiple threading (cycles.md §4.13) [F]: constant-area single-edge infeed.
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "cycles/turning_cycles.h"
#include "diag/codes.h"

namespace gcx::cycles {

namespace {

constexpr std::size_t kMaxPasses = 10000; // more is a typing error (no hang)

/// §4.13 infeed: D_n = max(Δd·√n, D_(n−1) + Δdmin); the first D_n >= k − d is clipped to
/// k − d; then m finishing passes at D = k. nullopt when there would be too many.
std::optional<std::vector<double>> threadDepths(double k, double first, const TurningModal& m) {
  std::vector<double> depths;
  const double rough = k - m.threadAllowance;
  for (int n = 1; rough > 0; ++n) {
    if (depths.size() >= kMaxPasses) return std::nullopt;
    const double prev = depths.empty() ? 0 : depths.back();
    const double d = std::max(first * std::sqrt(static_cast<double>(n)), prev + m.threadMinCut);
    depths.push_back(std::min(d, rough));
    if (d >= rough) break;
  }
  depths.insert(depths.end(), static_cast<std::size_t>(m.threadFinishPasses), k);
  return depths;
}

double sign(double v) {
  return v < 0 ? -1 : 1;
}

} // namespace

TurningOps expandThreading(const TurningRequest& req, const TurningModal& m, const TurningWords& w,
                           diag::Engine& diags) {
  const auto height = radiusWord(w, 'P'), first = radiusWord(w, 'Q');
  if (!height || *height <= 0) {
    paramError(w, 'P', "the thread height k must be given and > 0", diags);
    return std::nullopt;
  }
  if (!first || *first <= 0) {
    paramError(w, 'Q', "the first depth of cut Δd must be given and > 0", diags);
    return std::nullopt;
  }
  if (!checkFeed(req.feed, w, true, diags)) return std::nullopt;
  const auto depths = threadDepths(*height, *first, m);
  if (!depths) {
    paramError(w, 'Q', "too many passes: the first depth of cut is too small", diags);
    return std::nullopt;
  }
  TurningPath path(req.start, req.plane);
  const Vec2 a = path.start(), e = path.lathe(req.end);
  const double in = sign(e[1] - a[1]);    // infeed direction along P2 (OD: −)
  const double along = sign(e[0] - a[0]); // cut direction along P1
  const double flank = std::tan(m.threadAngle * std::numbers::pi / 360); // tan(a/2)
  const double lead = req.feed;
  // pull-out chamfer of r·L/10 at 45°, ending at Z, no longer than the thread
  const double chamfer = m.threadChamfer * lead / 10;
  int pass = 0;
  for (double depth : *depths) {
    path.pass(++pass);
    const double x = e[1] + in * (depth - *height);                // crest at X/2 + k (OD)
    const Vec2 start(a[0] + along * depth * flank, x + req.taper); // shifted along the flank
    path.rapid(start);
    const double length = std::abs(e[0] - start[0]);
    const double c = std::min(chamfer, length);
    if (c > 0) {
      const double t = (length - c) / length; // where the chamfer starts on the taper line
      path.thread({start[0] + along * (length - c), start[1] + t * (x - start[1])}, lead);
      path.thread({e[0], start[1] + t * (x - start[1]) - in * c}, lead);
    } else {
      path.thread({e[0], x}, lead);
    }
    path.rapid({e[0], a[1]}); // out to x_A
    path.rapid(a);            // back to z_A
  }
  return std::move(path.ops());
}

} // namespace gcx::cycles
