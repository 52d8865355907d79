// The cycles library's modal memory as one channel keeps it: opaque to the interpreter's
// interface (interpreter.h declares it only), so the machine's users never see the cycles
// library, and a dialect's cycles change only the files that run them.
#pragma once
#include <memory>

#include "cycles/drilling_state.h"
#include "cycles/turning.h"

namespace gcx::machine {

struct CycleState {
  cycles::DrillModal drill;     // drilling cycle mode and its variables (cycles.md §2.4)
  cycles::TurningModal turning; // the first blocks' values of the turning cycles (§4.2)
};

} // namespace gcx::machine
