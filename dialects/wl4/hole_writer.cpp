// A hole as WL4's canned cycle (wl4.md §5.1-§5.2): `#2=R #3=Z [#4=dwell]`, then `G81 G0 X Y F`,
// whose move calls the stock program %81 (programs/81.wl4) with a copy of the locals. Later
// holes of the same cycle are `G0 X Y`, after the assignments that changed. The stock cycles
// leave the tool at #2; a hole that ends elsewhere is followed by G80 and a rapid to its exit
// level (a G0 Z in cycle mode would drill again).
#include "dialects/wl4/hole_writer.h"

#include <fmt/format.h>
#include <map>

#include "motion/decimal.h"

namespace gcx::wl4 {

namespace {

using xlate::BlockOut;
using xlate::Hole;
using xlate::HoleKind;

// The stock programs by meaning (§5.2): %81 drills, %82 dwells #4 s at the bottom, %83 pecks #5
// deep, %85 feeds out to #2 at the feed in.
int cycleProgram(HoleKind k) {
  switch (k) {
  case HoleKind::Drill:
    return 81;
  case HoleKind::DrillDwell:
    return 82;
  case HoleKind::BoreFeedOut:
    return 85;
  case HoleKind::Peck:
    return 83;
  case HoleKind::ChipBreak:
    return 0; // none of the stock programs backs off without leaving the hole
  }
  return 81;
}
constexpr int kCancel10 = 800; // G80 (§2.1)
constexpr int kLevelR = 2, kBottom = 3, kDwell = 4, kPeck = 5;
constexpr double kPeckClearance = 1; // %83 starts each peck 1 mm above the last (§5.2)

class HoleWriter : public xlate::HoleLowering {
public:
  std::optional<std::string> refuse(const Hole& h, const BlockOut& out) const override {
    if (h.kind == HoleKind::BoreFeedOut && !xlate::sameWritten(out, h.retractFeed, h.feed))
      return fmt::format("WL4 %85 feeds out at the feed in, not F{}",
                         motion::formatDecimal(h.retractFeed, 3));
    if (cycleProgram(h.kind) == 0)
      return "WL4's stock programs %81-%89 have no chip-breaking cycle";
    if (h.kind == HoleKind::Peck && !xlate::sameWritten(out, h.clearance, kPeckClearance))
      return fmt::format("WL4 %83 starts each peck 1 mm above the last depth, not {} mm",
                         motion::formatDecimal(out.rounded(h.clearance), 4));
    return std::nullopt;
  }

  void write(const Hole& h, BlockOut& out) override {
    std::map<int, double> want{{kLevelR, h.r}, {kBottom, h.bottom}};
    if (h.kind == HoleKind::DrillDwell) want[kDwell] = h.dwell;
    if (h.kind == HoleKind::Peck) want[kPeck] = h.peck;
    bool assigned = false;
    for (const auto& [var, value] : want) {
      const auto m = vars_.find(var);
      if (m != vars_.end() && xlate::sameWritten(out, m->second, value)) continue;
      out.writeAssign(var, value);
      vars_[var] = out.rounded(value);
      assigned = true;
    }
    if (assigned) out.endBlock();
    const int program = cycleProgram(h.kind);
    const std::optional<int> rapid = xlate::gcodeFor(out.profile(), GAction::Rapid);
    if (program != cycle_) out.writeCode('G', program * 10);
    if (rapid) out.writeCode('G', *rapid);
    out.writeValue("X", h.x);
    out.writeValue("Y", h.y);
    if (program != cycle_ || !xlate::sameWritten(out, h.feed, feed_)) out.writeValue("F", h.feed);
    out.endBlock();
    cycle_ = program;
    feed_ = h.feed;
    if (xlate::sameWritten(out, h.exit, h.r)) return;
    cancel(out);
    if (rapid) out.writeCode('G', *rapid);
    out.writeValue("Z", h.exit);
    out.endBlock();
  }

  void cancel(BlockOut& out) override {
    if (!cycle_) return;
    out.writeCode('G', kCancel10);
    out.endBlock();
    cycle_ = 0;
  }

private:
  int cycle_ = 0; // the G8n in force, 0 after G80
  double feed_ = 0;
  std::map<int, double> vars_; // #2 #3 #4 as assigned; G80 does not clear variables
};

} // namespace

std::unique_ptr<xlate::HoleLowering> makeHoleWriter() {
  return std::make_unique<HoleWriter>();
}

} // namespace gcx::wl4
