// The NCT pocket-milling macro cycle `G65 P9999` (cycles.md §5): the argument errors the manual
// lists (MACRO ERROR 1 and 2, 000:15782-15797). The toolpath is the macro program O9999's
// the expander inlines it like any G65 call, or stops with CYC-POCKET-MACRO-MISSING.
//
// Codes: the manual prints "MACRO ERROR 1/2" without an alarm number. A macro raises such
// errors with `#3000=n(text)`, which the control shows as alarm 4000+n (000:12121-12133), so
// gcx reports 4001 and 4002 [D] - the same codes a supplied O9999 doing `#3000=1` would give.
#pragma once
#include "diag/diagnostic.h"
#include "dialect/profile.h"

namespace gcx::cycles {

inline constexpr std::int64_t PocketMacroProgram = 9999; // G65 P9999 (000:15678)

/// Checks a `G65 P9999` call; reports one located error (4001 or 4002) and returns false when
/// the arguments are wrong. In G17 the depth is Z and the longer of X/Y the length, in G18 Y
/// and Z/X, in G19 X and Y/Z (000:15693-15702).
bool checkPocketCall(const CycleMacroCall& call, diag::Engine& diags);

/// The profile entry of the pocket cycle (NCT profile, cycleMacros).
CycleMacro pocketCycleMacro();

} // namespace gcx::cycles
