// FMS-3000's control flow (fms3000.md §1.3, §6.1): its remap table and program files, as the
// control-flow engine reads them (docs/control-flow.md).
#pragma once
#include "dialect/control_flow.h"

namespace gcx::fms3000 {

/// `P<digits>` calls, M99 returns, M98 ends, user G programs and `GG<n>` built-ins (§6.1).
RemapTable remapTable();
const ControlFlow& controlFlow();

} // namespace gcx::fms3000
