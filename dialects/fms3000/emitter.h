// FMS-3000 as a target: blocks printed as FMS-3000 text (dialects/fms3000/printer.h), each
// ended by CR LF, the manual's block end (001:217-221).
#pragma once
#include <memory>
#include <ostream>

#include "emit/emitter.h"

namespace gcx::fms3000 {

/// The constructs gcx writes in FMS-3000 text: the cycles, P calls and G25 repeats.
emit::Capabilities emitterCapabilities();
std::unique_ptr<emit::ProgramEmitter> makeEmitter(std::ostream& out);

} // namespace gcx::fms3000
