// NCT as the target of a structured translation (translate/structured_spelling.h): WHILE loops,
// GOTO jumps to block numbers, M98 P calls, O-numbered programs in files of their own.
#pragma once
#include <string>

#include "translate/structured_spelling.h"

namespace gcx::nct {

const xlate::StructuredSpelling& structuredSpelling();

/// O0001-O9999 (nct.md §1.1): the number in a program's name (O1001.nct, FMS-3000's 0019.fms),
/// else 1.
int programNumber(const std::string& name);

} // namespace gcx::nct
