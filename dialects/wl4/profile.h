// The WL4 profile (wl4.md §1.4, §2): addresses, the G code table with its groups and actions,
// power-on state, machine rules and control flow.
#pragma once
#include "dialect/profile.h"

namespace gcx::wl4 {

const Profile& profile();

} // namespace gcx::wl4
