#include "cycles/level_turning.h"

#include <cmath>
#include <fmt/format.h>
#include <optional>
#include <string_view>

#include "cycles/level_drilling.h"
#include "cycles/level_turning_parts.h"

namespace gcx::cycles {

namespace level {

namespace {

// mandatory and allowed parameters (fms3000.md §5.1, §5.3 Tables 19-36; 001:3919-3958)
struct CycleWords {
  LevelCycle cycle;
  std::string_view mandatory;
  std::string_view allowed;
};
constexpr CycleWords kWords[] = {
    {LevelCycle::LongitudinalPass, "XZ", "XZPQF"},
    {LevelCycle::FacingPass, "XZ", "XZPQF"},
    {LevelCycle::LongitudinalMultiPass, "XZQ", "XZQDPVWFY"},
    {LevelCycle::FacingMultiPass, "XZQ", "XZQDPVWFY"},
    {LevelCycle::DeepDrillZ, "UZVW", "UZVWIFEX"},
    {LevelCycle::PeckGrooveX, "UXVW", "UXVWIFEZ"},
    {LevelCycle::DeepDrillZDecreasing, "UZVWPQ", "UZVWPQIFEX"},
    {LevelCycle::PeckGrooveXDecreasing, "UXVWPQ", "UXVWPQIFEZ"},
    {LevelCycle::CylindricalGrooves, "XZQ", "XZQF"},
    {LevelCycle::FaceGrooves, "XZQ", "XZQF"},
    {LevelCycle::ChipBreakDrillZ, "UZVW", "UZVWIFEX"},
    {LevelCycle::ChipBreakGrooveX, "UXVW", "UXVWIFEZ"},
    {LevelCycle::MultiPassThread, "XZH", "XZHPQVWAF"},
    {LevelCycle::TapOrDie, "Z", "ZFXMI"},
    {LevelCycle::LongitudinalRoughing, "Q", "QVWFDP"},
    {LevelCycle::FacingRoughing, "Q", "QVWFDP"},
    {LevelCycle::Chamfer, "R", "XZR"},
    {LevelCycle::Fillet, "R", "XZR"},
};

// G166/G167 (§5.3.2): the programmed axis p runs toward its target t, stopping r short of the
// corner K = (t on p, the current value on q); the chamfer (a line) or the fillet (a quarter
// circle) then ends r from K along q, on the side sign(R) names.
Result chamferOrFillet(const LevelTurnRequest& req, double feed) {
  const auto x = req.words.find('X'), z = req.words.find('Z');
  const bool alongZ = z != req.words.end();
  if (alongZ == (x != req.words.end()))
    return fmt::format("{} takes exactly one of X and Z", req.code);
  const int p = alongZ ? kZ : kX, q = alongZ ? kX : kZ;
  const double from = req.position[p];
  const double target = (alongZ ? z : x)->second + (req.incremental ? from : 0);
  const double r = std::abs(req.words.at('R'));
  const double d1 = sign(target - from), d2 = sign(req.words.at('R'));
  if (r == 0 || std::abs(target - from) < r - 1e-9)
    return fmt::format("{}: the travel {:g} is shorter than R {:g}", req.code,
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
  if (req.cycle == LevelCycle::Chamfer) {
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
    return fmt::format("{}: P and Q come together (the cone)", req.code);
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

// G154/G156/G160 along Z, G155/G157/G161 along X (Tables 23-26, 29, 30) [R]: the G83 (G156,
// G157 with the changing step) or G86 sequence on that axis from И.Т., with the end word of the
// axis as the bottom, then rapid to the final position of the other axis when it is given.
Result drillingAlongAnAxis(const LevelTurnRequest& req) {
  const bool alongX = req.cycle == LevelCycle::PeckGrooveX ||
                      req.cycle == LevelCycle::PeckGrooveXDecreasing ||
                      req.cycle == LevelCycle::ChipBreakGrooveX;
  const int axis = alongX ? kX : kZ, other = alongX ? kZ : kX;
  const char end = alongX ? 'X' : 'Z', final = alongX ? 'Z' : 'X';
  LevelDrillRequest drill;
  drill.cycle =
      req.cycle == LevelCycle::ChipBreakDrillZ || req.cycle == LevelCycle::ChipBreakGrooveX
          ? LevelCycle::ChipBreakDrill
          : LevelCycle::DeepDrill;
  drill.code = req.code;
  drill.axis = axis;
  drill.firstAxis = other;
  drill.secondAxis = 1;
  drill.position = req.position;
  drill.incremental = req.incremental;
  drill.feed = req.feed;
  drill.dwellSecondsPerUnit = req.dwellSecondsPerUnit;
  if (req.cycle == LevelCycle::DeepDrillZDecreasing ||
      req.cycle == LevelCycle::PeckGrooveXDecreasing) {
    drill.stepFactor = req.words.at('P');
    drill.minimumStep = std::abs(req.words.at('Q'));
    if (drill.stepFactor <= 0) return fmt::format("{}: the step factor P must be > 0", req.code);
    if (drill.stepFactor < 1 && drill.minimumStep <= 0)
      return fmt::format("{}: a step factor P below 1 needs a minimum step Q > 0", req.code);
  }
  for (const auto& [c, v] : req.words)
    if (c == end)
      drill.words['Z'] = v;
    else if (c != final && c != 'P' && c != 'Q')
      drill.words[c] = v;
  auto ops = expandLevelHole(drill);
  if (std::holds_alternative<std::string>(ops)) return std::get<std::string>(ops);
  auto list = std::get<std::vector<CycleOp>>(std::move(ops));
  if (req.words.count(final)) {
    Path path(list.empty() ? req.position : list.back().to);
    path.along(other, OpKind::Rapid, position(req, final, req.position[other]));
    for (const CycleOp& op : path.take())
      list.push_back(op);
  }
  return list;
}

} // namespace

} // namespace level

std::string_view diameterWords(LevelCycle cycle) {
  switch (cycle) {
  case LevelCycle::LongitudinalPass:
  case LevelCycle::FacingPass:
  case LevelCycle::FaceGrooves:
    return "XQ";
  case LevelCycle::LongitudinalMultiPass:
    return "XQD"; // Table 21: the depth per pass and the retract are along X
  case LevelCycle::FacingMultiPass:
    return "XVW"; // Table 22: the steps and their retract are along X
  case LevelCycle::MultiPassThread:
    return "XW"; // 001:3166-3167; P and Q are always radii (001:3172)
  case LevelCycle::PeckGrooveX:
  case LevelCycle::PeckGrooveXDecreasing:
  case LevelCycle::ChipBreakGrooveX:
    return "UXVWIQ"; // every length along X (001:2998-2999, 3058-3059)
  case LevelCycle::LongitudinalRoughing:
    return "QD"; // 001:3279-3280
  case LevelCycle::FacingRoughing:
    return "VW"; // 001:3370-3371
  default:
    return "X";
  }
}

std::optional<std::string> notImplemented(const LevelTurnRequest& req) {
  const bool multiPass =
      req.cycle == LevelCycle::LongitudinalMultiPass || req.cycle == LevelCycle::FacingMultiPass;
  if (multiPass && req.words.count('P'))
    return fmt::format("the cone P of {} is not implemented yet: the manual gives its length "
                       "but not where it ends across (fms3000.md §10 Q10)",
                       req.code);
  if (req.cycle == LevelCycle::MultiPassThread && req.feedPerRevolution)
    return fmt::format("{} under a feed per revolution is not implemented yet: its feed H is in "
                       "mm per minute (001:3158)",
                       req.code);
  return std::nullopt;
}

std::variant<std::vector<CycleOp>, std::string> expandLevelTurning(const LevelTurnRequest& req) {
  using namespace level;
  const CycleWords* spec = nullptr;
  for (const CycleWords& c : kWords)
    if (c.cycle == req.cycle) spec = &c;
  if (!spec) return fmt::format("{} is not implemented yet", req.code);
  for (char c : spec->mandatory)
    if (!req.words.count(c)) return fmt::format("{} needs {}", req.code, c);
  for (const auto& [c, v] : req.words)
    if (spec->allowed.find(c) == std::string_view::npos)
      return fmt::format("{} is no parameter of {}", c, req.code);
  const auto f = req.words.find('F');
  const double feed = f != req.words.end() ? f->second : req.feed;
  switch (req.cycle) {
  case LevelCycle::LongitudinalPass:
    return singlePassTurning(req, feed);
  case LevelCycle::FacingPass:
    return singlePassFacing(req, feed);
  case LevelCycle::CylindricalGrooves:
  case LevelCycle::FaceGrooves:
    return grooves(req, feed);
  case LevelCycle::TapOrDie:
    return tapping(req, feed);
  case LevelCycle::LongitudinalMultiPass:
  case LevelCycle::FacingMultiPass:
    return multiPassTurning(req, feed);
  case LevelCycle::MultiPassThread:
    return multiPassThread(req, feed);
  case LevelCycle::LongitudinalRoughing:
  case LevelCycle::FacingRoughing:
    return profileRoughing(req, feed);
  case LevelCycle::Chamfer:
  case LevelCycle::Fillet:
    return chamferOrFillet(req, feed);
  default:
    return drillingAlongAnAxis(req);
  }
}

} // namespace gcx::cycles
