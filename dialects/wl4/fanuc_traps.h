// Habits of Fanuc-style programs that mean something else in WL4 (wl4.md §9): each read block
// is checked and a warning names the likely Fanuc intent next to the WL4 meaning.
#pragma once
#include "diag/diagnostic.h"
#include "ir/block.h"

namespace gcx::wl4 {

void warnFanucTraps(const ir::Block& b, diag::Engine& diags);

} // namespace gcx::wl4
