#include "cycles/kept_contours.h"

#include <fmt/format.h>

#include "cycles/turning_state.h"
#include "diag/codes.h"
#include "dialect/profile.h"

namespace gcx::cycles {

KeptContours::KeptContours(const std::vector<ir::Block>& program, const Profile& profile)
    : profile_(profile) {
  for (const ir::Block& b : program)
    if (auto c = cycleOf(b)) referenced_.insert({c->ns, c->nf});
}

std::optional<KeptContours::Cycle> KeptContours::cycleOf(const ir::Block& b) const {
  const ir::Word* p = b.find('P');
  const ir::Word* q = b.find('Q');
  if (!p || !q || !p->isLiteral() || !q->isLiteral()) return std::nullopt;
  for (const ir::Word& w : b.words) {
    if (!w.is('G') || !w.isLiteral()) continue;
    const GCodeSpec* g = profile_.gcode(w.number);
    if (!g || (g->action != GAction::TurningCycle && g->action != GAction::ContourCycle)) continue;
    if (g->action == GAction::ContourCycle || // the profile's binding
        static_cast<TurningCycle>(g->arg) <= TurningCycle::PatternRepeat)
      return Cycle{static_cast<std::int64_t>(p->number), static_cast<std::int64_t>(q->number),
                   w.range};
  }
  return std::nullopt;
}

void KeptContours::written(const ir::Block& flat) {
  if (flat.sequence && keepsNumber(*flat.sequence)) positions_[*flat.sequence].push_back(count_);
  if (auto c = cycleOf(flat)) cycles_.push_back(*c);
  ++count_;
}

bool KeptContours::check(diag::Engine& diags) const {
  bool ok = true;
  auto once = [&](std::int64_t n) -> std::optional<std::size_t> {
    auto it = positions_.find(n);
    if (it == positions_.end() || it->second.size() != 1) return std::nullopt;
    return it->second.front();
  };
  for (const Cycle& c : cycles_) {
    const auto ns = once(c.ns), nf = once(c.nf);
    if (ns && nf && *ns <= *nf) continue;
    diags.error(diag::code::KeptContourLost, c.where,
                fmt::format("--keep cycles keeps this cycle, but its contour N{}-N{} is not in the "
                            "flattened program once and in order (after the program end, or "
                            "repeated by a loop or call); expand it with --to canonical",
                            c.ns, c.nf));
    ok = false;
  }
  return ok;
}

} // namespace gcx::cycles
