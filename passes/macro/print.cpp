// DPRNT / BPRNT (nct-macro.md §6): text and #v[cd] values to the run's print output.
#include <cmath>
#include <fmt/format.h>

#include "passes/macro/expander.h"

namespace gcx::macro {

// DPRNT[...]: text and #v[cd] values (§6): c integer digits, d decimals, rounded, vacant = 0
bool Expander::print(const ir::Stmt& s) {
  // after POPEN the first DPRNT names the output file (§6); gcx writes it to the print output
  if (periphery_ == Periphery::AwaitingName && !s.binaryPrint) {
    std::string name;
    for (const ir::PrintItem& it : s.items)
      name += it.isVariable ? "" : it.text;
    if (print_) *print_ << "(file " << name << ")\r\n%\r\n";
    periphery_ = Periphery::Open;
    return true;
  }
  // the dialect may leave out the '+' and the leading zeros (an NCT parameter bit)
  const bool omit = flow_.printOmitsSign && flow_.printOmitsSign(parameters());
  std::string line;
  for (const ir::PrintItem& it : s.items) {
    if (!it.isVariable) {
      for (char c : it.text)
        line += c == '*' ? ' ' : c;
      continue;
    }
    auto v = read(it.variable, s.range);
    if (!v) return false;
    const double x = v->orZero(); // vacant prints as 0
    if (s.binaryPrint) {          // #v[c]: round(v * 10^c) as a 4-byte big-endian integer
      const int exponent = it.fracDigits ? it.fracDigits : it.intDigits;
      const auto n = static_cast<std::uint32_t>(
          static_cast<std::int32_t>(std::llround(x * std::pow(10.0, exponent))));
      for (int shift = 24; shift >= 0; shift -= 8)
        line += static_cast<char>((n >> shift) & 0xFF);
      continue;
    }
    // #v[cd]: c integer digits, d decimals, rounded; sign '-' (or a space for '+')
    const std::string digits = fmt::format("{:.{}f}", std::fabs(x), it.fracDigits);
    const std::size_t point = digits.find('.');
    std::string integer = digits.substr(0, point);
    const std::string fraction = point == std::string::npos ? "" : digits.substr(point);
    if (!omit && static_cast<int>(integer.size()) < it.intDigits)
      integer.insert(0, it.intDigits - integer.size(), ' ');
    line += x < 0 ? "-" : omit ? "" : " ";
    line += integer + fraction;
  }
  if (print_) *print_ << line << "\r\n";
  return true;
}

} // namespace gcx::macro
