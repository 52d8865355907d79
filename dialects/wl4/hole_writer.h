// WL4's canned cycles %81-%89 as the target of a kept hole (translate/hole_lowering.h).
#pragma once
#include <memory>

#include "translate/hole_lowering.h"

namespace gcx::wl4 {

std::unique_ptr<xlate::HoleLowering> makeHoleWriter();

} // namespace gcx::wl4
