// A hole as LinuxCNC's `G98|G99 G73|G81|G82|G83|G85 X Y R Z [P] [Q] F` (LinuxCNC "G-Codes",
// canned cycles; docs/nct-vs-linuxcnc.md): every hole written whole, since LinuxCNC asks R again
// when the cycle code changes. Its pecks back off and re-approach 0.254 mm, fixed; G98 returns
// to the level the tool came from when that lies above R; G85 feeds out at F.
#include "dialects/ngc/hole_writer.h"

#include <fmt/format.h>

#include "cycles/drilling_state.h"
#include "motion/decimal.h"

namespace gcx::ngc {

namespace {

using xlate::BlockOut;
using xlate::Hole;
using xlate::HoleKind;

constexpr double kPeckDistance = 0.254; // mm: LinuxCNC's G73 back-off and G83 clearance

class HoleWriter : public xlate::HoleLowering {
public:
  std::optional<std::string> refuse(const Hole& h, const BlockOut& out) const override {
    if (h.kind == HoleKind::BoreFeedOut && !xlate::sameWritten(out, h.retractFeed, h.feed))
      return fmt::format("LinuxCNC's G85 feeds out at the feed in, not F{}",
                         motion::formatDecimal(h.retractFeed, 3));
    if (h.kind == HoleKind::Peck && !xlate::sameWritten(out, h.clearance, kPeckDistance))
      return fmt::format("LinuxCNC's G83 re-approaches 0.254 mm above the last depth, not {}",
                         motion::formatDecimal(h.clearance, 4));
    if (h.kind == HoleKind::ChipBreak && !xlate::sameWritten(out, h.backOff, kPeckDistance))
      return fmt::format("LinuxCNC's G73 backs off 0.254 mm, not {}",
                         motion::formatDecimal(h.backOff, 4));
    if (!xlate::sameWritten(out, h.exit, h.r) &&
        !(xlate::sameWritten(out, h.exit, h.start) && h.start >= h.r))
      return fmt::format("LinuxCNC leaves a hole at R or at the level above R it came from, not "
                         "at Z{}",
                         motion::formatDecimal(out.rounded(h.exit), 4));
    return std::nullopt;
  }

  void write(const Hole& h, BlockOut& out) override {
    const bool toR = xlate::sameWritten(out, h.exit, h.r);
    code(out, toR ? GAction::ReturnR : GAction::ReturnInitial);
    code(out, GAction::DrillCycle, static_cast<int>(xlate::drillCycleOf(h.kind)));
    out.writeValue("X", h.x);
    out.writeValue("Y", h.y);
    out.writeValue("R", h.r);
    out.writeValue("Z", h.bottom);
    if (h.kind == HoleKind::DrillDwell) out.writeValue("P", h.dwell);
    if (h.kind == HoleKind::Peck || h.kind == HoleKind::ChipBreak) out.writeValue("Q", h.peck);
    out.writeValue("F", h.feed);
    out.endBlock();
    open_ = true;
  }

  void cancel(BlockOut& out) override {
    if (!open_) return;
    code(out, GAction::CycleCancel);
    out.endBlock();
    open_ = false;
  }

private:
  static void code(BlockOut& out, GAction a, int arg = -1) {
    if (const std::optional<int> c = xlate::gcodeFor(out.profile(), a, arg)) out.writeCode('G', *c);
  }
  bool open_ = false;
};

} // namespace

std::unique_ptr<xlate::HoleLowering> makeHoleWriter() {
  return std::make_unique<HoleWriter>();
}

} // namespace gcx::ngc
