// Calls of system cycles written as macro programs (the profile's cycleMacros, cycles.md §5;
// the remap table's CallCycle rows): the bridge between the expander and the cycle's own checks.
#pragma once
#include <vector>

#include "dialect/profile.h"
#include "machine/interpreter.h"
#include "passes/macro/program_library.h"
#include "passes/macro/value.h"

namespace gcx::macro {

struct CycleMacroSite {
  const ir::Block& block;         // the call as written
  const ir::Word& callWord;       // its call code
  const ir::Word& p;              // its program word
  const std::vector<Value>& args; // the bound local frame
  const LoadedProgram& caller;
};

/// Runs the cycle's argument check in the machine's current plane, units and tool table, then
/// reports cycle.missingCode at P, naming the folders searched, when its program is not found.
/// False after a located error.
bool checkCycleMacroCall(const CycleMacro& cycle, const CycleMacroSite& site,
                         const machine::Interpreter& machine, const ProgramLibrary& library,
                         diag::Engine& diags);

} // namespace gcx::macro
