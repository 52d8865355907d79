// WL4 as the target of a structured translation (translate/structured_spelling.h): loops as labels
// and IF jumps, L calls of two-digit %-programs, every program of the result in one file.
#pragma once
#include <string>

#include "translate/structured_spelling.h"

namespace gcx::wl4 {

const xlate::StructuredSpelling& structuredSpelling();

/// `%NAME` of a main program (wl4.md §1.2): the source's name in upper case (lower case is no
/// program text, §1.1) when it is one WL4 allows for a main program (letters, digits and `_`, at
/// most 80, not the one- and two-digit names of subprograms), else MAIN.
std::string mainProgramName(const std::string& name);

} // namespace gcx::wl4
