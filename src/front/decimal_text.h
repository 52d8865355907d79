// The value of a decimal literal as the dialects write it: digits with at most one point, no
// sign, no exponent ("12", "0.5", ".5", "12."). Exact: the same double std::from_chars gives,
// with a fast path for the short numbers part programs are made of (docs/architecture.md).
#pragma once
#include <string_view>

namespace gcx::front {

/// The nearest double to digits; 0 for empty text; infinity beyond the largest double (callers
/// report it where they check values). digits holds only '0'-'9' and one '.'.
double decimalValue(std::string_view digits);

} // namespace gcx::front
