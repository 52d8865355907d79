// NCT as a target: blocks printed as normalised NCT text (dialects/nct/printer.h).
#pragma once
#include <memory>
#include <ostream>

#include "emit/emitter.h"

namespace gcx::nct {

/// NCT text expresses every construct: G81-G89 and the turning cycles, M98/G65 calls, WHILE
/// loops, #variables and expressions, G66 modal calls (nct.md, nct-macro.md).
emit::Capabilities emitterCapabilities();
std::unique_ptr<emit::ProgramEmitter> makeEmitter(std::ostream& out);

} // namespace gcx::nct
