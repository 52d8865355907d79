// Copying a word's text (a few characters: "-40.5", "07") without a call into the C library:
// the fast parse and the packed blocks of a two-thread run copy it for every word, three times
// a word in all, and a library memcpy costs more than the bytes.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace gcx::ir {

/// The n bytes at `from` to `to` (n at most 16), by two overlapping fixed-size moves that the
/// compiler makes single loads and stores. Reads and writes only the n bytes.
inline void copyShort(char* to, const char* from, std::size_t n) {
  if (n >= 8) {
    std::uint64_t a, b;
    std::memcpy(&a, from, 8);
    std::memcpy(&b, from + n - 8, 8);
    std::memcpy(to, &a, 8);
    std::memcpy(to + n - 8, &b, 8);
  } else if (n >= 4) {
    std::uint32_t a, b;
    std::memcpy(&a, from, 4);
    std::memcpy(&b, from + n - 4, 4);
    std::memcpy(to, &a, 4);
    std::memcpy(to + n - 4, &b, 4);
  } else {
    for (std::size_t i = 0; i < n; ++i)
      to[i] = from[i];
  }
}

/// to = the n bytes at `from` (n at most 16); in place when the length is unchanged (CAM output:
/// the same words block after block).
inline void assignShort(std::string& to, const char* from, std::size_t n) {
  if (to.size() != n) to.resize(n);
  copyShort(to.data(), from, n);
}

} // namespace gcx::ir
