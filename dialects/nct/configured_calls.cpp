#include "dialects/nct/configured_calls.h"

#include <cmath>
#include <fmt/format.h>

#include "diag/diagnostic.h"
#include "ir/block.h"

namespace gcx::nct {

std::optional<ConfiguredCall> configuredCall(const ir::Block& flat, const ParameterLookup& param,
                                             diag::Engine& diags) {
  auto prm = [&](int n) { return param(fmt::format("N{:04}", n), 0); };
  auto bit = [&](int n, int b, const char* name) {
    return param(fmt::format("N{:04}.{}", n, b), 0) == 1 ||
           param(fmt::format("N{:04}.{}", n, name), 0) == 1;
  };
  std::optional<ConfiguredCall> found;
  bool conflict = false;
  auto take = [&](ConfiguredCall::Kind kind, std::int64_t program, const ir::Word& w,
                  int valueVariable = 0) {
    if (found) {
      diags.error("NCTX09", w.range, "two codes configured as calls in one block (§5.8 P6)");
      conflict = true;
      return;
    }
    found = ConfiguredCall{kind, std::to_string(program), &w, valueVariable};
  };
  for (const ir::Word& w : flat.words) {
    if (w.kind != ir::ValueKind::Number || conflict) continue;
    if (w.is('G')) {
      for (int i = 0; i < 10; ++i) { // N1704-N1713: G(9010)...G(9019); 1000 means G0
        const double v = prm(1704 + i);
        if (v == 0) continue;
        const double code = std::fabs(v) == 1000 ? 0 : std::fabs(v);
        if (w.number == code)
          take(v < 0 ? ConfiguredCall::ModalG : ConfiguredCall::MacroG, 9010 + i, w);
      }
      const double start = prm(1714), first = prm(1715), count = prm(1716);
      const double g = w.number;
      if (count > 0 && g == std::floor(g) && g >= std::fabs(start) && g < std::fabs(start) + count)
        take(start < 0 ? ConfiguredCall::ModalG : ConfiguredCall::MacroG,
             static_cast<std::int64_t>(first + g - std::fabs(start)), w);
    } else if (w.is('M')) {
      const double m = w.number;
      for (int i = 0; i < 10; ++i) {
        if (prm(1733 + i) != 0 && prm(1733 + i) == m) take(ConfiguredCall::MacroM, 9020 + i, w);
        if (prm(1720 + i) != 0 && prm(1720 + i) == m)
          take(ConfiguredCall::SubprogramM, 9000 + i, w);
      }
      if (const double c = prm(1745); c > 0 && m >= prm(1743) && m < prm(1743) + c)
        take(ConfiguredCall::MacroM, static_cast<std::int64_t>(prm(1744) + m - prm(1743)), w);
      if (const double c = prm(1732); c > 0 && m >= prm(1730) && m < prm(1730) + c)
        take(ConfiguredCall::SubprogramM, static_cast<std::int64_t>(prm(1731) + m - prm(1730)), w);
    } else if (w.address.size() == 1) { // N1746 ABCST: A B C S T call O9030-O9034
      static const char letters[] = {'A', 'B', 'C', 'S', 'T'};
      static const char* const names[] = {"AM", "BM", "CM", "SM", "TM"};
      for (int i = 0; i < 5; ++i)
        if (w.address[0] == letters[i] && bit(1746, i, names[i]))
          take(ConfiguredCall::SubprogramLetter, 9030 + i, w, 195 + i);
      // N1747-N1750: four letters (their ASCII codes) calling the programs of N1751-N1754,
      // the value in #191-#194
      for (int i = 0; i < 4; ++i)
        if (prm(1747 + i) == static_cast<unsigned char>(w.address[0]) && prm(1751 + i) > 0)
          take(ConfiguredCall::SubprogramLetter, static_cast<std::int64_t>(prm(1751 + i)), w,
               191 + i);
    }
  }
  if (conflict) return std::nullopt;
  return found;
}

} // namespace gcx::nct
