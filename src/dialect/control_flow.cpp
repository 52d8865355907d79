#include "dialect/control_flow.h"

#include <algorithm>
#include <cctype>

#include "ir/block.h"

namespace gcx {

const Remap* RemapTable::find(std::string_view address, double value,
                              std::optional<double> programValue) const {
  for (const Remap& r : rows) {
    if (r.address.size() != address.size() || r.address[0] != address[0] || r.address != address)
      continue;
    if (r.code && (r.last ? value < *r.code || value > *r.last : value != *r.code)) continue;
    if (r.onlyProgram && programValue != r.onlyProgram) continue;
    return &r;
  }
  return nullptr;
}

std::uint32_t RemapTable::letters() const {
  if (lettersOf_ != rows.size()) { // recounted when rows were added
    letters_ = 0;
    for (const Remap& r : rows)
      if (!r.address.empty() && r.address[0] >= 'A' && r.address[0] <= 'Z')
        letters_ |= 1u << (r.address[0] - 'A');
    lettersOf_ = rows.size();
  }
  return letters_;
}

ProgramCall programFromDigits(const Remap& r, std::string_view digits) {
  ProgramCall call;
  if (r.program == ProgramSource::Fixed) {
    call.unit = r.fixedProgram;
    return call;
  }
  const std::size_t n = r.nameDigits > 0 ? static_cast<std::size_t>(r.nameDigits) : digits.size();
  call.unit = r.namePrefix + std::string(digits.substr(0, n));
  if (digits.size() > n) call.times = std::stol(std::string(digits.substr(n)));
  return call;
}

std::string programDigits(const ir::Word& w) {
  const bool digits = !w.text.empty() && std::all_of(w.text.begin(), w.text.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c));
  });
  return digits ? w.text : std::to_string(static_cast<std::int64_t>(w.number));
}

} // namespace gcx
