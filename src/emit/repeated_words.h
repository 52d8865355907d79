// The last text written for each letter's word. CAM output repeats most words from one line to
// the next (Z, F, one of X and Y): a number whose bits equal the letter's last one has the same
// text, which is copied instead of formatted again (some 20 instructions instead of 100).
#pragma once
#include <bit>
#include <cstdint>
#include <cstring>

#include "motion/decimal.h"

namespace gcx::emit {

class RepeatedWords {
public:
  /// If letter's last word stored had v (the same bits), its text written at `to`, which has
  /// kWordRoom bytes of room, all of which may be written; returns the text's end. Else null.
  char* repeat(char* to, char letter, double v) const {
    const Entry& e = entries_[index(letter)];
    if (e.letter != letter || e.bits != std::bit_cast<std::uint64_t>(v)) return nullptr;
    std::memcpy(to, e.text, motion::kWordRoom);
    return to + e.length;
  }
  /// The word [text, end) for letter and v, where text has kWordRoom bytes (end inside them).
  void store(char letter, double v, const char* text, const char* end) {
    Entry& e = entries_[index(letter)];
    e.letter = letter;
    e.bits = std::bit_cast<std::uint64_t>(v);
    e.length = static_cast<std::uint8_t>(end - text);
    std::memcpy(e.text, text, motion::kWordRoom); // the room, a fixed size: two moves
  }

private:
  static constexpr unsigned kEntries = 32; // 'A'..'Z' each its own entry
  static unsigned index(char letter) { return static_cast<unsigned char>(letter) % kEntries; }
  struct Entry {
    std::uint64_t bits = 0;
    char letter = 0; // 0: empty
    std::uint8_t length = 0;
    char text[motion::kWordRoom] = {};
  };
  Entry entries_[kEntries];
};

} // namespace gcx::emit
