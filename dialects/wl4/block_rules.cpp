#include "dialects/wl4/block_rules.h"

#include <fmt/format.h>

#include "diag/codes.h"

namespace gcx::wl4 {

bool checkBlockRules(const ir::Block& b, diag::Engine& diags) {
  // in a G76 block U W are the initial allowance, not increments (§5.6, 002:2918-2919)
  for (const ir::Word& w : b.words)
    if (w.is('G') && w.isLiteral() && w.number == 76) return true;
  const char* absolute = "XYZ";
  const char* relative = "UVW";
  for (int a = 0; a < 3; ++a) {
    const ir::Word* x = b.find(absolute[a]);
    const ir::Word* u = b.find(relative[a]);
    if (!x || !u) continue;
    const ir::Word* later = u->order > x->order ? u : x;
    diags.error(diag::code::Wl4AbsoluteAndIncremental, later->range,
                fmt::format("{} and {} in one block: the axis is either absolute ({}) or "
                            "incremental ({}), not both (wl4.md §3.2)",
                            absolute[a], relative[a], absolute[a], relative[a]));
    return false;
  }
  return true;
}

} // namespace gcx::wl4
