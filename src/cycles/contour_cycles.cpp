// The internal contour cycles (contour_cycles.h): roughing by levels that leave along the
// contour, approach passes, the finishing pass.
#include "cycles/contour_cycles.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"

namespace gcx::cycles {

namespace {

constexpr double kTol = 1e-6;
constexpr long kMaxPasses = 100000; // more is a typing error, not a part (no hang)

double sign(double v) {
  return v < 0 ? -1.0 : 1.0;
}

const char* axisName(int axis) {
  return axis == 0 ? "Z (P1)" : "X (P2)";
}

/// The contour must be monotonic along the cut axis (the manual's one condition; it may turn
/// back along the level axis: closed zones), block by block: an arc may bulge between its end
/// points, as the manual's own examples do (example 23's N122 by 0.12 mm) [D]. Returns the
/// cut direction.
std::optional<double> checkCut(const Profile& c, int cut, const std::string& label,
                               diag::Engine& diags) {
  double cutSign = 0;
  for (const ProfileSegment& seg : c.segments) {
    const Vec2 d = seg.to - seg.from;
    if (cutSign != 0 && std::abs(d[cut]) > kTol && sign(d[cut]) != cutSign) {
      diags.error(diag::code::CycleNonMonotonic, seg.range,
                  fmt::format("{}: the contour must be monotonic along {}; this block turns back "
                              "(wl4.md §5.6)",
                              label, axisName(cut)));
      return std::nullopt;
    }
    if (cutSign == 0 && std::abs(d[cut]) > kTol) cutSign = sign(d[cut]);
  }
  if (cutSign == 0) {
    diags.error(diag::code::CycleContourDegenerate, c.ns,
                fmt::format("{}: the contour has no length along {}: nothing to rough", label,
                            axisName(cut)));
    return std::nullopt;
  }
  return cutSign;
}

/// One level of a level cycle: along the cut axis from A's cut coordinate, the stretches where
/// the line lies outside the part (the contour at least as deep, s toward the part).
class Level {
public:
  Level(const Profile& c, int level, double s, double cutSign, double v)
      : c_(c), level_(level), cut_(1 - level), s_(s), cutSign_(cutSign), v_(v) {}

  /// [from, to] stretches ahead of `start` along the cut direction, in order.
  std::vector<std::pair<double, double>> stretches(double start) const {
    const double end = c_.segments.back().to[cut_];
    std::vector<double> at{start};
    for (double x : crossingsAt(c_, level_, v_))
      if (ahead(start, x) && ahead(x, end)) at.push_back(x);
    if (ahead(start, end)) at.push_back(end);
    std::sort(at.begin(), at.end(), [&](double a, double b) { return cutSign_ * (b - a) > 0; });
    std::vector<std::pair<double, double>> out;
    for (std::size_t i = 0; i + 1 < at.size(); ++i) { // touching stretches are one (one G1)
      if (!ahead(at[i], at[i + 1]) || !outside((at[i] + at[i + 1]) / 2)) continue;
      if (!out.empty() && std::abs(out.back().second - at[i]) < kTol)
        out.back().second = at[i + 1];
      else
        out.emplace_back(at[i], at[i + 1]);
    }
    return out;
  }

private:
  bool ahead(double from, double x) const { return cutSign_ * (x - from) > kTol; }
  /// The line at cut coordinate x is outside the part: the contour there is at least as deep;
  /// before the contour's start P', as deep as P' (levels below it are not reached from A).
  bool outside(double x) const {
    if (cutSign_ * (x - c_.aPrime[cut_]) < 0) return s_ * (c_.aPrime[level_] - v_) >= -kTol;
    for (double depth : crossingsAt(c_, cut_, x))
      if (s_ * (depth - v_) >= -kTol) return true;
    return false;
  }

