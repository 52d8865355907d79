// A hole as `G00 X Y G81 U Z [I] [E] F` (fms3000.md §5.1-§5.2), G83 (pecks) and G86 (chip breaking)
// with V W: the words before the cycle code position the tool, the words after it are the cycle's
// levels, U the start of the feed, Z the bottom, I the exit (absent: the tool stays at U), E the
// dwell in tenths of a second, G82's H the feed out. The same cycle remembers every parameter not
// written (§5.1), so a later hole writes only what changed; each hole restates its cycle code, so
// nothing depends on which cycles N3023 repeats modally. G80 ends the run before any other block.
#include "dialects/fms3000/hole_writer.h"

#include <cmath>
#include <fmt/format.h>
#include <map>

#include "cycles/level_cycle.h"
#include "motion/decimal.h"

namespace gcx::fms3000 {

namespace {

using xlate::BlockOut;
using xlate::Hole;
using xlate::HoleKind;

cycles::LevelCycle levelCycle(HoleKind k) {
  return k == HoleKind::BoreFeedOut ? cycles::LevelCycle::BoreFeedExit
         : k == HoleKind::Peck      ? cycles::LevelCycle::DeepDrill
         : k == HoleKind::ChipBreak ? cycles::LevelCycle::ChipBreakDrill
                                    : cycles::LevelCycle::Drill;
}

// E: the dwell in the dialect's unit (tenths of a second), nullopt when not a whole number
std::optional<double> dwellUnits(const Hole& h, const BlockOut& out) {
  const double units = h.dwell / out.profile().machine.dwell.secondsPerUnit;
  if (std::fabs(units - std::round(units)) > 1e-6) return std::nullopt;
  return std::round(units);
}

class HoleWriter : public xlate::HoleLowering {
public:
  std::optional<std::string> refuse(const Hole& h, const BlockOut& out) const override {
    if (h.kind == HoleKind::DrillDwell && !dwellUnits(h, out))
      return fmt::format("FMS-3000 dwells in whole tenths of a second (E), not {} s",
                         motion::formatDecimal(h.dwell, 6));
    return std::nullopt;
  }

  void write(const Hole& h, BlockOut& out) override {
    const cycles::LevelCycle cycle = levelCycle(h.kind);
    std::map<char, double> want{{'U', h.r}, {'Z', h.bottom}, {'F', h.feed}};
    if (!xlate::sameWritten(out, h.exit, h.r)) want['I'] = h.exit;
    if (h.kind == HoleKind::DrillDwell) want['E'] = *dwellUnits(h, out);
    if (h.kind == HoleKind::Peck) { // G83: V each peck, W the clearance (§5.2)
      want['V'] = h.peck;
      want['W'] = h.clearance;
    }
    if (h.kind == HoleKind::ChipBreak) { // G86: V each step, W the rapid back (§5.2)
      want['V'] = h.peck;
      want['W'] = h.backOff;
    }
    if (h.kind == HoleKind::BoreFeedOut && !xlate::sameWritten(out, h.retractFeed, h.feed))
      want['H'] = h.retractFeed;
    if (cycle_ != cycle) memory_.clear(); // another cycle forgets every parameter
    // a remembered dwell or feed out this hole has not: only G80 forgets them
    if ((memory_.count('E') && !want.count('E')) || (memory_.count('H') && !want.count('H')))
      cancel(out);
    // a remembered exit: I at U leaves the tool at U again
    if (memory_.count('I') && !want.count('I')) want['I'] = h.r;
    if (const std::optional<int> rapid = xlate::gcodeFor(out.profile(), GAction::Rapid))
      out.writeCode('G', *rapid);
    out.writeValue("X", h.x);
    out.writeValue("Y", h.y);
    if (const std::optional<int> c =
            xlate::gcodeFor(out.profile(), GAction::LevelDrillCycle, static_cast<int>(cycle)))
      out.writeCode('G', *c);
    for (const char letter : {'U', 'Z', 'I', 'V', 'W', 'E', 'H', 'F'}) {
      const auto w = want.find(letter);
      if (w == want.end()) continue;
      const auto m = memory_.find(letter);
      if (m != memory_.end() && xlate::sameWritten(out, m->second, w->second)) continue;
      const char address[2] = {letter, 0};
      if (letter == 'E')
        out.writeExact(address, w->second);
      else
        out.writeValue(address, w->second);
      memory_[letter] = w->second;
    }
    out.endBlock();
    cycle_ = cycle;
  }

  void cancel(BlockOut& out) override {
    if (!cycle_) return;
    if (const std::optional<int> c = xlate::gcodeFor(out.profile(), GAction::CycleCancel))
      out.writeCode('G', *c);
    out.endBlock();
    cycle_.reset();
    memory_.clear();
  }

private:
  std::optional<cycles::LevelCycle> cycle_;
  std::map<char, double> memory_;
};

} // namespace

std::unique_ptr<xlate::HoleLowering> makeHoleWriter() {
  return std::make_unique<HoleWriter>();
}

} // namespace gcx::fms3000
