#include "motion/decimal.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace gcx::motion {

void appendDecimal(std::string& out, double v, int decimals) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  char buf[400]; // fixed notation of the largest double needs 309 digits plus decimals
  auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed,
                           std::clamp(decimals, 0, 17));
  char* end = res.ptr;
  if (std::find(buf, end, '.') != end) {
    while (end[-1] == '0')
      --end;
    if (end[-1] == '.') --end;
  }
  // Rounding can leave "-0" for tiny negative values.
  if (end - buf == 2 && buf[0] == '-' && buf[1] == '0') {
    out += '0';
    return;
  }
  out.append(buf, end);
}

std::string formatDecimal(double v, int decimals) {
  std::string s;
  appendDecimal(s, v, decimals);
  return s;
}

} // namespace gcx::motion
