#include "dialects/wl4/fanuc_traps.h"

#include <cmath>
#include <fmt/format.h>
#include <string_view>

#include "diag/codes.h"

namespace gcx::wl4 {

namespace {

bool dimension(const ir::Word& w) {
  return w.address.size() == 1 &&
         std::string_view("XYZUVWIJKR").find(w.address[0]) != std::string_view::npos;
}

} // namespace

void warnFanucTraps(const ir::Block& b, diag::Engine& diags) {
  for (const ir::Word& w : b.words) {
    if (!w.isLiteral()) continue;
    // a number without a point is whole millimetres (§1.5); Fanuc reads it in 0.001 mm
    if (dimension(w) && w.text.find('.') == std::string::npos && std::fabs(w.number) >= 1000)
      diags.warning(diag::code::Wl4WholeMillimetres, w.range,
                    fmt::format("{}{} is {} mm in WL4: a number without a point is whole "
                                "millimetres; a Fanuc program would mean {} mm (write {}{:.3f})",
                                w.address, w.text, w.text, w.number / 1000, w.address,
                                w.number / 1000));
    if (w.is('G') && (w.number == 98 || w.number == 99))
      diags.warning(diag::code::Wl4FanucReturnLevel, w.range,
                    fmt::format("G{} is no WL4 code: a WL4 cycle has no return level, the tool "
                                "stays at #2 (Fanuc G98/G99, wl4.md §5.2)",
                                w.text));
    if (w.is('M') && w.number == 98)
      diags.warning(diag::code::Wl4FanucCall, w.range,
                    "M98 calls nothing in WL4 (a machine M code): call program %nn with L nn or "
                    "L nnpp (Fanuc M98 P, wl4.md §6.7)");
  }
}

} // namespace gcx::wl4
