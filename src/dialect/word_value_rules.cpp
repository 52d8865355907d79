#include "dialect/word_value_rules.h"

namespace gcx {

const AddressRule& WordValueRules::find(std::string_view address, bool callNumber) const {
  static constexpr AddressRule other{"", false, Rounding::None, -anyValue, anyValue};
  const bool call = callNumber && (address == "P" || address == "S");
  for (const AddressRule& r : rows) // asked for every word: the first letter before a memcmp
    if (r.callNumber == call && r.address.size() == address.size() &&
        (address.empty() || r.address[0] == address[0]) && r.address == address)
      return r;
  if (!address.empty() && !coordinateRow.empty() && address != coordinateRow &&
      coordinateLetters.find(address[0]) != std::string::npos)
    return find(coordinateRow, false);
  return other;
}

} // namespace gcx
