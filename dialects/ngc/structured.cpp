#include "dialects/ngc/structured.h"

#include "dialects/ngc/from_nct.h"

namespace gcx::ngc {

StructuredWriter structuredWriter(const Dialect& source) {
  if (source.name == "nct") return &writeFromNct;
  return nullptr; // FMS-3000 and WL4 are written flat
}

} // namespace gcx::ngc
