// G65 calls of system cycles written as macro programs (the profile's cycleMacros, e.g. NCT
// G65 P9999, cycles.md §5): the bridge between the expander and the cycle's own checks.
#pragma once
#include <array>

#include "dialect/profile.h"
#include "machine/interpreter.h"
#include "passes/macro/program_library.h"
#include "passes/macro/value.h"

namespace gcx::macro {

struct CycleMacroSite {
  const ir::Block& block;            // the call as written
  const ir::Word& p;                 // its P word
  const std::array<Value, 34>& args; // bound #1..#33
  const LoadedProgram& caller;
};

/// Runs the cycle's argument check in the machine's current plane, units and tool table, then
/// reports cycle.missingCode at P, naming the folders searched, when its program is not found.
/// False after a located error.
bool checkCycleMacroCall(const CycleMacro& cycle, const CycleMacroSite& site,
                         const machine::Interpreter& machine, const ProgramLibrary& library,
                         diag::Engine& diags);

} // namespace gcx::macro