  const Profile& c_;
  int level_, cut_;
  double s_, cutSign_, v_;
};

/// The levels: A + s·E·k, P's own level and the contour's extreme toward s, in order.
std::vector<double> levelValues(double a, double s, double e, double start, double limit) {
  std::vector<double> out;
  for (long k = 1;; ++k) {
    const double v = a + s * e * static_cast<double>(k); // never accumulated (§1.2 rule 3)
    if (s * (v - limit) >= -1e-9) break;
    out.push_back(v);
  }
  out.push_back(start);
  out.push_back(limit);
  std::sort(out.begin(), out.end(), [&](double x, double y) { return s * (x - y) < 0; });
  out.erase(std::unique(out.begin(), out.end(),
                        [](double x, double y) { return std::abs(x - y) < 1e-9; }),
            out.end());
  return out;
}

bool levels(const ContourCycleRequest& req, TurningPath& path, diag::Engine& diags) {
  const Profile& c = req.contours.front();
  const int level = req.cycle == ContourCycle::Longitudinal ? 1 : 0, cut = 1 - level;
  const Vec2 a = path.start();
  if (std::abs(c.aPrime[level] - a[level]) < kTol) {
    diags.error(diag::code::CycleParam, req.block,
                fmt::format("{}: the start point A lies level with the contour's start along "
                            "{}: A -> P gives the infeed direction (wl4.md §5.6)",
                            req.label, axisName(level)));
    return false;
  }
  const double s = sign(c.aPrime[level] - a[level]);
  const auto cutSign = checkCut(req.programmed, cut, req.label, diags);
  if (!cutSign) return false;
  const double e = *req.depth, limit = extremeAlong(c, level, s);
  if (std::abs(limit - a[level]) / e > kMaxPasses) {
    diags.error(diag::code::CycleParam, req.depthWord,
                fmt::format("{}: more than {} passes: the depth of cut E is too small", req.label,
                            kMaxPasses));
    return false;
  }
  auto point = [&](double l, double x) {
    Vec2 p;
    p[level] = l, p[cut] = x;
    return p;
  };
  double previous = a[level];
  int pass = 0;
  for (double v : levelValues(a[level], s, e, c.aPrime[level], limit)) {
    for (const auto& [from, to] : Level(c, level, s, *cutSign, v).stretches(a[cut])) {
      path.pass(++pass);
      if (std::abs(from - a[cut]) < kTol) { // the open stretch from A: in, along, out (§5.6)
        if (std::abs(path.at()[cut] - a[cut]) > kTol) path.rapid(point(path.at()[level], a[cut]));
        path.approach(req.infeed, point(v, a[cut]), req.feed);
        path.feed(point(v, to), req.feed);
        // back along the cut axis at the shallowest point of the way out: clear of the part
        const double clear = followOut(c, path.at(), level, s, v, previous, path, req.feed);
        path.rapid(point(clear, path.at()[cut]));
        path.rapid(point(clear, a[cut]));
        continue;
      }
      // a closed zone: from A's level down onto its near wall at the previous level, along the
      // wall to this one, across, up the far wall, back to A's level
      // (the near wall: the last point at the previous level before `from` with the contour
      // not at this level in between; none: straight down at `from`)
      std::optional<double> wall, barrier;
      for (double x : crossingsAt(c, level, v))
        if (*cutSign * (from - x) > kTol && (!barrier || *cutSign * (x - *barrier) > 0))
          barrier = x;
      for (double x : crossingsAt(c, level, previous))
        if (*cutSign * (from - x) >= -kTol && (!barrier || *cutSign * (x - *barrier) > kTol) &&
            (!wall || *cutSign * (x - *wall) > 0))
          wall = x;
      const Vec2 top = point(previous, wall.value_or(from));
      path.rapid(point(a[level], path.at()[cut]));
      path.rapid(point(a[level], top[cut]));
      path.rapid(top);
      if (wall) followProfileUntil(c, top, level, v, path, req.feed);
      path.feed(point(v, from), req.feed);
      path.feed(point(v, to), req.feed);
      followOut(c, path.at(), level, s, v, previous, path, req.feed);
      path.rapid(point(a[level], path.at()[cut]));
    }
    previous = v;
  }
  path.rapid(a);
  return true;
}

void finishing(const ContourCycleRequest& req, TurningPath& path) {
  const Profile& c = req.contours.front();
  const Vec2 a = path.start();
  path.approach(req.infeed, c.aPrime, req.feed);
  followProfile(c, path, req.feed);
  path.rapid({path.at()[0], a[1]}); // G0 to X of A, then to its Z
  path.rapid(a);
}

} // namespace

int approachPasses(double initialAllowance, double depth) {
  const double n = std::ceil(std::abs(initialAllowance) / depth - 1e-9);
  return static_cast<int>(std::clamp(n, 1.0, static_cast<double>(kMaxPasses)));
}

std::optional<std::vector<CycleOp>> expandContourCycle(const ContourCycleRequest& req,
                                                       diag::Engine& diags) {
  if (req.feed <= 0) {
    diags.error(diag::code::MissingData, req.block, fmt::format("{}: no feed F", req.label));
    return std::nullopt;
  }
  TurningPath path(req.start, req.plane);
  if (!req.depth) {
    finishing(req, path);
  } else if (req.cycle == ContourCycle::Approach) {
    int k = 0;
    for (const Profile& c : req.contours) { // G0|G1 A -> P_i, the contour, G0 to A
      path.pass(++k);
      path.approach(req.infeed, c.aPrime, req.feed);
      followProfile(c, path, req.feed);
      path.rapid(path.start());
    }
  } else if (!levels(req, path, diags)) {
    return std::nullopt;
  }
  return std::move(path.ops());
}

} // namespace gcx::cycles
