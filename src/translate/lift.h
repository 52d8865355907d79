// A program unit's blocks read by meaning (translate/steps.h) through the source dialect's
// profile: its G-code table, M-code table, dwell rule, remap table (calls, returns, repeats) and
// statements. What has no dialect-neutral meaning yet, or means something only this dialect's
// control does, is refused with the reason: structured translation then writes flat motion.
#pragma once
#include <functional>
#include <vector>

#include "dialect/profile.h"
#include "ir/block.h"
#include "translate/steps.h"

namespace gcx::xlate {

/// A machine setting of the run's setup, by meaning (machine/settings.h).
using SettingLookup = std::function<double(Setting)>;

/// Reads `blocks` (one unit, as the program library loaded it) into `out.steps`; false with the
/// first block that has no dialect-neutral meaning in `why`.
bool liftUnit(const std::vector<ir::Block>& blocks, const Profile& source,
              const SettingLookup& settings, UnitSteps& out, Unkept& why);

} // namespace gcx::xlate
