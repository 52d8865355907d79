// The rules of an FMS-3000 block beyond its syntax, checked as it is read (fms3000.md §1.2,
// §6.2, §6.3, §8 negative vectors): G numbers, call names, G25 L, an E without a use.
#pragma once
#include "diag/diagnostic.h"
#include "ir/block.h"

namespace gcx::fms3000 {

/// False after reporting an error; warnings leave the block valid.
bool checkBlockRules(const ir::Block& b, diag::Engine& diags);

/// True for the codes whose following words are cycle parameters (G81-G88, G150-G167).
bool isCycleCode(double g);

} // namespace gcx::fms3000
