// FMS-3000's level drilling cycles as the target of a kept hole (translate/hole_lowering.h).
#pragma once
#include <memory>

#include "translate/hole_lowering.h"

namespace gcx::fms3000 {

std::unique_ptr<xlate::HoleLowering> makeHoleWriter();

} // namespace gcx::fms3000
