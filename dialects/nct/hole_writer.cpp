// A hole as `G98|G99 G73|G81|G82|G83|G85 X Y R Z [P] [Q E] F` (nct.md §3, cycles.md §2): the cycle
// and the return level are found by meaning in the profile; R, Z, P and F are modal in cycle mode,
// so a later hole of the same cycle is `X Y` with only what changed. NCT leaves a hole at the
// initial level registered when cycle mode began (G98) or at R (G99), nowhere else.
#include "dialects/nct/hole_writer.h"

#include <fmt/format.h>

#include "cycles/drilling_state.h"
#include "motion/decimal.h"

namespace gcx::nct {

namespace {

using xlate::BlockOut;
using xlate::Hole;
using xlate::HoleKind;

class HoleWriter : public xlate::HoleLowering {
public:
  std::optional<std::string> refuse(const Hole& h, const BlockOut& out) const override {
    if (h.kind == HoleKind::BoreFeedOut && !xlate::sameWritten(out, h.retractFeed, h.feed))
      return fmt::format("NCT G85 feeds out at the feed in, not F{}",
                         motion::formatDecimal(h.retractFeed, 3));
    if (!returnToR(h, run_ ? run_->initial : h.start, out) && !returnToR(h, h.start, out))
      return fmt::format("NCT leaves a hole at its initial level or at R, not at Z{}",
                         motion::formatDecimal(out.rounded(h.exit), 4));
    return std::nullopt;
  }

  void write(const Hole& h, BlockOut& out) override {
    if (run_ && !returnToR(h, run_->initial, out)) cancel(out); // a new initial level
    const bool fresh = !run_;
    // E: G83's clearance above the last depth, G73's back-off (cycles.md §2.4)
    const bool pecks = h.kind == HoleKind::Peck || h.kind == HoleKind::ChipBreak;
    const double e = h.kind == HoleKind::Peck ? h.clearance : h.backOff;
    Run next{h.kind, false, fresh ? h.start : run_->initial, h.r, h.bottom, h.feed, h.dwell,
             h.peck, e};
    next.toR = *returnToR(h, next.initial, out);
    if (fresh || next.toR != run_->toR)
      code(out, next.toR ? GAction::ReturnR : GAction::ReturnInitial);
    if (fresh || next.kind != run_->kind)
      code(out, GAction::DrillCycle, static_cast<int>(xlate::drillCycleOf(h.kind)));
    out.writeValue("X", h.x);
    out.writeValue("Y", h.y);
    auto changed = [&](double now, double before) {
      return fresh || !xlate::sameWritten(out, now, before);
    };
    if (changed(h.r, run_ ? run_->r : 0)) out.writeValue("R", h.r);
    if (changed(h.bottom, run_ ? run_->bottom : 0)) out.writeValue("Z", h.bottom);
    // P in seconds, like G4 P (the dwell of a later hole of G82 is the stored one)
    if (h.kind == HoleKind::DrillDwell &&
        (fresh || run_->kind != h.kind || changed(h.dwell, run_->dwell)))
      out.writeValue("P", h.dwell);
    if (pecks &&
        (fresh || run_->kind != h.kind || changed(h.peck, run_->peck) || changed(e, run_->e))) {
      out.writeValue("Q", h.peck);
      out.writeValue("E", e);
    }
    if (changed(h.feed, run_ ? run_->feed : 0)) out.writeValue("F", h.feed);
    out.endBlock();
    run_ = next;
  }

  void cancel(BlockOut& out) override {
    if (!run_) return;
    code(out, GAction::CycleCancel);
    out.endBlock();
    run_.reset();
  }

private:
  struct Run {
    HoleKind kind;
    bool toR;
    double initial, r, bottom, feed, dwell, peck, e;
  };

  // G99 when the hole ends at R, G98 when at `initial`; nullopt when elsewhere
  static std::optional<bool> returnToR(const Hole& h, double initial, const BlockOut& out) {
    if (xlate::sameWritten(out, h.exit, h.r)) return true;
    if (xlate::sameWritten(out, h.exit, initial)) return false;
    return std::nullopt;
  }

  static void code(BlockOut& out, GAction a, int arg = -1) {
    if (const std::optional<int> c = xlate::gcodeFor(out.profile(), a, arg)) out.writeCode('G', *c);
  }

  std::optional<Run> run_;
};

} // namespace

std::unique_ptr<xlate::HoleLowering> makeHoleWriter() {
  return std::make_unique<HoleWriter>();
}

} // namespace gcx::nct
