// IR blocks as WL4 text (wl4.md §1, §6.8): words, expressions in WL4's spelling, assignments,
// guards, jumps, L calls, comments and messages, in the block's source order.
#pragma once
#include <string>

#include "ir/block.h"

namespace gcx::wl4 {

std::string printBlock(const ir::Block& b);
std::string printExpr(const ir::Expr& e);

} // namespace gcx::wl4
