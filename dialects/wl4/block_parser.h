// The WL4 block parser (wl4.md §1, §6.8; grammar/WL4.g4 is the normative syntax): one block's
// text in, one IR block out, every item at its byte offset so the block runs left to right.
#pragma once
#include "diag/diagnostic.h"
#include "front/raw_block.h"
#include "ir/block.h"

namespace gcx::wl4 {

/// Parses raw into out; false after reporting a located error (the block is then dropped).
bool parseBlock(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags);

} // namespace gcx::wl4
