// Mirroring by the sign of an axis word (WL4 G51, wl4.md §3.13-§3.14): `G51 X-1` mirrors X about
// the work system's zero, `G51 X1` ends it, `G51 S2000` limits the spindle speed instead.
#include <fmt/format.h>

#include "diag/codes.h"
#include "machine/code_names.h"
#include "machine/interpreter.h"

namespace gcx::machine {

bool Interpreter::mirrorBySign(const BlockWords& w) {
  const std::string code = gName(*w.findAction(GAction::MirrorBySign));
  if (w.s) {
    if (w.hasAxisWord())
      return fail(diag::code::ForbiddenAddress, w.s->range,
                  fmt::format("{0} S (spindle limit) and {0} mirror words in one block (wl4.md "
                              "§3.14)",
                              code));
    state_.maxSpindleSpeed = w.s->number;
    return true;
  }
  unsigned on = 0, off = 0;
  for (int a = 0; a < 3; ++a) {
    const ir::Word* x = w.axis[a];
    if (!x) continue;
    if (x->number != 1 && x->number != -1)
      return fail(diag::code::DataOutOfRange, x->range,
                  fmt::format("{0} {1}{2}: an axis word of {0} is -1 (mirror on) or 1 (off) "
                              "(wl4.md §3.13)",
                              code, x->address, x->number));
    (x->number < 0 ? on : off) |= 1u << a;
  }
  if (off) transforms_.cancelMirror(off);
  if (on) transforms_.mirror(on, Vec3::Zero());
  return true;
}

} // namespace gcx::machine
