// The structures a program has, read from its blocks by meaning (the profile's cycle codes, the
// control-flow remap table, the statements), so a translation's note names only what the
// program holds, each with its block.
#pragma once
#include <string_view>
#include <vector>

#include "dialect/profile.h"
#include "ir/block.h"

namespace gcx::xlate {

enum class Structure : unsigned char { Cycle, Subprogram, Loop, Variable };

/// "cycles", "subprogram calls", "loops and jumps", "variables".
std::string_view structureName(Structure s);

struct StructureAt {
  Structure kind;
  SourceLoc at;
};

/// The structures of `blocks` in source order (one entry per kind and block).
std::vector<StructureAt> scanStructures(const std::vector<ir::Block>& blocks, const Profile& p);

} // namespace gcx::xlate
