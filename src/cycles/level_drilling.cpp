#include "cycles/level_drilling.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace gcx::cycles {

namespace {

// mandatory and allowed parameters per cycle (fms3000.md §5.1, §5.2)
struct CycleWords {
  LevelCycle cycle;
  const char* mandatory;
  const char* allowed;
};
constexpr CycleWords kWords[] = {
    {LevelCycle::Drill, "UZ", "UZIFE"},
    {LevelCycle::BoreFeedExit, "UZ", "UZIFEH"},
    {LevelCycle::DeepDrill, "UZVW", "UZIFEVW"},
    {LevelCycle::Tap, "UZ", "UZIFEM"},
    {LevelCycle::BoreSpindleStop, "UZ", "UZIFEM"},
    {LevelCycle::ChipBreakDrill, "UZVW", "UZIFEVW"},
    {LevelCycle::InterruptedDrill, "UZV", "UZIFEVW"},
    {LevelCycle::BoreOrientedStop, "UZ", "UZIFEMXY"},
};

class Builder {
public:
  Builder(const LevelDrillRequest& req) : req_(req), at_(req.position) {}
  void move(OpKind kind, double level, double feed = 0) {
    Vec3 to = at_;
    to[req_.axis] = level;
    moveTo(kind, to, feed);
  }
  void moveTo(OpKind kind, const Vec3& to, double feed = 0) {
    appendMove(ops_, at_, kind, to, feed);
  }
  void event(OpKind kind, double value = 0) {
    CycleOp op;
    op.kind = kind;
    op.to = at_;
    op.value = value;
    ops_.push_back(op);
  }
  void dwell(double tenths) {
    if (tenths > 0) event(OpKind::Dwell, tenths * req_.dwellSecondsPerUnit);
  }
  void spindle(int direction) {
    event(direction > 0   ? OpKind::SpindleCW
          : direction < 0 ? OpKind::SpindleCCW
                          : OpKind::SpindleStop);
  }
  const Vec3& at() const { return at_; }
  std::vector<CycleOp> take() { return std::move(ops_); }

private:
  const LevelDrillRequest& req_;
  Vec3 at_;
  std::vector<CycleOp> ops_;
};

} // namespace

