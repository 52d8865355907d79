// G, M and letter codes the machine parameters turn into calls (nct-macro.md §5.8): N1704-N1716
// G codes, N1720-N1745 M codes, N1746-N1754 letters.
#pragma once
#include <optional>

#include "dialect/control_flow.h"

namespace gcx::nct {

/// The configured call a flat block makes, nullopt if none; two in one block report NCTX09
/// (§5.8 P6) and return nullopt.
std::optional<ConfiguredCall> configuredCall(const ir::Block& flat, const ParameterLookup& param,
                                             diag::Engine& diags);

} // namespace gcx::nct
