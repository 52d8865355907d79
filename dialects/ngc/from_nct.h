// NCT programs as structured LinuxCNC RS274/NGC (docs/translation.md, "ngc: what is kept"):
// cycles G73 G81 G82 G83 G85 G89 as LinuxCNC's, M98 subprograms and G65 macros as o-word
// subroutines, WHILE loops as o-word while, IF THEN as o-word if, variables #1-#33, #100-#199
// and #500-#999 with their expressions.
#pragma once
#include "dialects/ngc/structured.h"

namespace gcx::ngc {

bool writeFromNct(const std::vector<ir::Block>& main, const FindProgram& find, Structured& out,
                  Unkept& unkept);

} // namespace gcx::ngc
