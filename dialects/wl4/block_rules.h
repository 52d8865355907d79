// Rules of one WL4 block that the parser leaves to the checks (wl4.md §3.2): an axis written
// absolute and incremental in the same block (X with U, Y with V, Z with W) is an error [D].
#pragma once
#include "diag/diagnostic.h"
#include "ir/block.h"

namespace gcx::wl4 {

/// False after reporting the block's first broken rule at its word.
bool checkBlockRules(const ir::Block& b, diag::Engine& diags);

} // namespace gcx::wl4
