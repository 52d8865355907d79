// A block's items in source order: words, statements and comments merged by their `order`.
// WL4 evaluates a block left to right (wl4.md §1.9) and FMS cycle words mean different things
// before and after the cycle's G code (fms3000.md §6.3); both walk a block this way.
#pragma once
#include <cstddef>
#include <vector>

#include "ir/block.h"

namespace gcx::ir {

enum class ItemKind : unsigned char { Word, Stmt, Comment };

/// An item of a block: which vector, and the index in it.
struct ItemRef {
  ItemKind kind = ItemKind::Word;
  std::size_t index = 0;

  bool operator==(const ItemRef&) const = default;
};

/// Calls visit(ItemRef) for every item of b in source order (ties: words, statements, comments).
template <class Visit> void forEachItem(const Block& b, Visit&& visit) {
  std::size_t w = 0, s = 0, c = 0;
  constexpr std::uint32_t kNone = ~std::uint32_t{0};
  while (true) {
    const std::uint32_t ow = w < b.words.size() ? b.words[w].order : kNone;
    const std::uint32_t os = s < b.stmts.size() ? b.stmts[s].order : kNone;
    const std::uint32_t oc = c < b.comments.size() ? b.comments[c].order : kNone;
    if (w == b.words.size() && s == b.stmts.size() && c == b.comments.size()) return;
    if (w < b.words.size() && ow <= os && ow <= oc)
      visit(ItemRef{ItemKind::Word, w++});
    else if (s < b.stmts.size() && os <= oc)
      visit(ItemRef{ItemKind::Stmt, s++});
    else
      visit(ItemRef{ItemKind::Comment, c++});
  }
}

/// The items of b in source order, for tests and tools (the hot path uses forEachItem).
inline std::vector<ItemRef> items(const Block& b) {
  std::vector<ItemRef> out;
  forEachItem(b, [&](ItemRef r) { out.push_back(r); });
  return out;
}

} // namespace gcx::ir
