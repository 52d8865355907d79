// The words of one block sorted by role, with their values converted to numbers: what the
// interpreter reads. Only literal words reach it (the macro pass evaluates expressions).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "dialect/profile.h"
#include "ir/block.h"

namespace gcx::machine {

struct BlockWords {
  std::vector<const ir::Word*> gWords;
  std::vector<const GCodeSpec*> gCodes;   // parallel to gWords; null when not in the table
  std::array<const ir::Word*, 3> axis{};  // X Y Z
  std::array<const ir::Word*, 3> uvw{};   // U V W
  std::array<const ir::Word*, 3> ijk{};   // I J K
  std::array<const ir::Word*, 6> extra{}; // A B C, and U V W where the machine has them as axes
  const ir::Word *r = nullptr, *f = nullptr, *s = nullptr, *t = nullptr, *h = nullptr, *d = nullptr,
                 *p = nullptr, *q = nullptr, *l = nullptr, *e = nullptr;
  std::vector<const ir::Word*> m;
  /// The contour geometry words (MachineRules::contour): chamfer, rounding, direction angle.
  const ir::Word *chamfer = nullptr, *rounding = nullptr, *angle = nullptr;
  std::vector<const ir::Word*> other;        // multi-letter words (AX), <file>, O, N words
  std::array<const ir::Word*, 26> letters{}; // every single-letter word by its letter
  std::uint32_t lettersSet = 0; // the entries of letters that sortWords set, by bit, for clear()
  /// The actions of gCodes as bits, so that asking for an action the block lacks (the usual
  /// answer, asked many times a block) does not walk the codes.
  std::array<std::uint64_t, 4> actionBits{};

  /// The word of a letter as written (null if none): for rules the profile gives by letter.
  const ir::Word* letter(char c) const { return c >= 'A' && c <= 'Z' ? letters[c - 'A'] : nullptr; }

  bool hasAxisWord() const;
  /// As a new BlockWords, keeping the lists' storage. Every member above is named in it: a
  /// member added must be added there (BlockWordsTest.ClearForgetsEveryWord).
  void clear();
  /// The G code of this block with the given action, or null.
  /// Inline: the interpreter asks for dozens of actions per block, and most are absent.
  const ir::Word* findAction(GAction a) const {
    const auto bit = static_cast<unsigned>(a);
    if (!((actionBits[bit / 64] >> (bit % 64)) & 1u)) return nullptr;
    return findPresentAction(a);
  }
  bool has(GAction a) const { return findAction(a) != nullptr; }

private:
  const ir::Word* findPresentAction(GAction a) const;
};

/// Sorts the words; returns the first word that is not a literal (to be reported), or null.
const ir::Word* sortWords(const ir::Block& b, const Profile& profile, BlockWords& out);

} // namespace gcx::machine
