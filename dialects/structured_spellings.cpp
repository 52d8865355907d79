// The structured spellings of the target dialects (translate/structured_spelling.h).
#include "dialects/fms3000/structured_spelling.h"
#include "dialects/nct/structured_spelling.h"
#include "dialects/wl4/structured_spelling.h"

namespace gcx::xlate {

const StructuredSpelling* structuredSpellingFor(std::string_view dialect) {
  if (dialect == "nct") return &nct::structuredSpelling();
  if (dialect == "fms3000") return &fms3000::structuredSpelling();
  if (dialect == "wl4") return &wl4::structuredSpelling();
  return nullptr;
}

} // namespace gcx::xlate
