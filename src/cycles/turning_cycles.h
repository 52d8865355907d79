// The per-family expanders behind expandTurning() (turning.h). Internal to the turning cycles.
#pragma once
#include "cycles/turning.h"

namespace gcx::cycles {

using TurningOps = std::optional<std::vector<CycleOp>>;

/// G71.7 / G72.7 stock removal (§4.8, §4.9).
TurningOps expandStockRemoval(const TurningRequest& req, const TurningModal& m,
                              const TurningWords& w, diag::Engine& diags);
/// G73.7 pattern repeating (§4.10).
TurningOps expandPatternRepeat(const TurningRequest& req, const TurningModal& m,
                               const TurningWords& w, diag::Engine& diags);
/// G74.7 / G75.7 grooving and peck drilling (§4.12).
TurningOps expandGrooving(const TurningRequest& req, const TurningModal& m, const TurningWords& w,
                          diag::Engine& diags);
/// G76.7 multiple threading (§4.13).
TurningOps expandThreading(const TurningRequest& req, const TurningModal& m, const TurningWords& w,
                           diag::Engine& diags);

/// A radius-valued parameter word of the block (§4.3: depths are radius, always), or nullopt.
std::optional<double> radiusWord(const TurningWords& w, char c);
/// The finishing allowance (Δw, Δu/2) of a P/Q block in lathe (z, x): each follows its axis'
/// diameter mode (§4.3, Q-11) [F].
Vec2 allowance(const TurningWords& w);
/// F > 0, else error 2004 (or 2021 for a thread lead) at the block.
bool checkFeed(double f, const TurningWords& w, bool lead, diag::Engine& diags);
/// CYC-PARAM at word c (or the block).
void paramError(const TurningWords& w, char c, const std::string& why, diag::Engine& diags);

} // namespace gcx::cycles
