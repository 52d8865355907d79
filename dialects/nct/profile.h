// The NCT milling-channel profile (nct.md §1.3, §2.1; nct-macro.md §1.2).
#pragma once
#include "dialect/profile.h"

namespace gcx::nct {

const Profile& profile();

} // namespace gcx::nct
