// NCT's control flow (nct-macro.md §2-§6, nct.md §5): its remap table, variables, argument
// binding, message variables and program files, as the control-flow engine reads them.
#pragma once
#include <vector>

#include "dialect/control_flow.h"
#include "dialect/profile.h"

namespace gcx::nct {

/// The remap rows of M98/M99 and G65/G66/G66.1/G67, with a CallCycle row per cycle macro.
RemapTable remapTable(const std::vector<CycleMacro>& cycleMacros);
/// NCT's control flow; `cycleMacros` are the profile's system cycles written as macros.
const ControlFlow& controlFlow(const std::vector<CycleMacro>& cycleMacros);

} // namespace gcx::nct
