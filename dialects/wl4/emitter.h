// `--to wl4` and `gcx fmt` for WL4: blocks as WL4 text inside `%name ... %` units (wl4.md §1.2).
#pragma once
#include <memory>
#include <ostream>

#include "emit/emitter.h"

namespace gcx::wl4 {

emit::Capabilities emitterCapabilities();
std::unique_ptr<emit::ProgramEmitter> makeEmitter(std::ostream& out);

} // namespace gcx::wl4
