#include "dialects/fms3000/code_rules.h"

#include <fmt/format.h>
#include <string_view>

#include "diag/codes.h"
#include "dialects/fms3000/block_rules.h"

namespace gcx::fms3000 {

namespace {

const ir::Word* findG(const ir::Block& b, double code) {
  for (const ir::Word& w : b.words)
    if (w.is('G') && w.number == code) return &w;
  return nullptr;
}

bool isAxisWord(const ir::Word& w) {
  return w.address.size() == 1 &&
         std::string_view("XYZUVWABC").find(w.address[0]) != std::string_view::npos;
}

// M00 M01 M02 M30 M98 M99: stop, end or return; one of them per block (001:3717, 001:3897)
bool isEndCode(const ir::Word& w) {
  return w.is('M') && (w.number == 0 || w.number == 1 || w.number == 2 || w.number == 30 ||
                       w.number == 98 || w.number == 99);
}

} // namespace

bool checkMotionCodeRules(const ir::Block& b, diag::Engine& diags) {
  if (const ir::Word* g45 = findG(b, 45))
    diags.warning(diag::code::FmsDependentAxes, g45->range,
                  "G45 (dependent axes accounted together) is not modelled: gcx moves every axis "
                  "as programmed, as under G46 (fms3000.md §10 Q25, 001:506-520)");
  const ir::Word* g27 = findG(b, 27);
  if (!g27) return true;
  for (const ir::Word& w : b.words)
    if (w.is('I') || w.is('J') || w.is('K')) {
      diags.error(diag::code::FmsMotionCodeWords, w.range,
                  fmt::format("G27 with {}: homing takes only the axis letters (\"G27 с I J K\", "
                              "001:3799)",
                              w.address));
      return false;
    }
  for (const ir::Word& w : b.words)
    if (isAxisWord(w)) return true;
  diags.error(diag::code::FmsMotionCodeWords, g27->range,
              "G27 without axes: write the axes to home, e.g. G27 X0 Y0 (\"G27 без координат\", "
              "001:3797)");
  return false;
}

bool checkProgramEndRules(const ir::Block& b, diag::Engine& diags) {
  const ir::Word* end = nullptr;
  for (const ir::Word& w : b.words) {
    if (!isEndCode(w)) continue;
    if (end) {
      diags.error(diag::code::FmsProgramRule, w.range,
                  fmt::format("M{} and M{} in one block: M00, M01, M02, M30, M98 and M99 exclude "
                              "each other (001:3717, 001:3897)",
                              end->text, w.text));
      return false;
    }
    end = &w;
  }
  bool cycle = false; // after a cycle code P is a parameter (§5.1)
  const ir::Word* call = nullptr;
  for (const ir::Word& w : b.words) {
    if (w.is('G') && isCycleCode(w.number)) {
      if (call) {
        diags.error(diag::code::FmsProgramRule, w.range,
                    fmt::format("P{} and the cycle G{} in one block: a block calls at most one "
                                "program or cycle (001:3815)",
                                call->text, w.text));
        return false;
      }
      cycle = true;
    }
    if (!w.is('P') || cycle) continue;
    if (end && end->number == 99) {
      diags.error(diag::code::FmsProgramRule, w.range,
                  fmt::format("P{} in an M99 block: the return takes no call (001:3768)", w.text));
      return false;
    }
    if (call) {
      diags.error(diag::code::FmsProgramRule, w.range,
                  fmt::format("P{} and P{} in one block: a block calls at most one program "
                              "(001:3815)",
                              call->text, w.text));
      return false;
    }
    call = &w;
  }
  return true;
}

} // namespace gcx::fms3000
