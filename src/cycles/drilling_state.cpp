#include "cycles/drilling_state.h"

#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"

namespace gcx::cycles {

namespace {

// cycles.md §2.1, in the order of DrillCycle
constexpr double kMaxRepetitions = 99999999; // 000:9616

bool negative(const std::optional<DrillWord>& w, char address, diag::Engine& diags,
              const SourceRange& block) {
  if (!w || w->value >= 0) return false;
  diags.error(diag::code::CycleQNegative, w->range.begin.valid() ? w->range : block,
              fmt::format("{} must be positive in a drilling cycle (000:9584, 9590)", address));
  return true;
}

} // namespace

std::optional<long> updateModal(DrillModal& m, const DrillWords& w, diag::Engine& diags) {
  if (!m.cycle && !w.code) return 0; // not in cycle mode: Q, E, L... mean something else
  const DrillVariables& in = w.vars;
  if (negative(in.q, 'Q', diags, w.range) || negative(in.e, 'E', diags, w.range))
    return std::nullopt;
  long holes = 1;
  if (w.l) {
    const double l = w.l->value;
    if (!(l >= 0 && l <= kMaxRepetitions) || l != std::floor(l)) {
      diags.error(diag::code::CycleLRange, w.l->range.begin.valid() ? w.l->range : w.range,
                  "repetition count L must be 0-99999999 (000:9616)");
      return std::nullopt;
    }
    holes = static_cast<long>(l);
  }
  if (!m.cycle) { // entering cycle mode (000:9485-9493)
    m.axis = w.axis;
    m.initial = w.axisPosition;
  } else if (m.axis != w.axis) { // a new drilling axis (000:9494-9505)
    m.axis = w.axis;
    m.initial = w.axisPosition;
    m.vars.r.reset();
  }
  if (w.code) m.cycle = w.code, m.label = w.label;
  DrillVariables& v = m.vars;
  if (in.z) v.z = in.z;
  if (in.r) v.r = in.r; // stored even without a hole (§9 Q-4)
  if (!w.holeWord && !in.z) return 0;
  // I J K Q E P count only in a block that drills (000:10338-10340)
  auto keep = [](const std::optional<DrillWord>& from, std::optional<DrillWord>& to) {
    if (from) to = from;
  };
  keep(in.q, v.q), keep(in.e, v.e), keep(in.p, v.p);
  keep(in.i, v.i), keep(in.j, v.j), keep(in.k, v.k);
  keep(in.overridePercent ? in.overridePercent : in.i, v.overridePercent);
  if (!v.z || !v.r) {
    diags.error(diag::code::CycleNoData, w.range,
                fmt::format("no bottom point or R point: {} missing for {} (000:9503-9505, 9624)",
                            !v.z && !v.r ? "the drilling-axis word and R"
                            : !v.z       ? "the drilling-axis word"
                                         : "R",
                            m.label));
    return std::nullopt;
  }
  return holes; // L0: the data are stored, nothing moves (000:9617)
}

} // namespace gcx::cycles
