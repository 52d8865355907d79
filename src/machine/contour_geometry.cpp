// The interpreter's side of the automatic contour geometry (nct.md §4): the direction angle of
// a line completes its end point in program coordinates; a chamfer or rounding is requested
// from the stage that inserts it (contour_corners.h).
#include <cmath>
#include <fmt/format.h>
#include <utility>

#include "diag/codes.h"
#include "emit/number.h"
#include "machine/interpreter.h"
#include "motion/geometry.h"

namespace gcx::machine {

bool Interpreter::contourGeometry(const BlockWords& w, Vec3& to) {
  bool over = false;
  if (!intersection(w, to, over)) return false;
  if (!w.angle && !w.chamfer && !w.rounding) return true;
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  const bool first = axisGiven(w, ax.first), second = axisGiven(w, ax.second);
  const bool line = state_.motion == GAction::Rapid || state_.motion == GAction::Linear;
  if (w.angle && !over) {
    // ,A: exactly one plane coordinate; the other follows from the direction (nct.md §4.2)
    if (!line)
      return fail(
          diag::code::AngleLine, w.angle->range,
          fmt::format("{} gives the direction of a G0 or G1 line (nct.md §4.2)", w.angle->address));
    const bool compensating = state_.radiusComp != GAction::RadiusCompOff;
    if (!first && !second && compensating && !directionLine_) {
      // a line known by its direction only: it ends where the next, over-determined line
      // meets it (nct.md §4.3 line-line, TV21); nothing moves yet
      if (w.chamfer || w.rounding)
        return fail(diag::code::NotImplemented, (w.chamfer ? w.chamfer : w.rounding)->range,
                    "a chamfer or rounding on a line given by its direction alone is not "
                    "implemented yet");
      directionLine_ = DirectionLine{w.angle->number, from_, state_.motion, state_.feed};
      to = program_;
      return true;
    }
    if (first == second)
      return fail(diag::code::AngleLine, w.angle->range,
                  fmt::format("{} completes one plane coordinate of a line; without either it "
                              "is a line by its direction for an intersection, only under "
                              "G41/G42 (nct.md §4.2, §4.3)",
                              w.angle->address));
    const double a = w.angle->number * M_PI / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    if (std::fabs(first ? c : s) < 1e-12)
      return fail(diag::code::AngleLine, w.angle->range,
                  fmt::format("a line of direction {} never reaches the given coordinate",
                              emit::formatNumber(w.angle->number)));
    if (first)
      to[ax.second] = program_[ax.second] + (to[ax.first] - program_[ax.first]) * s / c;
    else
      to[ax.first] = program_[ax.first] + (to[ax.second] - program_[ax.second]) * c / s;
  }
  if (!w.chamfer && !w.rounding) return true;
  if (w.chamfer && w.rounding)
    return fail(diag::code::ChamferAndRounding, w.rounding->range,
                "a chamfer and a rounding in one block (nct.md §4.1)");
  const ir::Word* word = w.chamfer ? w.chamfer : w.rounding;
  const bool arc = state_.motion == GAction::ArcCW || state_.motion == GAction::ArcCCW;
  if ((!arc && to[ax.first] == program_[ax.first] && to[ax.second] == program_[ax.second]) ||
      state_.motion == GAction::Rapid || (!line && !arc))
    return fail(diag::code::IllegalChamfer, word->range,
                "illegal chamfer or rounding: the block is no G1, G2 or G3 move in the selected "
                "plane (nct.md §4.1)");
  if (word->number <= 0)
    return fail(diag::code::DataOutOfRange, word->range,
                fmt::format("{} must be greater than 0", word->address));
  // the size scales with the programmable transforms (uniform in the plane, nct.md §3.15)
  const Eigen::Matrix3d m = transforms_.matrix().linear();
  const double det = m(ax.first, ax.first) * m(ax.second, ax.second) -
                     m(ax.first, ax.second) * m(ax.second, ax.first);
  const double col1 = std::hypot(m(ax.first, ax.first), m(ax.second, ax.first));
  const double col2 = std::hypot(m(ax.first, ax.second), m(ax.second, ax.second));
  double factor = std::sqrt(std::fabs(det));
  if (std::fabs(col1 - col2) > 1e-9 * col1) {
    // unequal factors: a rounding takes their mean (000:8694-8697); the manual gives no
    // rule for a chamfer
    if (w.chamfer)
      return fail(diag::code::NotImplemented, word->range,
                  "a chamfer under scaling with unequal factors is not implemented (the manual "
                  "gives a rule only for ,R)");
    factor = (col1 + col2) / 2;
  }
  corners_.request(w.chamfer ? ContourCornerStage::Kind::Chamfer
                             : ContourCornerStage::Kind::Rounding,
                   mm(word->number) * factor, state_.plane);
  return true;
}

} // namespace gcx::machine
