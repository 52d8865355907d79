#include "cycles/pocket.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <optional>
#include <string>
#include <vector>

#include "diag/codes.h"
#include "emit/number.h"
#include "ir/block.h"

namespace gcx::cycles {

namespace {

// argument specification I (nct-macro.md §5.4)
constexpr int ArgD = 7, ArgE = 8, ArgQ = 17, ArgR = 18, ArgX = 24, ArgY = 25, ArgZ = 26;

struct PlaneAxes {
  int first, second, depth; // local numbers of the two plane sizes and the depth
};

PlaneAxes planeAxes(motion::Plane plane) {
  if (plane == motion::Plane::ZX) return {ArgZ, ArgX, ArgY};
  if (plane == motion::Plane::YZ) return {ArgY, ArgZ, ArgX};
  return {ArgX, ArgY, ArgZ};
}

char letterOf(int arg) {
  return arg == ArgX ? 'X' : arg == ArgY ? 'Y' : 'Z';
}

// The word an argument came from; the call code's word when it was not written.
const ir::Word* wordOf(const CycleMacroCall& c, char letter) {
  for (const ir::Word& w : c.block->words)
    if (w.is(letter)) return &w;
  return c.callWord;
}

bool less(double a, double b) {
  return a < b - 1e-9;
}

// a value for a message: at most 4 decimals (an inch tool radius is 0.19685...)
std::string num(double v) {
  return emit::formatNumber(std::round(v * 1e4) / 1e4);
}

// A pocket size with where it came from: a plane word, R (a derived width), or nothing.
struct Size {
  double value = 0;
  const ir::Word* word = nullptr; // null: derived from the tool (drilling, or slot)
  std::string text;               // "width Y10", "width 2R = 6"
};

bool error2(diag::Engine& diags, const ir::Word* at, const std::string& what) {
  diags.error(diag::code::PocketMacroError2, at->range,
              fmt::format("MACRO ERROR 2: {} (cycles.md §7, 000:15787-15797)", what));
  return false;
}

} // namespace

bool checkPocketCall(const CycleMacroCall& c, diag::Engine& diags) {
  const PlaneAxes ax = planeAxes(c.plane);
  std::vector<std::optional<double>> a = c.args; // a variable beyond the frame is vacant
  a.resize(std::max<std::size_t>(a.size(), ArgZ + 1));

  // MACRO ERROR 1: depth, tool radius register D or depth of cut Q not given (000:15782-15785)
  std::vector<std::string> missing;
  if (!a[ax.depth]) missing.push_back(fmt::format("the depth {}", letterOf(ax.depth)));
  if (!a[ArgD]) missing.push_back("the tool radius register D");
  if (!a[ArgQ]) missing.push_back("the depth of cut Q");
  if (!missing.empty()) {
    std::string list = missing.front();
    for (std::size_t i = 1; i < missing.size(); ++i)
      list += (i + 1 == missing.size() ? " and " : ", ") + missing[i];
    diags.error(diag::code::PocketMacroError1, c.callWord->range,
                fmt::format("MACRO ERROR 1: {} not given ({}; cycles.md §7, 000:15782-15785)", list,
                            c.planeCode));
    return false;
  }

  // the tool: register D (mm, geometry + wear), in program units; a register outside the
  // table has radius 0 and fails the "tool diameter 0" test below
  const double reg = std::round(*a[ArgD]);
  double radius = reg >= 0 && reg <= 999 ? std::fabs(c.toolRadius(static_cast<int>(reg))) : 0;
  if (c.inch) radius /= 25.4;
  const double tool = 2 * radius;
  // corner radius: R, by default the tool radius (000:15703-15708); sizes are magnitudes
  const bool haveR = a[ArgR].has_value();
  const double corner = haveR ? std::fabs(*a[ArgR]) : radius;
  const std::string cornerText = haveR ? fmt::format("R{}", num(corner))
                                       : fmt::format("{} (the tool radius, no R)", num(corner));

  // length = the longer plane size, width = the shorter (000:15693-15702); degenerate cases
  // (000:15765-15778): no width -> 2R; no length and width -> a circle of radius R, or, with
  // no R either, drilling (the tool diameter)
  std::vector<Size> given;
  for (int arg : {ax.first, ax.second})
    if (a[arg]) {
      const ir::Word* w = wordOf(c, letterOf(arg));
      given.push_back({std::fabs(*a[arg]), w, fmt::format("{}{}", letterOf(arg), num(*a[arg]))});
    }
  if (given.size() == 2 && given[0].value < given[1].value) std::swap(given[0], given[1]);
  for (std::size_t i = 0; i < given.size(); ++i)
    given[i].text = fmt::format("{} {}", i == 0 ? "length" : "width", given[i].text);
  const ir::Word* rWord = haveR ? wordOf(c, 'R') : nullptr;
  if (given.size() < 2 && (haveR || !given.empty()))
    given.push_back(
        {2 * corner, rWord,
         fmt::format("{} 2R = {}", given.empty() ? "circle diameter" : "width", num(2 * corner))});

  // MACRO ERROR 2 (000:15787-15797), in the manual's order
  for (const Size& s : given)
    if (less(s.value, 2 * corner))
      return error2(
          diags, s.word ? s.word : c.callWord,
          fmt::format("pocket {} is less than twice the corner radius {}", s.text, cornerText));
  for (const Size& s : given)
    if (less(s.value, tool))
      return error2(diags, s.word ? s.word : c.callWord,
                    fmt::format("pocket {} is less than the tool diameter {} (D{})", s.text,
                                num(tool), num(reg)));
  if (a[ArgE] && *a[ArgE] == 0)
    return error2(diags, wordOf(c, 'E'), "the stepover E is 0 % of the tool diameter");
  if (tool == 0)
    return error2(diags, wordOf(c, 'D'),
                  fmt::format("the tool diameter in register D{} is 0", num(reg)));
  if (*a[ArgQ] == 0) return error2(diags, wordOf(c, 'Q'), "the depth of cut Q is 0");
  return true;
}

CycleMacro pocketCycleMacro() {
  return {PocketMacroProgram, "pocket-milling cycle", diag::code::PocketMacroMissing,
          "cycles.md §5, Q-19", checkPocketCall};
}

} // namespace gcx::cycles
