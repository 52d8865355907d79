// IR printed back as FMS-3000 text (gcx fmt): `N`, then the words in source order with their
// texts as written (P019 stays P019), `rem` comment lines and `endcont`. Reading the output
// again gives the same IR.
#pragma once
#include <string>

#include "ir/block.h"

namespace gcx::fms3000 {

/// One block, without its line end.
std::string printBlock(const ir::Block& b);

} // namespace gcx::fms3000
