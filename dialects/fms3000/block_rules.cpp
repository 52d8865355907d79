#include "dialects/fms3000/block_rules.h"

#include <algorithm>
#include <fmt/format.h>

#include "diag/codes.h"
#include "dialects/fms3000/code_rules.h"

namespace gcx::fms3000 {

namespace {

bool whole(const ir::Word& w) {
  return w.text.find('.') == std::string::npos && w.text.find_first_of("+-") == std::string::npos;
}

// G: 1-3 digits, 0..255 (Table 3, 001:297, 001:3771); GG alike
bool checkGWord(const ir::Word& w, diag::Engine& diags) {
  if (whole(w) && w.text.size() <= 3 && w.number <= 255) return true;
  diags.error(diag::code::DataOutOfRange, w.range,
              fmt::format("{}{} is no G function: it takes 1-3 digits, 0-255 (fms3000.md §1.2)",
                          w.address, w.text));
  return false;
}

// P as a call: a program name of 1-4 digits, kept as written (001:292, 001:3748)
bool checkCallWord(const ir::Word& w, diag::Engine& diags) {
  if (whole(w) && w.text.size() <= 4) return true;
  diags.error(
      diag::code::DataOutOfRange, w.range,
      fmt::format("P{} is no program name: a call takes 1-4 digits (fms3000.md §1.2)", w.text));
  return false;
}

bool hasG(const ir::Block& b, double code) {
  for (const ir::Word& w : b.words)
    if (w.is('G') && w.number == code) return true;
  return false;
}

// The Fanuc habits of fms3000.md §9 that mean something else here: a warning naming the
// likely intent, beside whatever the FMS-3000 meaning or error is.
void warnFanucHabits(const ir::Block& b, diag::Engine& diags) {
  const ir::Word* p = b.find('P');
  const ir::Word* g10 = nullptr;
  const ir::Word* g4 = nullptr;
  const ir::Word* m98 = nullptr;
  const ir::Word* drill = nullptr;
  for (const ir::Word& w : b.words) {
    if (w.is('G') && w.number == 10) g10 = &w;
    if (w.is('G') && w.number == 4) g4 = &w;
    if (w.is('G') && w.number >= 81 && w.number <= 88) drill = &w;
    if (w.is('M') && w.number == 98) m98 = &w;
  }
  if (g10 && (b.find('L') || !(hasG(b, 2) || hasG(b, 3))))
    diags.warning(diag::code::FmsFanucHabit, g10->range,
                  "G10 is helical interpolation with G02/G03 in FMS-3000; Fanuc's data setting "
                  "G10 L_ P_ does not exist (fms3000.md §3.6, §9)");
  if (m98 && p)
    diags.warning(diag::code::FmsFanucHabit, m98->range,
                  fmt::format("M98 ends the program in FMS-3000; the Fanuc call 'M98 P{0}' is "
                              "written 'P{0}' alone (fms3000.md §2.2, §9)",
                              p->text));
  if (g4 && p && !b.find('E'))
    diags.warning(diag::code::FmsFanucHabit, p->range,
                  fmt::format("G04 dwells E tenths of a second in FMS-3000 (G04 E5 = 0.5 s); "
                              "P{} is the Fanuc dwell and here calls a program (fms3000.md §3.9)",
                              p->text));
  if (drill) {
    const ir::Word* r = b.find('R');
    const ir::Word* fanuc = r;
    for (const ir::Word& w : b.words)
      if (w.is('G') && (w.number == 98 || w.number == 99)) fanuc = &w;
    if (fanuc)
      diags.warning(diag::code::FmsFanucHabit, fanuc->range,
                    fmt::format("'{}{}' is a Fanuc cycle word: FMS-3000 cycles take the levels "
                                "U (start of feed), Z (bottom) and I (exit), and have no R level "
                                "or G98/G99 (fms3000.md §5.1, §9)",
                                fanuc->address, fanuc->text));
  }
}

// At most one of the codes that set or move to points per block (001:3849-3870, [D] for the
// pairs the manual does not list); cycles are forbidden under G20 (001:3912); G166/G167 take
// exactly one of X and Z (001:3914).
bool checkCodeCombinations(const ir::Block& b, diag::Engine& diags) {
  static constexpr double exclusive[] = {20, 27, 28, 30, 31, 47, 48, 60, 67, 68, 69, 92};
  const ir::Word* first = nullptr;
  for (const ir::Word& w : b.words) {
    if (!w.is('G')) continue;
    const bool one =
        std::find(std::begin(exclusive), std::end(exclusive), w.number) != std::end(exclusive);
    if (one && first) {
      diags.error(diag::code::ModalGroupConflict, w.range,
                  fmt::format("G{} and G{} exclude each other in one block (001:3849-3870)",
                              first->text, w.text));
      return false;
    }
    if (one) first = &w;
    if (isCycleCode(w.number) && hasG(b, 20) && w.number != 166 && w.number != 167) {
      diags.error(diag::code::FmsCycleParameters, w.range,
                  "cycles are forbidden in the arbitrary plane G20 (001:3912)");
      return false;
    }
    if (w.number == 166 || w.number == 167) {
      const bool x = b.find('X') != nullptr, z = b.find('Z') != nullptr;
      if (x == z) {
        diags.error(diag::code::FmsCycleParameters, w.range,
                    fmt::format("G{} takes exactly one of X and Z (001:3914)", w.text));
        return false;
      }
      if (!b.find('R')) {
        diags.error(diag::code::FmsCycleParameters, w.range,
                    fmt::format("G{} needs R, the chamfer or fillet size (001:3914)", w.text));
        return false;
      }
    }
  }
  return true;
}

bool hasCycleCode(const ir::Block& b) {
  for (const ir::Word& w : b.words)
    if (w.is('G') && isCycleCode(w.number)) return true;
  return false;
}

} // namespace

bool isCycleCode(double g) {
  return (g >= 81 && g <= 88) || (g >= 150 && g <= 167);
}

bool checkBlockRules(const ir::Block& b, diag::Engine& diags) {
  warnFanucHabits(b, diags);
  if (!checkCodeCombinations(b, diags)) return false;
  if (!checkMotionCodeRules(b, diags) || !checkProgramEndRules(b, diags)) return false;
  // a call and a program end in one block: the manual gives no order (§1.4, §10 Q21), so gcx
  // refuses rather than guess (with the Fanuc warning above for M98 P)
  if (const ir::Word* p = b.find('P'); p && !hasCycleCode(b))
    for (const ir::Word& w : b.words)
      if (w.is('M') && (w.number == 2 || w.number == 30 || w.number == 98)) {
        diags.error(diag::code::FmsCallAndEnd, p->range,
                    fmt::format("P{} calls a program in a block that ends the program (M{}); the "
                                "manual gives no order: write the call in a block of its own "
                                "(fms3000.md §1.4)",
                                p->text, w.text));
        return false;
      }
  bool ok = true;
  bool cycle = false; // a word after a cycle code is its parameter (§5.1, §6.3)
  bool dwell = false;
  const ir::Word* g25 = nullptr;
  const ir::Word* e = nullptr;
  for (const ir::Word& w : b.words) {
    if (w.address == "G" || w.address == "GG") {
      ok &= checkGWord(w, diags);
      cycle |= isCycleCode(w.number);
      dwell |= w.number == 4;
      if (w.number == 25) g25 = &w;
    } else if (w.is('P') && !cycle) {
      ok &= checkCallWord(w, diags);
    } else if (w.is('E') && !cycle && !e) {
      e = &w;
    } else if (w.is('L')) {
      // `G25 L_`: G25 before L, and L ends the block (001:368-372)
      if (!g25) {
        diags.error(diag::code::SyntaxError, w.range,
                    "L is the repeat count of G25 and must follow it (fms3000.md §6.2)");
        ok = false;
      } else if (&w != &b.words.back()) {
        diags.error(diag::code::SyntaxError, w.range,
                    "'G25 L_' must end its block (fms3000.md §6.2)");
        ok = false;
      }
    }
  }
  if (g25 && !b.find('L')) {
    diags.error(diag::code::MissingData, g25->range,
                "G25 without L: the repeat count is required (\"Требуется параметр\", 001:3899)");
    ok = false;
  }
  if (e && !dwell)
    diags.warning(
        diag::code::FmsUnusedE, e->range,
        fmt::format("E{} is unused: E is the G04 dwell or a cycle parameter, and FMS-3000 "
                    "numbers have no exponent (fms3000.md §1.2)",
                    e->text));
  return ok;
}

} // namespace gcx::fms3000
