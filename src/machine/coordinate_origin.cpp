// The set-coordinates words as an origin rather than the tool's position (FMS-3000 G92 with
// its G92 meaning parameter 1 or 2, fms3000.md §3.10): with 1 the words place the new system's
// origin in machine coordinates, like a stored work offset (the operator's common offset still
// adds); with 2 they shift the current origin, and successive shifts add up.
#include "diag/codes.h"
#include "machine/interpreter.h"

namespace gcx::machine {

bool Interpreter::setCoordinateOrigin(const BlockWords& w, bool additive) {
  const Vec3 stored = currentWorkOffset();
  for (int a = 0; a < 3; ++a) {
    if (w.uvw[a])
      return fail(diag::code::IllegalIncremental, w.uvw[a]->range,
                  "the set-coordinates words are absolute only");
    if (!w.axis[a]) continue;
    const double v = mm(w.axis[a]->number);
    offsets_.g52[a] = 0;
    offsets_.g92[a] = additive ? offsets_.g92[a] + v : v - stored[a];
  }
  reexpress();
  return true;
}

} // namespace gcx::machine
