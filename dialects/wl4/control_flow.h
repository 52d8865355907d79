// WL4's control flow (wl4.md §5.1, §6): `%name` units, L calls with a copy of the caller's
// locals, M99 returns, the user canned cycles G81-G89 as modal calls of %81-%89, labels.
#pragma once
#include <string_view>

#include "dialect/control_flow.h"
#include "ir/block.h"

namespace gcx::wl4 {

const ControlFlow& controlFlow();
/// A block number written with a leading 0 is a label a jump reaches (`N010`, §1.8).
bool isLabel(std::string_view sequenceText);
/// G4 X (a dwell), G36 (home), G51 X-1 (mirror), G92 (set coordinates): the block's axis words
/// are no move (§3.7, §3.9, §3.11, §3.13).
bool axisWordsNoMove(const ir::Block& flat);

} // namespace gcx::wl4