std::variant<std::vector<CycleOp>, std::string> expandLevelHole(const LevelDrillRequest& req) {
  const CycleWords* spec = nullptr;
  for (const CycleWords& c : kWords)
    if (c.cycle == req.cycle) spec = &c;
  if (!spec) return fmt::format("{} is no drilling cycle", req.code);
  for (const auto& [letter, value] : req.words)
    if (std::string_view(spec->allowed).find(letter) == std::string_view::npos)
      return fmt::format("{} is no parameter of {}", letter, req.code);
  for (const char* m = spec->mandatory; *m; ++m)
    if (!req.words.count(*m)) return fmt::format("{} needs its parameter {}", req.code, *m);
  auto word = [&](char c) -> std::optional<double> {
    auto it = req.words.find(c);
    return it == req.words.end() ? std::nullopt : std::optional<double>(it->second);
  };
  const double feed = word('F').value_or(req.feed);
  if (feed <= 0) return fmt::format("{} without a feed F", req.code);
  const double p0 = req.position[req.axis];
  const double p1 = req.incremental ? p0 + *word('U') : *word('U');
  const double p2 = req.incremental ? p1 + *word('Z') : *word('Z');
  const double p3 = p1; // the U level (§10 Q7)
  const double p4 = word('I') ? (req.incremental ? p2 + *word('I') : *word('I')) : p3;
  const double s = p2 >= p1 ? 1.0 : -1.0;
  const double e = word('E').value_or(0);
  Builder b(req);
  b.move(OpKind::Rapid, p1);
  // the depths of the pecks, point 1 + s * min(kV, |p2 - p1|)
  std::vector<double> depths;
  if (req.cycle == LevelCycle::DeepDrill || req.cycle == LevelCycle::ChipBreakDrill ||
      req.cycle == LevelCycle::InterruptedDrill) {
    const double v = *word('V');
    if (v <= 0) return fmt::format("{} needs a step V > 0", req.code);
    const double total = std::fabs(p2 - p1);
    double step = v, sum = 0;
    for (int k = 1;; ++k) {
      // equal steps as k * V, never accumulated; a changing step as the sum of the steps
      sum = req.stepFactor == 1 ? k * v : sum + step;
      depths.push_back(p1 + s * std::min(sum, total));
      if (sum >= total - 1e-9) break;
      if (k > 100000) return std::string("more than 100000 steps: is V a typing error?");
      step *= req.stepFactor;
      if (req.stepFactor < 1 && step < req.minimumStep) step = req.minimumStep;
    }
  }
  switch (req.cycle) {
  case LevelCycle::Drill:
    b.move(OpKind::Feed, p2, feed);
    b.dwell(e);
    b.move(OpKind::Rapid, p3);
    break;
  case LevelCycle::BoreFeedExit:
    b.move(OpKind::Feed, p2, feed);
    b.dwell(e);
    b.move(OpKind::Feed, p3, word('H').value_or(feed));
    break;
  case LevelCycle::DeepDrill: {
    const double w = *word('W');
    for (std::size_t k = 0; k < depths.size(); ++k) {
      if (k > 0) {
        b.move(OpKind::Rapid, p1);
        b.move(OpKind::Rapid, depths[k - 1] - s * w);
      }
      b.move(OpKind::Feed, depths[k], feed);
    }
    b.dwell(e);
    b.move(OpKind::Rapid, p3);
    break;
  }
  case LevelCycle::ChipBreakDrill: {
    const double w = *word('W');
    for (std::size_t k = 0; k < depths.size(); ++k) {
      if (k > 0) b.move(OpKind::Rapid, depths[k - 1] - s * w);
      b.move(OpKind::Feed, depths[k], feed);
    }
    b.dwell(e);
    b.move(OpKind::Rapid, p3);
    break;
  }
  case LevelCycle::InterruptedDrill:
    for (std::size_t k = 0; k < depths.size(); ++k) {
      b.move(OpKind::Feed, depths[k], feed);
      if (k + 1 < depths.size()) b.dwell(word('W').value_or(0));
    }
    b.dwell(e);
    b.move(OpKind::Rapid, p3);
    break;
  case LevelCycle::Tap:
    b.move(OpKind::Feed, p2, feed);
    b.spindle(-req.spindleDirection);
    b.dwell(e);
    b.move(OpKind::Feed, p3, feed);
    b.dwell(e);
    break;
  case LevelCycle::BoreSpindleStop:
  case LevelCycle::BoreOrientedStop: {
    b.move(OpKind::Feed, p2, feed);
    b.dwell(e);
    if (req.cycle == LevelCycle::BoreSpindleStop) {
      b.spindle(0);
      b.move(OpKind::Rapid, p3);
      break;
    }
    b.event(OpKind::SpindleOrient);
    Vec3 shifted = b.at();
    shifted[req.firstAxis] += word('X').value_or(0);
    shifted[req.secondAxis] += word('Y').value_or(0);
    b.moveTo(OpKind::Rapid, shifted);
    b.move(OpKind::Rapid, p3);
    Vec3 back = b.at();
    back[req.firstAxis] = req.position[req.firstAxis];
    back[req.secondAxis] = req.position[req.secondAxis];
    b.moveTo(OpKind::Rapid, back);
    break;
  }
  }
  b.move(OpKind::Rapid, p4);
  // G84 reverses back, G85/G88 restart the spindle, unless M is written (§5.2)
  if ((req.cycle == LevelCycle::Tap || req.cycle == LevelCycle::BoreSpindleStop ||
       req.cycle == LevelCycle::BoreOrientedStop) &&
      !word('M') && req.spindleDirection != 0)
    b.spindle(req.spindleDirection);
  return b.take();
}

} // namespace gcx::cycles
