// How a value an expression computes becomes an address's value (`X#1`, `G#29`): each
// dialect's table of rounding and range per address (NCT nct-macro.md §2.6, WL4 wl4.md §6.1).
#pragma once
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace gcx {

/// Rounding of a value given to an address; ties away from zero.
enum class Rounding : unsigned char {
  Integer,    // NCT: M T H D L N, P as program / sequence number, S as call number
  Tenth,      // NCT G: one decimal (G#1 with 84.2 -> G84.2, with 1.04 -> G1)
  Resolution, // coordinates: WordValueRules::resolution
  None,       // kept as computed
};

/// One row: rounding, then the inclusive range the rounded value must lie in. min >= 0 means
/// the address takes no sign.
struct AddressRule {
  std::string_view address;
  bool callNumber; // the row of P / S used as a program, sequence or call number
  Rounding rounding;
  double min;
  double max;
};

inline constexpr double anyValue = std::numeric_limits<double>::max(); // finite: inf, NaN fail

struct WordValueRules {
  std::vector<AddressRule> rows;
  /// An address not in rows that starts with one of these letters is a coordinate and takes
  /// the row of coordinateRow (NCT's extended axis names XDE, Z1).
  std::string coordinateLetters;
  std::string_view coordinateRow;
  double resolution = 1e-6;   // the step of Rounding::Resolution
  std::string_view reference; // the spec section messages cite ("nct-macro.md §2.6")

  /// The row of an address; an address the table does not name keeps its value unchecked.
  const AddressRule& find(std::string_view address, bool callNumber) const;
};

} // namespace gcx
