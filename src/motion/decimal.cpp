#include "motion/decimal.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>

namespace gcx::motion {

namespace {
constexpr double kPow10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
constexpr std::uint64_t kPow10Int[] = {1,      10,      100,      1000,      10000,
                                       100000, 1000000, 10000000, 100000000, 1000000000};

// v scaled to `decimals` places and rounded as an integer, when that integer is certainly the
// correctly rounded value to_chars prints. Below 1e12 the product v * 10^d is within 1.2e-4 of
// the exact one, so unless it lies within 1e-3 of a half both round to the same integer. The
// whole part by truncation and the fraction by subtraction are exact below 2^52, and inline
// (std::floor and std::llround are library calls at the default instruction set).
bool scaledInteger(double v, int decimals, std::int64_t& out) {
  if (decimals < 0 || decimals > 9) return false;
  const double scaled = v * kPow10[decimals];
  if (!(std::fabs(scaled) < 1e12)) return false;
  const auto whole = static_cast<std::int64_t>(scaled);    // toward zero
  const double frac = scaled - static_cast<double>(whole); // (-1, 1), the sign of scaled
  const double away = std::fabs(frac);
  if (std::fabs(away - 0.5) < 1e-3) return false;
  out = away < 0.5 ? whole : whole + (frac < 0 ? -1 : 1);
  return true;
}

// "00" "01" ... "99": two digits per step
constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233"
    "34353637383940414243444546474849505152535455565758596061626364656667"
    "6869707172737475767778798081828384858687888990919293949596979899";

// Digits of n, most significant first, into the end of buf; returns the first digit.
char* writeDigits(std::uint64_t n, char* end) {
  while (n >= 100) {
    const std::uint64_t pair = n % 100;
    n /= 100;
    end -= 2;
    end[0] = kDigitPairs[2 * pair];
    end[1] = kDigitPairs[2 * pair + 1];
  }
  if (n >= 10) {
    end -= 2;
    end[0] = kDigitPairs[2 * n];
    end[1] = kDigitPairs[2 * n + 1];
    return end;
  }
  *--end = static_cast<char>('0' + n);
  return end;
}

// Decimals as a template argument: the split into whole and fraction divides by a constant,
// which the compiler turns into a multiplication (a 64-bit division is some 40 cycles).
// letter: not 0, the text is a word " X..." (appendWord).
template <int decimals> void appendScaled(std::string& out, std::int64_t r, char letter) {
  char buf[32];
  char* const end = buf + sizeof buf;
  char* p = end;
  std::uint64_t m = r < 0 ? static_cast<std::uint64_t>(-r) : static_cast<std::uint64_t>(r);
  std::uint64_t frac = m % kPow10Int[decimals];
  const std::uint64_t whole = m / kPow10Int[decimals];
  if (frac != 0) {
    int places = decimals;
    while (frac % 10 == 0) { // trailing zeros are dropped
      frac /= 10;
      --places;
    }
    char* const digits = writeDigits(frac, p);
    p -= places;
    std::fill(p, digits, '0'); // the fraction's leading zeros
    *--p = '.';
  }
  p = writeDigits(whole, p);
  if (r < 0) *--p = '-'; // r == 0 is "0": a rounded -0 has no sign
  if (letter) {
    *--p = letter;
    *--p = ' ';
  }
  out.append(p, static_cast<std::size_t>(end - p));
}

void appendScaled(std::string& out, std::int64_t r, int decimals, char letter) {
  switch (decimals) { // scaledInteger admits 0-9
  case 0:
    return appendScaled<0>(out, r, letter);
  case 1:
    return appendScaled<1>(out, r, letter);
  case 2:
    return appendScaled<2>(out, r, letter);
  case 3:
    return appendScaled<3>(out, r, letter);
  case 4:
    return appendScaled<4>(out, r, letter);
  case 5:
    return appendScaled<5>(out, r, letter);
  case 6:
    return appendScaled<6>(out, r, letter);
  case 7:
    return appendScaled<7>(out, r, letter);
  case 8:
    return appendScaled<8>(out, r, letter);
  default:
    return appendScaled<9>(out, r, letter);
  }
}
} // namespace

void appendDecimal(std::string& out, double v, int decimals) {
  std::int64_t scaled = 0;
  if (scaledInteger(v, decimals, scaled)) {
    appendScaled(out, scaled, decimals, 0);
    return;
  }
  appendDecimalExact(out, v, decimals);
}

void appendWord(std::string& out, char letter, double v, int decimals) {
  std::int64_t scaled = 0;
  if (scaledInteger(v, decimals, scaled)) {
    appendScaled(out, scaled, decimals, letter);
    return;
  }
  out += ' ';
  out += letter;
  appendDecimalExact(out, v, decimals);
}

void appendDecimalExact(std::string& out, double v, int decimals) {
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
