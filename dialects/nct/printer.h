// IR printed back as normalised NCT text (gcx fmt). Reading the output again gives the same IR.
#pragma once
#include <string>

#include "ir/block.h"

namespace gcx::nct {

std::string printExpr(const ir::Expr& e);
/// One block, without the trailing LF.
std::string printBlock(const ir::Block& b);

} // namespace gcx::nct
