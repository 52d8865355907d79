// LinuxCNC's drilling cycles as the target of a kept hole (translate/hole_lowering.h).
#pragma once
#include <memory>

#include "translate/hole_lowering.h"

namespace gcx::ngc {

std::unique_ptr<xlate::HoleLowering> makeHoleWriter();

} // namespace gcx::ngc
