// What WL4's words mean to the machine model (wl4.md §2.3, §3): M codes and their timing, the
// dwell word, block skip's sense, the work offsets.
#pragma once
#include "dialect/machine_rules.h"

namespace gcx::wl4 {

MachineRules machineRules();

} // namespace gcx::wl4
