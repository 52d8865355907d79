// LinuxCNC RS274/NGC as the target of a structured translation from FMS-3000 or WL4
// (translate/structured_spelling.h): o-word subroutines before the main program in one file,
// o-word while and do loops, parameters, G81-G85 holes. NCT programs have their own writer
// (from_nct.h).
#pragma once
#include "translate/structured_spelling.h"

namespace gcx::ngc {

const xlate::StructuredSpelling& structuredSpelling();

} // namespace gcx::ngc
