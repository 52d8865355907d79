// GOTO and IF GOTO: label resolution by block number (nct-macro.md §4.1 G5: from the block
// after the jump to the end, then from the start) and the loops a jump leaves.
#include <fmt/format.h>

#include "diag/codes.h"
#include "emit/number.h"
#include "passes/macro/expander.h"

namespace gcx::macro {

bool Expander::jumpTo(Frame& f, const ir::Expr& label, const SourceRange& where) {
  auto v = eval_.value(label);
  if (!v) return false;
  if (v->vacant)
    return fail(diag::code::BlockNotFound, where, "GOTO to a vacant block number (§2.5 rule 5)");
  const double n = roundHalfAway(v->number);
  const Profile& profile = machine_.profile(); // its N range; no int64 overflow
  const auto first = static_cast<double>(profile.minSequenceNumber),
             last = static_cast<double>(profile.maxSequenceNumber);
  const bool inRange = n >= first && n <= last;
  if (!inRange && n > 0)
    return fail(diag::code::BlockNotFound, where,
                fmt::format("block N{:g} not found: block numbers are {}-{}", n,
                            profile.minSequenceNumber, profile.maxSequenceNumber));
  const std::size_t target =
      inRange ? f.program->find(static_cast<std::int64_t>(n), f.pc + 1) : LoadedProgram::npos;
  if (target == LoadedProgram::npos)
    return fail(diag::code::BlockNotFound, where,
                fmt::format("block N{} not found", emit::formatNumber(n)));
  if (target <= f.pc && ++jumps_ > limits_.maxJumps)
    return fail(diag::code::RunawayLoop, where,
                fmt::format("more than {} backward jumps: runaway loop (GOTO N{}; exceeded "
                            "--max-jumps {}; raise it with --max-jumps N)",
                            limits_.maxJumps, emit::formatNumber(n), limits_.maxJumps));
  f.pc = target;
  // loops the jump left are over
  std::erase_if(f.loops, [&](const Loop& l) {
    return target < l.head || target > f.program->loopPartner[l.head];
  });
  return true;
}

} // namespace gcx::macro
