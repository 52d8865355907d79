// FMS-3000 G152 multi-pass longitudinal turning and G153 multi-pass facing (fms3000.md §5.3,
// Tables 21, 22, 001:2790-2880), and the chip breaking of G86 that their cuts and those of
// G164/G165 share: a reconstruction [R] of the spec, unverified against the control.
#include <cmath>
#include <fmt/format.h>

#include "cycles/level_drilling.h"
#include "cycles/level_turning_parts.h"

namespace gcx::cycles::level {

namespace {

constexpr double kTol = 1e-6;
constexpr double kResolution = 0.0005;
constexpr long kMaxPasses = 100000; // more is a typing error, not a part (no hang)

} // namespace

std::variant<std::vector<CycleOp>, std::string>
chipBreakingCut(const Vec3& from, int axis, double to, double step, double retract, double feed) {
  LevelDrillRequest steps;
  steps.cycle = LevelCycle::ChipBreakDrill;
  steps.axis = axis;
  steps.position = from;
  steps.words = {{'U', from[axis]}, {'Z', to}, {'V', step}, {'W', retract}, {'F', feed}};
  auto ops = expandLevelHole(steps);
  if (const std::string* why = std::get_if<std::string>(&ops)) return *why;
  std::vector<CycleOp> cut;
  for (const CycleOp& op : std::get<std::vector<CycleOp>>(ops)) { // up to the bottom only
    if (op.kind != OpKind::Rapid && op.kind != OpKind::Feed) continue;
    cut.push_back(op);
    if (op.kind == OpKind::Feed && std::abs(op.to[axis] - to) < kTol) break;
  }
  return cut;
}

// G152 (Table 21) [R]: depth levels x_k = x0 - s*k*Q (s toward X) strictly between x0 and X,
// each: X to the level at z0 (rapid with the G0 flag, else at F), a cut along Z to Z (with V W
// the chip breaking of G86), rapid X by D when given (001:2841-2843), rapid Z back to z0 (segments
// 1-4); then the finishing pass, the same on X itself ("зачистка по контуру 1-4", 001:2830); then,
// unless Y ("конец цикла на уровне X", 001:2840), rapid X back to x0. G153 (Table 22) swaps X and
// Z. The cone (P) is not here: its end on the depth axis is no parameter (notImplemented()).
Result multiPassTurning(const LevelTurnRequest& req, double feed) {
  const DepthAndCut ax = depthAndCut(req, req.cycle == LevelCycle::FacingMultiPass);
  const int depthAxis = ax.depth, cutAxis = ax.cut;
  const double out = ax.out, back = ax.back, bottom = ax.bottom, end = ax.end;
  if (std::abs(bottom - out) < kResolution)
    return fmt::format("{}: no travel along {} (001:3965-3968)", req.code, ax.depthWord);
  const bool v = req.words.count('V') != 0, w = req.words.count('W') != 0;
  if (v != w) return fmt::format("{}: V and W come together (001:3950-3953)", req.code);
  if (v && (req.words.at('V') <= 0 || req.words.at('W') < 0))
    return fmt::format("{}: the step V must be > 0 and the retract W >= 0", req.code);
  const double q = std::abs(req.words.at('Q'));
  if (q < kResolution) return fmt::format("{}: the depth per pass Q must not be 0", req.code);
  if (feed <= 0) return fmt::format("{} without a feed F", req.code);
  if (std::abs(bottom - out) / q > kMaxPasses)
    return fmt::format("{}: more than {} passes: is Q a typing error?", req.code, kMaxPasses);
  const double s = sign(out - bottom);
  const auto d = req.words.find('D');
  Path path(req.position);
  for (long k = 1;; ++k) {
    const double level = out - s * static_cast<double>(k) * q;
    const bool finishing = !(s * (level - bottom) > kTol);
    const double at = finishing ? bottom : level;
    path.along(depthAxis, req.rapidFlag ? OpKind::Rapid : OpKind::Feed, at,
               req.rapidFlag ? 0 : feed);
    if (v) {
      auto cut =
          chipBreakingCut(path.at(), cutAxis, end, req.words.at('V'), req.words.at('W'), feed);
      if (const std::string* why = std::get_if<std::string>(&cut))
        return fmt::format("{}: {}", req.code, *why);
      path.append(std::get<std::vector<CycleOp>>(cut));
    } else {
      path.along(cutAxis, OpKind::Feed, end, feed);
    }
    if (d != req.words.end()) path.along(depthAxis, OpKind::Rapid, at + d->second);
    path.along(cutAxis, OpKind::Rapid, back);
    if (finishing) break;
  }
  if (!req.words.count('Y')) path.along(depthAxis, OpKind::Rapid, out);
  return path.take();
}

} // namespace gcx::cycles::level
