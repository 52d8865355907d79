// Loops whose count is known from their text, for a target that repeats a fragment a given number
// of times but has no variables (FMS-3000 G25 L<n> ... M25): a counter set to a number, a WHILE
// on it or a jump back while it holds, the counter stepped by a number at the end of the body and
// read nowhere else. Each becomes RepeatStart / RepeatEnd with its count; the counter goes.
#pragma once
#include "translate/steps.h"

namespace gcx::xlate {

/// Rewrites the counted loops of `unit` as repeats; returns how many it rewrote. Loops of another
/// shape are left as they are (the writer then says why the target cannot keep them).
int countedLoopsAsRepeats(UnitSteps& unit);

/// Rewrites each jump back to a label, taken while a condition holds, as a do-while loop over the
/// steps from the label to the jump (DoStart / DoEnd), for a target that has such loops but no
/// jumps (LinuxCNC `o.. do` ... `o.. while`); returns how many. A jump that other jumps cross is
/// left as it is.
int backwardJumpsAsDoLoops(UnitSteps& unit);

} // namespace gcx::xlate
