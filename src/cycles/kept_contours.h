// `--keep cycles` for the turning contour cycles G70.7-G73.7 and the contour cycles
// (GAction::ContourCycle, WL4 G76-G78 P Q): a kept cycle names its contour by
// block numbers (P ns, Q nf), so the flattened text must still hold those blocks, with their
// numbers, once and in order. This keeps the numbers that are referenced and reports a kept
// cycle whose contour did not survive flattening (it lay after the program end, or a loop
// repeated it), instead of writing a program that no longer means the same (cycles.md §4.7).
#pragma once
#include <cstdint>
#include <map>
#include <set>
#include <vector>

#include "diag/diagnostic.h"
#include "ir/block.h"

namespace gcx {
struct Profile;
}

namespace gcx::cycles {

class KeptContours {
public:
  /// Collects the P and Q numbers of the contour cycles in `program`.
  KeptContours(const std::vector<ir::Block>& program, const Profile& profile);
  /// Whether a flat block keeps its number N n in the output.
  bool keepsNumber(std::int64_t n) const { return referenced_.count(n) != 0; }
  /// Notes a block written to the output, in order.
  void written(const ir::Block& flat);
  /// After the run: GCX042 at each written cycle whose ns..nf is not in the output once, in
  /// order. False if any was reported.
  bool check(diag::Engine& diags) const;

private:
  struct Cycle {
    std::int64_t ns, nf;
    SourceRange where;
  };
  /// The contour cycle's P and Q when the block holds one.
  std::optional<Cycle> cycleOf(const ir::Block& b) const;

  const Profile& profile_;
  std::set<std::int64_t> referenced_;
  std::map<std::int64_t, std::vector<std::size_t>> positions_; // N -> output block indices
  std::vector<Cycle> cycles_;
  std::size_t count_ = 0;
};

} // namespace gcx::cycles
