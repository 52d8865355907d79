#include "emit/number.h"

#include <charconv>

namespace gcx::emit {

void appendNumber(std::string& out, double v) {
  if (v == 0) v = 0; // drop the sign of -0
  char buf[400];
  auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  out.append(buf, res.ptr);
}

std::string formatNumber(double v) {
  std::string s;
  appendNumber(s, v);
  return s;
}

} // namespace gcx::emit
