#include "dialects/wl4/word_value_rules.h"

namespace gcx::wl4 {

/// "Values used as addresses are converted to the address type" (002:1799-1803): integer
/// addresses G M N L T D H S round half away from zero (`G#29` with 90 -> G90), dimension words
/// and F E P R to 0.001 (wl4.md §6.1 [D]). The manual gives no ranges for computed values.
WordValueRules wordValueRules() {
  constexpr double any = anyValue;
  WordValueRules r;
  for (std::string_view a : {"G", "M", "N", "L", "T", "D", "H", "S"})
    r.rows.push_back({a, false, Rounding::Integer, -any, any});
  for (std::string_view a :
       {"X", "Y", "Z", "U", "V", "W", "A", "B", "C", "I", "J", "K", "R", "F", "E", "P"})
    r.rows.push_back({a, false, Rounding::Resolution, -any, any});
  r.coordinateLetters = "XYZUVWABC"; // the axis words (a block with one calls a modal cycle)
  r.coordinateRow = "X";
  r.resolution = 0.001;
  r.reference = "wl4.md §6.1";
  return r;
}

} // namespace gcx::wl4
