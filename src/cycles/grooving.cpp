// G74.7 face grooving / peck drilling and G75.7 grooving (cycles.md §4.12) [F]: pecks along one
// axis, columns stepped along the other, every level computed from A (§1.2 rule 3).
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "cycles/turning_cycles.h"

namespace gcx::cycles {

namespace {

constexpr double kTol = 1e-9;
constexpr long kMaxSteps = 100000; // more is a typing error (no hang)

double sign(double v) {
  return v < 0 ? -1 : 1;
}

/// Distance, direction and count of equal steps of at most `step` from a to b along one axis.
struct Run {
  double length = 0, dir = 1;
  long count = 0; // steps after the start (0: a single position)
  double at(double from, long k, double step) const {
    return from + dir * std::min(k * step, length);
  }
};

Run run(double a, double b, double step) {
  Run r;
  r.length = std::abs(b - a), r.dir = sign(b - a);
  const double n = r.length > kTol ? std::ceil(r.length / step - 1e-9) : 0;
  r.count = n > kMaxSteps ? kMaxSteps + 1 : static_cast<long>(n); // no overflow on tiny steps
  return r;
}

} // namespace

TurningOps expandGrooving(const TurningRequest& req, const TurningModal& m, const TurningWords& w,
                          diag::Engine& diags) {
  const bool face = w.cycle == TurningCycle::FaceGrooving; // G74.7 pecks along P1, G75.7 along P2
  const int peckAxis = face ? 0 : 1, stepAxis = 1 - peckAxis;
  const char peckWord = face ? 'Q' : 'P', stepWord = face ? 'P' : 'Q'; // Q = Δk, P = Δi
  if (!checkFeed(req.feed, w, false, diags)) return std::nullopt;
  TurningPath path(req.start, req.plane);
  const Vec2 a = path.start(), e = path.lathe(req.end);

  // The peck: Δk (G74.7) / Δi (G75.7); without it the column is cut in one feed [F].
  const auto peck = radiusWord(w, peckWord);
  if (peck && *peck <= 0) {
    paramError(w, peckWord, fmt::format("the peck {} must be > 0", peckWord), diags);
    return std::nullopt;
  }
  const Run pecks =
      run(a[peckAxis], e[peckAxis], peck.value_or(std::abs(e[peckAxis] - a[peckAxis])));
  const auto step = radiusWord(w, stepWord);
  Run columns = run(a[stepAxis], e[stepAxis], 1);
  if (columns.count > 0 && (!step || *step <= 0)) {
    paramError(w, stepWord, fmt::format("the step {} must be given and > 0", stepWord), diags);
    return std::nullopt;
  }
  if (columns.count > 0) columns = run(a[stepAxis], e[stepAxis], *step);
  if (pecks.count * std::max(columns.count, 1L) > kMaxSteps) {
    paramError(w, peckWord, "too many pecks: the peck or step is too small", diags);
    return std::nullopt;
  }
  // Relief Δd at the bottom: back against the step direction; without steps its sign
  // gives the direction (Fanuc) [F].
  const double relief =
      w['R'] ? (columns.count > 0 ? -columns.dir * std::abs(w['R']->value) : w['R']->value) : 0;
  const double peckLength = peck.value_or(pecks.length);
  for (long j = 0; j <= columns.count; ++j) {
    path.pass(static_cast<int>(j + 1));
    Vec2 p = path.at();
    p[stepAxis] = columns.at(a[stepAxis], j, step.value_or(0));
    path.rapid(p); // to the column, at the start level of the pecks
    for (long i = 1; i <= pecks.count; ++i) {
      p[peckAxis] = pecks.at(a[peckAxis], i, peckLength);
      path.feed(p, req.feed);
      if (i == pecks.count) break; // the last peck goes straight to the relief
      p[peckAxis] -= pecks.dir * m.grooveRetract;
      path.rapid(p);
    }
    p[stepAxis] += relief;
    path.rapid(p);
    p[peckAxis] = a[peckAxis];
    path.rapid(p);
  }
  path.rapid(a);
  return std::move(path.ops());
}

} // namespace gcx::cycles
