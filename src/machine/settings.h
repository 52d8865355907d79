// Machine settings by meaning: the dialect's profile names the setup key of each one
// (dialect/machine_rules.h), so the machine never spells a dialect's parameter numbers.
#pragma once
#include "cycles/drilling_state.h"
#include "dialect/profile.h"
#include "machine/setup.h"

namespace gcx::machine {

/// The setting's value: the setup's value under the dialect's key, else under its alias, else
/// the dialect's fallback; `absent` when the dialect has no such setting.
double setting(const Profile& profile, const Setup& setup, Setting which, double absent = 0);
/// How messages name the setting ("" when the dialect has none).
const char* settingLabel(const Profile& profile, Setting which);
/// The setup key of the setting, or null.
const char* settingKey(const Profile& profile, Setting which);
/// The drilling cycles' machine settings (cycles.md §2.8).
cycles::DrillConfig drillConfig(const Profile& profile, const Setup& setup);

} // namespace gcx::machine
