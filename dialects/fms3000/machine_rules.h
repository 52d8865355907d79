// How the machine model reads FMS-3000 words and settings (fms3000.md §0, §1.4, §2.2, §3).
#pragma once
#include "dialect/machine_rules.h"

namespace gcx::fms3000 {

MachineRules machineRules();

} // namespace gcx::fms3000
