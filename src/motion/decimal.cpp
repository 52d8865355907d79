#include "motion/decimal.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>

namespace gcx::motion {

namespace {
constexpr double kPow10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
constexpr std::uint64_t kPow10Int[] = {1,
                                       10,
                                       100,
                                       1000,
                                       10000,
                                       100000,
                                       1000000,
                                       10000000,
                                       100000000,
                                       1000000000,
                                       10000000000,
                                       100000000000,
                                       1000000000000,
                                       10000000000000,
                                       100000000000000,
                                       1000000000000000,
                                       10000000000000000,
                                       100000000000000000,
                                       1000000000000000000};

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

// The last `count` digits of n (leading zeros included) into [end - count, end).
inline void writeDigits(std::uint64_t n, char* end, int count) {
  for (; count >= 2; count -= 2) {
    const std::uint64_t pair = n % 100;
    n /= 100;
    end -= 2;
    end[0] = kDigitPairs[2 * pair];
    end[1] = kDigitPairs[2 * pair + 1];
  }
  if (count) end[-1] = static_cast<char>('0' + n % 10);
}

inline void writePair(char* to, unsigned n) {
  to[0] = kDigitPairs[2 * n];
  to[1] = kDigitPairs[2 * n + 1];
}

// Digits of n without leading zeros (at least one), written forward at `to`; returns the end.
// Below 10000 (nearly every coordinate and feed) by 32-bit steps without a loop.
inline char* writeWhole(char* to, std::uint64_t n) {
  if (n < 100) {
    if (n < 10) {
      *to = static_cast<char>('0' + n);
      return to + 1;
    }
    writePair(to, static_cast<unsigned>(n));
    return to + 2;
  }
  if (n < 10000) {
    const auto m = static_cast<unsigned>(n);
    const unsigned high = m / 100, low = m % 100;
    if (high < 10) {
      *to = static_cast<char>('0' + high);
      writePair(to + 1, low);
      return to + 3;
    }
    writePair(to, high);
    writePair(to + 2, low);
    return to + 4;
  }
  int count = 5;
  while (count < 19 && n >= kPow10Int[count])
    ++count;
  writeDigits(n, to + count, count);
  return to + count;
}

// The `decimals` digits of a fraction 0 < frac < 10^decimals after a point at `to`, without its
// trailing zeros; returns the end.
template <int decimals> char* writeFraction(char* to, std::uint64_t frac) {
  *to = '.';
  char* end = to + 1 + decimals;
  if constexpr (decimals == 6) { // the canonical output's: three pairs of 32-bit steps
    const auto f = static_cast<unsigned>(frac);
    const unsigned rest = f % 10000;
    writePair(to + 1, f / 10000);
    writePair(to + 3, rest / 100);
    writePair(to + 5, rest % 100);
  } else {
    writeDigits(frac, end, decimals); // with the fraction's leading zeros
  }
  while (end[-1] == '0') // trailing zeros are dropped; frac != 0 stops the loop
    --end;
  return end;
}

// The text of r / 10^decimals written forward at `to` (at most 32 bytes), trailing zeros of the
// fraction dropped; letter: not 0, the text is a word " X..." (putWord). Decimals as a template
// argument: the split into whole and fraction divides by a constant, which the compiler turns
// into a multiplication (a 64-bit division is some 40 cycles).
template <int decimals>
[[gnu::always_inline]] inline char* writeScaled(char* to, std::int64_t r, char letter) {
  if (letter) {
    to[0] = ' ';
    to[1] = letter;
    to += 2;
  }
  if (r < 0) *to++ = '-'; // r == 0 is "0": a rounded -0 has no sign
  const std::uint64_t m = r < 0 ? static_cast<std::uint64_t>(-r) : static_cast<std::uint64_t>(r);
  const std::uint64_t frac = m % kPow10Int[decimals];
  to = writeWhole(to, m / kPow10Int[decimals]);
  return frac == 0 ? to : writeFraction<decimals>(to, frac);
}

char* writeScaled(char* to, std::int64_t r, int decimals, char letter) {
  switch (decimals) { // scaledInteger admits 0-9
  case 0:
    return writeScaled<0>(to, r, letter);
  case 1:
    return writeScaled<1>(to, r, letter);
  case 2:
    return writeScaled<2>(to, r, letter);
  case 3:
    return writeScaled<3>(to, r, letter);
  case 4:
    return writeScaled<4>(to, r, letter);
  case 5:
    return writeScaled<5>(to, r, letter);
  case 6:
    return writeScaled<6>(to, r, letter);
  case 7:
    return writeScaled<7>(to, r, letter);
  case 8:
    return writeScaled<8>(to, r, letter);
  default:
    return writeScaled<9>(to, r, letter);
  }
}

void appendScaled(std::string& out, std::int64_t r, int decimals, char letter) {
  char buf[kWordRoom];
  out.append(buf, static_cast<std::size_t>(writeScaled(buf, r, decimals, letter) - buf));
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

char* putWord(char* to, char letter, double v, int decimals) {
  std::int64_t scaled = 0;
  if (!scaledInteger(v, decimals, scaled)) return nullptr;
  return decimals == 6 ? writeScaled<6>(to, scaled, letter) // the emitters' own, inline
                       : writeScaled(to, scaled, decimals, letter);
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
