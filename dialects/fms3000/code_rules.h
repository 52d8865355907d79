// The block rules of FMS-3000's one-block codes and of its program ends, checked as a block is
// read: G27 needs axes and no I J K (001:3797-3799), G45 is not modelled (§10 Q25); the program
// end codes exclude each other (001:3717, 001:3897), M99 takes no P (001:3768), and a block
// calls at most one program or cycle (001:3815).
#pragma once
#include "diag/diagnostic.h"
#include "ir/block.h"

namespace gcx::fms3000 {

/// False after reporting an error; the G45 warning leaves the block valid.
bool checkMotionCodeRules(const ir::Block& b, diag::Engine& diags);
bool checkProgramEndRules(const ir::Block& b, diag::Engine& diags);

} // namespace gcx::fms3000
