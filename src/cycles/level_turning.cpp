#include "cycles/level_turning.h"

#include <cmath>
#include <fmt/format.h>
#include <optional>
#include <string_view>

#include "cycles/level_drilling.h"

namespace gcx::cycles {

namespace {

constexpr int kX = 0, kZ = 2;

// mandatory and allowed parameters (fms3000.md §5.1, §5.3 Tables 19, 23, 29, 35, 36)
struct CycleWords {
  int cycle;
  std::string_view mandatory;
  std::string_view allowed;
};
constexpr CycleWords kWords[] = {
    {150, "XZ", "XZPQF"}, {154, "UZVW", "UZVWIFEX"}, {160, "UZVW", "UZVWIFEX"},
    {166, "R", "XZR"},    {167, "R", "XZR"},
};

double sign(double v) {
  return v < 0 ? -1.0 : 1.0;
}

class Path {
public:
  explicit Path(const Vec3& start) : at_(start) {}
  void to(OpKind kind, double x, double z, double feed = 0) {
    Vec3 p = at_;
    p[kX] = x;
    p[kZ] = z;
    appendMove(ops_, at_, kind, p, feed);
  }
  void arc(OpKind kind, double x, double z, double cx, double cz, double feed) {
    CycleOp op;
    op.kind = kind;
    op.to = at_;
    op.to[kX] = x;
    op.to[kZ] = z;
    op.center = at_;
    op.center[kX] = cx;
    op.center[kZ] = cz;
    op.feed = feed;
    ops_.push_back(op);
    at_ = op.to;
  }
  double x() const { return at_[kX]; }
  double z() const { return at_[kZ]; }
  std::vector<CycleOp> take() { return std::move(ops_); }

private:
  Vec3 at_;
  std::vector<CycleOp> ops_;
};

using Result = std::variant<std::vector<CycleOp>, std::string>;

// G166/G167 (§5.3.2): the programmed axis p runs toward its target t, stopping r short of the
// corner K = (t on p, the current value on q); the chamfer (a line) or the fillet (a quarter
// circle) then ends r from K along q, on the side sign(R) names.
Result chamferOrFillet(const LevelTurnRequest& req, double feed) {
  const auto x = req.words.find('X'), z = req.words.find('Z');
  const bool alongZ = z != req.words.end();
  if (alongZ == (x != req.words.end()))
    return fmt::format("G{} takes exactly one of X and Z", req.cycle);
  const int p = alongZ ? kZ : kX, q = alongZ ? kX : kZ;
  const double from = req.position[p];
  const double target = (alongZ ? z : x)->second + (req.incremental ? from : 0);
  const double r = std::abs(req.words.at('R'));
  const double d1 = sign(target - from), d2 = sign(req.words.at('R'));
  if (r == 0 || std::abs(target - from) < r - 1e-9)
    return fmt::format("G{}: the travel {:g} is shorter than R {:g}", req.cycle,
                       std::abs(target - from), r);
  Vec3 straight = req.position, end = req.position, centre = req.position;
  straight[p] = target - r * d1;
  end[p] = target;
  end[q] = req.position[q] + r * d2;
  centre[p] = straight[p];
  centre[q] = end[q];
  Path path(req.position);
  path.to(req.modalRapid ? OpKind::Rapid : OpKind::Feed, straight[kX], straight[kZ],
          req.modalRapid ? 0 : feed);
  if (req.cycle == 166) {
    path.to(OpKind::Feed, end[kX], end[kZ], feed);
  } else {
    // G18 looks at Z (first) and X (second) from +Y: counterclockwise when the turn from the
    // start radius to the end radius is positive in (Z, X)
    const double sz = straight[kZ] - centre[kZ], sx = straight[kX] - centre[kX];
    const double ez = end[kZ] - centre[kZ], ex = end[kX] - centre[kX];
    const bool ccw = sz * ex - sx * ez > 0;
    path.arc(ccw ? OpKind::ArcCCW : OpKind::ArcCW, end[kX], end[kZ], centre[kX], centre[kZ], feed);
  }
  return path.take();
}

// G150 (Table 19) [R]: 1 X to X (G1, or G0 when the G0 flag is given); 2 Z to Z - s*P (to Z
// without a cone); 3 to the cone's end (Q, Z); 4 X back to x0; 5 rapid Z back to z0.
Result singlePassTurning(const LevelTurnRequest& req, double feed) {
  const double x0 = req.position[kX], z0 = req.position[kZ];
  const auto at = [&](char c, double origin) {
    return req.words.at(c) + (req.incremental ? origin : 0);
  };
  const double x = at('X', x0), z = at('Z', z0);
  const bool cone = req.words.count('P') || req.words.count('Q');
  if (cone && !(req.words.count('P') && req.words.count('Q')))
    return std::string("G150: P and Q come together (the cone)");
  const double s = sign(z - z0);
  Path path(req.position);
  path.to(req.rapidFlag ? OpKind::Rapid : OpKind::Feed, x, z0, req.rapidFlag ? 0 : feed);
  if (cone) {
    path.to(OpKind::Feed, x, z - s * std::abs(req.words.at('P')), feed);
    path.to(OpKind::Feed, at('Q', x0), z, feed);
  } else {
    path.to(OpKind::Feed, x, z, feed);
  }
  path.to(OpKind::Feed, x0, path.z(), feed);
  path.to(OpKind::Rapid, x0, z0);
  return path.take();
}

// G154/G160 (Tables 23, 29) [R]: the G83/G86 sequence along Z from И.Т., then rapid to X
Result drillingAlongZ(const LevelTurnRequest& req) {
  LevelDrillRequest drill;
  drill.cycle = req.cycle == 154 ? 83 : 86;
  drill.axis = kZ;
  drill.firstAxis = kX;
  drill.secondAxis = 1;
  drill.position = req.position;
  drill.incremental = req.incremental;
  drill.feed = req.feed;
  drill.dwellSecondsPerUnit = req.dwellSecondsPerUnit;
  for (const auto& [c, v] : req.words)
    if (c != 'X') drill.words[c] = v;
  auto ops = expandLevelHole(drill);
  if (std::holds_alternative<std::string>(ops)) return std::get<std::string>(ops);
  auto list = std::get<std::vector<CycleOp>>(std::move(ops));
  if (const auto x = req.words.find('X'); x != req.words.end()) {
    Vec3 from = list.empty() ? req.position : list.back().to;
    Path path(from);
    path.to(OpKind::Rapid, x->second + (req.incremental ? req.position[kX] : 0), from[kZ]);
    for (const CycleOp& op : path.take())
      list.push_back(op);
  }
  return list;
}

} // namespace

Result expandLevelTurning(const LevelTurnRequest& req) {
  const CycleWords* spec = nullptr;
  for (const CycleWords& c : kWords)
    if (c.cycle == req.cycle) spec = &c;
  if (!spec) return fmt::format("G{} is not implemented yet", req.cycle);
  for (char c : spec->mandatory)
    if (!req.words.count(c)) return fmt::format("G{} needs {}", req.cycle, c);
  for (const auto& [c, v] : req.words)
    if (spec->allowed.find(c) == std::string_view::npos)
      return fmt::format("{} is no parameter of G{}", c, req.cycle);
  const auto f = req.words.find('F');
  const double feed = f != req.words.end() ? f->second : req.feed;
  switch (req.cycle) {
  case 150:
    return singlePassTurning(req, feed);
  case 154:
  case 160:
    return drillingAlongZ(req);
  default:
    return chamferOrFillet(req, feed);
  }
}

} // namespace gcx::cycles
