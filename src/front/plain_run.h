// Skipping the bulk of a program's text sixteen bytes at a time: the upper-case letters, digits,
// blanks and `+ - . /` of word-address blocks, which ask nothing of the block cutter. Where the
// target has no SSE2, nothing is skipped and the caller's byte loop does all the work.
#pragma once
#include <bit>
#include <cstddef>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace gcx::front {

/// Whether plainRunEnd looks at sixteen bytes at a time on this target (else it skips nothing).
#if defined(__SSE2__)
inline constexpr bool kPlainRunsBySimd = true;
#else
inline constexpr bool kPlainRunsBySimd = false;
#endif

/// The bytes plainRunEnd skips: A-Z, 0-9, a blank and `+ - . /`.
constexpr bool isRunPlain(unsigned char c) {
  return (c >= 'A' && c <= 'Z') || (c >= '-' && c <= '9') || c == ' ' || c == '+';
}

/// The first position at or after `from` whose byte is not run-plain, looked for sixteen bytes at
/// a time; or, where fewer than sixteen bytes are left before `size`, the position it got to.
inline std::size_t plainRunEnd(const unsigned char* data, std::size_t from, std::size_t size) {
#if defined(__SSE2__)
  // c in [lo, hi] is (c - lo) <= (hi - lo) unsigned: min(c - lo, hi - lo) == c - lo
  const __m128i letters = _mm_set1_epi8('A'), letterSpan = _mm_set1_epi8('Z' - 'A');
  const __m128i numerals = _mm_set1_epi8('-'), numeralSpan = _mm_set1_epi8('9' - '-');
  const __m128i blank = _mm_set1_epi8(' '), plus = _mm_set1_epi8('+');
  for (; from + 16 <= size; from += 16) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(data + from));
    const __m128i l = _mm_sub_epi8(v, letters), n = _mm_sub_epi8(v, numerals);
    const __m128i plain =
        _mm_or_si128(_mm_or_si128(_mm_cmpeq_epi8(_mm_min_epu8(l, letterSpan), l),
                                  _mm_cmpeq_epi8(_mm_min_epu8(n, numeralSpan), n)),
                     _mm_or_si128(_mm_cmpeq_epi8(v, blank), _mm_cmpeq_epi8(v, plus)));
    const auto notPlain = static_cast<unsigned>(~_mm_movemask_epi8(plain)) & 0xFFFFu;
    if (notPlain) return from + static_cast<std::size_t>(std::countr_zero(notPlain));
  }
#else
  (void)data, (void)size;
#endif
  return from;
}

} // namespace gcx::front
