// NCT's machine rules: its parameter keys for the settings the core reads, its M codes, dwell
// and block-skip rules (nct.md §1.6, §2.2, §3; cycles.md §2.8).
#pragma once
#include "dialect/machine_rules.h"

namespace gcx::nct {

MachineRules machineRules();

} // namespace gcx::nct
