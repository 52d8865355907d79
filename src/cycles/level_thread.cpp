// FMS-3000 G162 multi-pass thread (fms3000.md §5.3, Table 31, 001:3141-3199): a reconstruction
// [R] of the spec, unverified against the control.
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "cycles/level_turning_parts.h"

namespace gcx::cycles::level {

namespace {

constexpr double kTol = 1e-6;
constexpr double kResolution = 0.0005;
constexpr long kMaxPasses = 100000; // more is a typing error, not a part (no hang)

// The depths of the passes: Q, 2Q, ... while they stay within P, then the rest B below Q as the
// allowances B/2, B/4, B/8 and B - (B/2 + B/4 + B/8) (001:3190-3199). One pass at depth 0
// without P and Q: X is then the thread's end point itself.
std::variant<std::vector<double>, std::string> passDepths(const LevelTurnRequest& req) {
  const bool p = req.words.count('P') != 0, q = req.words.count('Q') != 0;
  if (p != q) return fmt::format("{}: P and Q come together (001:3946-3949)", req.code);
  if (!p) return std::vector<double>{0};
  const double total = std::abs(req.words.at('P')), step = std::abs(req.words.at('Q'));
  if (total < kResolution || step < kResolution)
    return fmt::format("{}: the depth P and the depth per pass Q must not be 0", req.code);
  if (total / step > kMaxPasses)
    return fmt::format("{}: more than {} passes: is Q a typing error?", req.code, kMaxPasses);
  std::vector<double> depths;
  const long n = static_cast<long>(std::floor(total / step + 1e-9));
  for (long k = 1; k <= n; ++k)
    depths.push_back(static_cast<double>(k) * step);
  const double done = static_cast<double>(n) * step, rest = total - done;
  if (rest > kTol)
    for (double part : {rest / 2, rest * 3 / 4, rest * 7 / 8, rest})
      depths.push_back(done + part);
  return depths;
}

} // namespace

// G162 (Table 31) [R], each pass at depth d (along the approach a = sign(X - x0), from X):
// with the infeed angle A, first along Z to the pass's start z0 + shift, shift = -a*d*tan(A)
// (A counterclockwise from the approach in the lathe plane, Z first and X second, as G18 sees
// it); 1: X to the thread at H; 2: the thread along its line, spindle-synchronised at the
// pitch F, to Z - s*V, then the run-out at 45° (away from the part by V) to Z; 3-4: X back to
// x0 at H (away, opposite to the approach, 001:3169-3170); 5: Z back to z0 at H. The line of a
// pass runs from X + a*d at z0 to W further along X at Z (the taper, 001:3167-3169). The pitch
// leads the axis of the longer travel (E44, 001:3181-3186): along Z the same revolutions cover
// F * |Z - z0| / max(|Z - z0|, |W|).
Result multiPassThread(const LevelTurnRequest& req, double pitch) {
  const double x0 = req.position[kX], z0 = req.position[kZ];
  const double x = position(req, 'X', x0), z = position(req, 'Z', z0);
  if (std::abs(x - x0) < kResolution)
    return fmt::format("{}: no travel along X (001:3965-3966)", req.code);
  if (std::abs(z - z0) < kResolution)
    return fmt::format("{}: no travel along Z (001:3967-3968)", req.code);
  const double h = req.words.at('H');
  if (h <= 0) return fmt::format("{} needs the feed H > 0 (mm per minute)", req.code);
  if (pitch <= 0)
    return fmt::format("{} needs the thread pitch F > 0 (mm per revolution)", req.code);
  if (req.spindleDirection == 0)
    return fmt::format("{} cuts with the spindle turning: M03 or M04 first", req.code);
  const double length = std::abs(z - z0), s = sign(z - z0), a = sign(x - x0);
  const auto word = [&](char c) {
    const auto it = req.words.find(c);
    return it == req.words.end() ? 0.0 : it->second;
  };
  const double runOut = std::abs(word('V')), taper = word('W'), angle = word('A');
  if (runOut >= length - kResolution)
    return fmt::format("{}: the run-out V {:g} is not shorter than the thread {:g}", req.code,
                       runOut, length);
  if (std::abs(angle) >= 90 - kTol)
    return fmt::format("{}: the infeed angle A {:g} is not within ±90°", req.code, angle);
  const auto depths = passDepths(req);
  if (const std::string* why = std::get_if<std::string>(&depths)) return *why;
  const double lead = pitch * length / std::max(length, std::abs(taper));
  const double tanA = std::tan(angle * std::numbers::pi / 180);
  Path path(req.position);
  for (double d : std::get<std::vector<double>>(depths)) {
    const auto line = [&](double at) { return x + a * d + taper * (at - z0) / (z - z0); };
    const double start = z0 - a * d * tanA, last = z - s * runOut;
    path.along(kZ, OpKind::Feed, start, h);
    path.along(kX, OpKind::Feed, line(start), h);
    path.thread(line(last), last, lead);
    path.thread(line(last) - a * runOut, z, lead);
    path.along(kX, OpKind::Feed, x0, h);
    path.along(kZ, OpKind::Feed, z0, h);
  }
  return path.take();
}

} // namespace gcx::cycles::level
