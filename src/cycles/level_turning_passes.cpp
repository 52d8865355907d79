// FMS-3000 G151 single-pass facing, G158/G159 grooves and G163 tapping (fms3000.md §5.3,
// Tables 20, 27, 28, 32):
// reconstructions [R] of the spec, unverified against the control.
#include <cmath>
#include <fmt/format.h>

#include "cycles/level_turning_parts.h"

namespace gcx::cycles::level {

namespace {

constexpr long kMaxGrooves = 100000; // more is a typing error, not a part (no hang)

} // namespace

// G151 (Table 20) [R]: 1 Z to Z (G1, or G0 with the flag); 2 X to Q, the cone's start (to X
// without a cone); 3 to (X, Z - s*P); 4 Z back to z0; 5 rapid X back to x0.
Result singlePassFacing(const LevelTurnRequest& req, double feed) {
  const double x0 = req.position[kX], z0 = req.position[kZ];
  const double x = position(req, 'X', x0), z = position(req, 'Z', z0);
  const bool p = req.words.count('P') != 0, q = req.words.count('Q') != 0;
  if (p != q) return fmt::format("{}: P and Q come together (the cone)", req.code);
  Path path(req.position);
  path.along(kZ, req.rapidFlag ? OpKind::Rapid : OpKind::Feed, z, req.rapidFlag ? 0 : feed);
  if (p) {
    path.along(kX, OpKind::Feed, position(req, 'Q', x0), feed);
    path.to(OpKind::Feed, x, z - sign(z - z0) * std::abs(req.words.at('P')), feed);
  } else {
    path.along(kX, OpKind::Feed, x, feed);
  }
  path.along(kZ, OpKind::Feed, z0, feed);
  path.along(kX, OpKind::Rapid, x0);
  return path.take();
}

// G158 (Table 27) [R]: grooves along X at z0, z0 + s*Q, ... and last at Z: each is a feed to
// the bottom X and a rapid back to x0; between grooves Z moves at F, or rapid with the G0 flag.
// G159 (Table 28) the same with X and Z swapped. The cycle ends out of the last groove.
Result grooves(const LevelTurnRequest& req, double feed) {
  const DepthAndCut ax = depthAndCut(req, req.cycle == LevelCycle::FaceGrooves);
  const int deep = ax.depth, step = ax.cut;
  const double out = ax.out, first = ax.back, bottom = ax.bottom, last = ax.end;
  const double pitch = std::abs(req.words.at('Q'));
  if (pitch < 0.0005) return fmt::format("{}: the pitch Q must not be 0", req.code);
  const double s = sign(last - first), travel = std::abs(last - first);
  if (travel / pitch > kMaxGrooves)
    return fmt::format("{}: more than {} grooves: is Q a typing error?", req.code, kMaxGrooves);
  Path path(req.position);
  for (long k = 0;; ++k) {
    const bool end = k * pitch >= travel - 0.0005;
    const double at = end ? last : first + s * static_cast<double>(k) * pitch;
    if (k > 0)
      path.along(step, req.rapidFlag ? OpKind::Rapid : OpKind::Feed, at, req.rapidFlag ? 0 : feed);
    path.along(deep, OpKind::Feed, bottom, feed);
    path.along(deep, OpKind::Rapid, out);
    if (end) break;
  }
  return path.take();
}

// G163 (Table 32, 001:3201-3240) [R]: a spindle-synchronised feed along Z to Z at F mm per
// revolution, the spindle reversed (through a stop when M5 is written), the synchronised feed
// back to z0, the spindle's first direction again, then rapid to X when given. I (sync with the
// zero mark before the Z move) changes no motion: a synchronised move starts on the mark.
Result tapping(const LevelTurnRequest& req, double feed) {
  if (const auto m = req.words.find('M'); m != req.words.end() && m->second != 5)
    return fmt::format("{}: M5 is its only M (a stop before the reverse)", req.code);
  if (feed <= 0)
    return fmt::format("{} needs the thread pitch F > 0 (mm per revolution)", req.code);
  if (req.spindleDirection == 0)
    return fmt::format("{} taps with the spindle turning: M03 or M04 first", req.code);
  const double z0 = req.position[kZ];
  const bool stop = req.words.count('M') != 0;
  Path path(req.position);
  const auto reverse = [&](int direction) {
    if (stop) path.event(OpKind::SpindleStop);
    path.event(direction > 0 ? OpKind::SpindleCW : OpKind::SpindleCCW);
  };
  path.thread(position(req, 'Z', z0), feed);
  reverse(-req.spindleDirection);
  path.thread(z0, feed);
  reverse(req.spindleDirection);
  if (req.words.count('X')) path.along(kX, OpKind::Rapid, position(req, 'X', req.position[kX]));
  return path.take();
}

} // namespace gcx::cycles::level
