#include "dialects/fms3000/structured_spelling.h"

#include <fmt/format.h>

#include "dialects/fms3000/hole_writer.h"
#include "dialects/fms3000/profile.h"
#include "translate/flat_writer.h"

namespace gcx::fms3000 {

namespace {

// A program's name: 1-4 digits, leading zeros significant (fms3000.md §1.3): the source's digits
// when they are such a name, else a free number from 9999 down.
std::string subprogramName(const std::string& source, const std::set<std::string>& taken) {
  const bool digits = !source.empty() && source.size() <= 4 &&
                      source.find_first_not_of("0123456789") == std::string::npos;
  if (digits && !taken.count(source)) return source;
  for (int n = 9999; n >= 1; --n)
    if (!taken.count(std::to_string(n))) return std::to_string(n);
  return {};
}

xlate::StructuredSpelling make() {
  xlate::StructuredSpelling s;
  s.profile = &profile();
  s.label = "FMS-3000";
  s.extension = ".fms";
  s.decimals = 3;     // the control's resolution, 0.001 mm (001:417-419)
  s.codeDigits = 2;   // G00, G04, M03 as the manual writes them
  s.maxCallTimes = 1; // P has no repeat count: more runs are a G25 repeat
  s.commentLine = &emit::lineComment;
  s.subprogramName = &subprogramName;
  // a program is named by its file (§1.3)
  s.mainName = [](const std::string& stem, const std::set<std::string>&) { return stem; };
  s.fileName = [](const std::string& unit) { return unit + ".fms"; };
  s.opening = [](const std::string&, bool) { return std::vector<ir::Block>{}; };
  s.closing = s.opening;
  s.call = [](ir::Block& b, const std::string& unit, long) {
    ir::Word p;
    p.address = "P";
    p.text = unit; // P019 is not P19
    p.number = std::stod(unit);
    p.order = static_cast<std::uint32_t>(b.words.size() + b.stmts.size());
    b.words.push_back(std::move(p));
  };
  s.holes = &makeHoleWriter;
  return s;
}

} // namespace

const xlate::StructuredSpelling& structuredSpelling() {
  static const xlate::StructuredSpelling s = make();
  return s;
}

} // namespace gcx::fms3000
