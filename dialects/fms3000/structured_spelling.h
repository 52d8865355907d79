// FMS-3000 as the target of a structured translation (translate/structured_spelling.h): P calls of
// programs named by their digits, each in a file of its own, and G25 L<n> ... M25 repeats; no
// variables, jumps or conditions.
#pragma once
#include "translate/structured_spelling.h"

namespace gcx::fms3000 {

const xlate::StructuredSpelling& structuredSpelling();

} // namespace gcx::fms3000
