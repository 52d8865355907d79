#include "machine/block_words.h"

#include <bit>
#include <memory>
#include <vector>

#include "machine/reused_block_words.h"

namespace gcx::machine {

bool BlockWords::hasAxisWord() const {
  for (int i = 0; i < 3; ++i)
    if (axis[i] || uvw[i]) return true;
  for (const ir::Word* x : extra)
    if (x) return true;
  return false;
}

void BlockWords::clear() {
  gWords.clear();
  gCodes.clear();
  axis = {};
  uvw = {};
  ijk = {};
  extra = {};
  r = f = s = t = h = d = p = q = l = e = nullptr;
  m.clear();
  chamfer = rounding = angle = nullptr;
  other.clear();
  // only the entries set: zeroing all 26 compiles to a `rep stos`, slow to start for a block of
  // five words
  for (std::uint32_t set = lettersSet; set != 0; set &= set - 1)
    letters[static_cast<std::size_t>(std::countr_zero(set))] = nullptr;
  lettersSet = 0;
  actionBits = {};
}

const ir::Word* BlockWords::findPresentAction(GAction a) const {
  for (std::size_t i = 0; i < gCodes.size(); ++i)
    if (gCodes[i] && gCodes[i]->action == a) return gWords[i];
  return nullptr;
}

namespace {
struct WordsStack {
  std::vector<std::unique_ptr<BlockWords>> slots; // never shrinks: a slot's address is kept
  std::size_t depth = 0;
};
thread_local WordsStack wordsStack;

BlockWords& takeWords() {
  WordsStack& s = wordsStack;
  if (s.depth == s.slots.size()) s.slots.push_back(std::make_unique<BlockWords>());
  return *s.slots[s.depth++];
}
} // namespace

ReusedBlockWords::ReusedBlockWords() : words_(takeWords()) {}
ReusedBlockWords::~ReusedBlockWords() {
  --wordsStack.depth;
}

const ir::Word* sortWords(const ir::Block& b, const Profile& profile, BlockWords& out) {
  out.clear(); // the lists keep their storage (out may be a ReusedBlockWords')
  for (const ir::Word& w : b.words) {
    if (w.kind != ir::ValueKind::Number && w.kind != ir::ValueKind::Path) return &w;
    if (w.address.size() != 1) {
      const ContourWords& contour = profile.machine.contour;
      if (!contour.chamfer.empty() && w.address == contour.chamfer)
        out.chamfer = &w;
      else if (!contour.rounding.empty() && w.address == contour.rounding)
        out.rounding = &w;
      else if (!contour.angle.empty() && w.address == contour.angle)
        out.angle = &w;
      else
        out.other.push_back(&w);
      continue;
    }
    const char letter = w.address[0];
    if (letter >= 'A' && letter <= 'Z') {
      out.letters[letter - 'A'] = &w;
      out.lettersSet |= std::uint32_t{1} << (letter - 'A');
    }
    switch (letter) {
    case 'G':
      out.gWords.push_back(&w);
      out.gCodes.push_back(profile.gcode(w.number));
      if (const GCodeSpec* g = out.gCodes.back()) {
        const auto bit = static_cast<unsigned>(g->action);
        out.actionBits[bit / 64] |= std::uint64_t{1} << (bit % 64);
      }
      break;
    case 'X':
      out.axis[0] = &w;
      break;
    case 'Y':
      out.axis[1] = &w;
      break;
    case 'Z':
      out.axis[2] = &w;
      break;
    case 'U':
    case 'V':
    case 'W': // incremental X Y Z where the dialect says so, else axes of their own
      (profile.uvwIncremental ? out.uvw[letter - 'U'] : out.extra[3 + letter - 'U']) = &w;
      break;
    case 'A':
      out.extra[0] = &w;
      break;
    case 'B':
      out.extra[1] = &w;
      break;
    case 'C':
      out.extra[2] = &w;
      break;
    case 'I':
      out.ijk[0] = &w;
      break;
    case 'J':
      out.ijk[1] = &w;
      break;
    case 'K':
      out.ijk[2] = &w;
      break;
    case 'R':
      out.r = &w;
      break;
    case 'F':
      out.f = &w;
      break;
    case 'S':
      out.s = &w;
      break;
    case 'T':
      out.t = &w;
      break;
    case 'H':
      out.h = &w;
      break;
    case 'D':
      out.d = &w;
      break;
    case 'P':
      out.p = &w;
      break;
    case 'Q':
      out.q = &w;
      break;
    case 'L':
      out.l = &w;
      break;
    case 'E':
      out.e = &w;
      break;
    case 'M':
      out.m.push_back(&w);
      break;
    default:
      out.other.push_back(&w);
      break;
    }
  }
  return nullptr;
}

} // namespace gcx::machine
