// LinuxCNC RS274/NGC as a target: its codes by meaning, the order it acts in, its parameters
// (LinuxCNC's "G-Code Overview", "O Codes" and "Numbered Parameters" chapters). Not a source
// dialect: gcx reads a LinuxCNC program through rs274 (docs/equivalence.md).
#pragma once
#include "dialect/profile.h"

namespace gcx::ngc {

const Profile& profile();

} // namespace gcx::ngc
