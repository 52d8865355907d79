// The FMS-3000 profile (fms3000.md §1.2 address table, §2.1 G codes, §2.2 M codes).
#pragma once
#include "dialect/profile.h"

namespace gcx::fms3000 {

const Profile& profile();

} // namespace gcx::fms3000
