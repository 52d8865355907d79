// Polar coordinates about a pole (FMS-3000 G36, fms3000.md §3.11): `G36 X_ Y_` (the current
// plane's axis names) sets the pole, absolute in the work system, without motion; until G35 (or
// G37, the other code of its group) `G0|G1 I_ A_` and `G2|G3 I_ A_ R_` end at radius I and angle
// A (degrees from the first plane axis, counterclockwise) about the pole, whatever G90/G91 say.
// The block then runs as an ordinary one whose plane axis words hold that end point.
#include <fmt/format.h>

#include <cmath>
#include <string_view>

#include "diag/codes.h"
#include "machine/code_names.h"
#include "machine/interpreter.h"
#include "motion/geometry.h"

namespace gcx::machine {

namespace {

constexpr std::string_view kAxes = "XYZ";
constexpr std::string_view kOtherAxes = "UVWABC";

bool isAxis(const ir::Word& w, std::string_view letters) {
  return w.address.size() == 1 && letters.find(w.address[0]) != std::string_view::npos;
}

} // namespace

std::optional<bool> Interpreter::polePolarBlock(const ir::Block& block) {
  if (polarRewritten_) return std::nullopt;
  // no pole set and no code to set one: nothing below applies (the loop finds no pole)
  if (!pole_ && !profile_.defines(GAction::PolePolar)) return std::nullopt;
  const ir::Word* pole = nullptr;
  const ir::Word* otherTransform = nullptr; // G35 or G37 end polar mode
  const ir::Word* plane = nullptr;
  bool incremental = state_.incremental;
  for (const ir::Word& w : block.words) {
    if (!w.is('G')) continue;
    const GCodeSpec* g = profile_.gcode(w.number);
    if (!g) continue;
    if (g->action == GAction::PolePolar) pole = &w;
    if (g->action == GAction::RotateOn || g->action == GAction::RotateOff) otherTransform = &w;
    if (g->action == GAction::Absolute || g->action == GAction::Incremental)
      incremental = g->action == GAction::Incremental;
    if (g->action == GAction::PlaneXY || g->action == GAction::PlaneZX ||
        g->action == GAction::PlaneYZ)
      plane = &w;
  }
  if (otherTransform) pole_.reset();
  if (!pole && !pole_) return std::nullopt;
  if (plane) // 001:3859
    return fail(diag::code::FmsPolarRule, plane->range,
                fmt::format("no plane change in polar coordinates: {} first (fms3000.md §3.11)",
                            codeName(profile_, GAction::RotateOff)));
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  const char first = kAxes[static_cast<std::size_t>(ax.first)];
  const char second = kAxes[static_cast<std::size_t>(ax.second)];
  ir::Block rest = block;
  if (pole) { // G36: the pole, no motion (001:536-540)
    const ir::Word *p1 = nullptr, *p2 = nullptr;
    for (const ir::Word& w : block.words) {
      if (w.is(first))
        p1 = &w;
      else if (w.is(second))
        p2 = &w;
      else if (isAxis(w, kAxes) || isAxis(w, kOtherAxes) || w.is('I') || w.is('A'))
        return fail(diag::code::FmsPolarRule, w.range,
                    fmt::format("{} takes the pole on the plane's axes {} and {}, not {} "
                                "(fms3000.md §3.11)",
                                gName(*pole), first, second, w.address));
    }
    if (!p1 || !p2)
      return fail(diag::code::FmsPolarRule, pole->range,
                  fmt::format("{} without the pole: write {} and {} (fms3000.md §3.11)",
                              gName(*pole), first, second));
    pole_ = {p1->number, p2->number};
    if (const GCodeSpec* g = profile_.gcode(pole->number);
        g->group > 0 && g->group < static_cast<int>(modalCodes_.size()))
      modalCodes_[g->group] = g->code10;
    std::erase_if(rest.words, [&](const ir::Word& w) {
      return w.is(first) || w.is(second) || w.order == pole->order;
    });
    return rest.words.empty() || runRewritten(rest);
  }
  const ir::Word *radius = nullptr, *angle = nullptr;
  for (const ir::Word& w : block.words) {
    if (w.is('I'))
      radius = &w;
    else if (w.is('A'))
      angle = &w;
    else if (isAxis(w, kAxes) || isAxis(w, kOtherAxes) || w.is('J') || w.is('K'))
      return fail(diag::code::FmsPolarRule, w.range,
                  fmt::format("{} in polar coordinates: a polar block moves in the plane by I "
                              "(radius) and A (angle) only (fms3000.md §3.11)",
                              w.address));
  }
  if (!radius && !angle) return std::nullopt;
  if (radius && radius->number < 0)
    return fail(
        diag::code::FmsPolarRule, radius->range,
        "the polar radius I is a distance from the pole, never negative (fms3000.md §3.11)");
  // an omitted I keeps the distance from the pole, an omitted A the angle [D]
  const double d1 = program_[ax.first] - (*pole_)[0], d2 = program_[ax.second] - (*pole_)[1];
  const double r = radius ? radius->number : std::hypot(d1, d2);
  const double a = angle ? angle->number * M_PI / 180.0 : std::atan2(d2, d1);
  const double end[2] = {(*pole_)[0] + r * std::cos(a), (*pole_)[1] + r * std::sin(a)};
  std::erase_if(rest.words, [](const ir::Word& w) { return w.is('I') || w.is('A'); });
  const ir::Word& at = radius ? *radius : *angle;
  for (int i = 0; i < 2; ++i) {
    ir::Word w = at;
    w.address = std::string(1, i == 0 ? first : second);
    w.incremental = false;
    const int axis = i == 0 ? ax.first : ax.second;
    w.number = incremental ? end[i] - program_[axis] : end[i]; // G90/G91 have no effect
    w.text = fmt::format("{}", w.number);
    rest.words.push_back(std::move(w));
  }
  return runRewritten(rest);
}

bool Interpreter::runRewritten(const ir::Block& rest) {
  polarRewritten_ = true;
  const bool ok = executeBlock(rest);
  polarRewritten_ = false;
  return ok;
}

} // namespace gcx::machine
