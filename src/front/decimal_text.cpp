#include "front/decimal_text.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

namespace gcx::front {

namespace {

// 10^0 .. 10^22 are exact doubles
constexpr double kExactPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                        1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                        1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr std::uint64_t kExactMantissa = std::uint64_t{1} << 53;

double slowValue(std::string_view digits) {
  std::string text;
  if (!digits.empty() && digits.front() == '.') text = "0"; // from_chars wants a leading digit
  text.append(digits);
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec == std::errc::result_out_of_range) // beyond a double: too large, or too small to tell
    return text.find_first_not_of("0.") < text.find('.') ? HUGE_VAL : 0.0;
  return v;
}

} // namespace

double decimalValue(std::string_view digits) {
  // Clinger's fast path: an integer mantissa below 2^53 and a power of ten up to 10^22 are both
  // exact doubles, and one IEEE division of exact operands is correctly rounded
  std::uint64_t mantissa = 0;
  int fraction = -1; // digits after the point; -1 before the point
  for (char c : digits) {
    if (c == '.') {
      fraction = 0;
      continue;
    }
    if (mantissa >= kExactMantissa / 10) return slowValue(digits);
    mantissa = mantissa * 10 + static_cast<std::uint64_t>(c - '0');
    if (fraction >= 0) ++fraction;
  }
  if (fraction > 22) return slowValue(digits);
  const double m = static_cast<double>(mantissa);
  return fraction > 0 ? m / kExactPowersOfTen[fraction] : m;
}

} // namespace gcx::front
