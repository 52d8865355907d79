// Without LinuxCNC's `rs274`, gcx reads only the canonical RS274/NGC it writes itself
// (docs/canonical.md): plain G0-G4 motion, planes, units, feeds, S/M3-M5, T M6, M7-M9, M0/M1,
// M2/M30. This finds the first construct of full LinuxCNC beyond that subset (O-word
// subroutines and loops, parameters and expressions, canned cycles, cutter compensation) and
// reports it with a located error that says how to install rs274.
#pragma once
#include <string_view>

#include "diag/diagnostic.h"

namespace gcx::equiv {

/// False (and a GCX050 error at the construct) when the text needs LinuxCNC's interpreter.
bool checkCanonicalSubset(std::string_view text, FileId file, diag::Engine& diags);

} // namespace gcx::equiv
