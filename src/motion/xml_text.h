// Text for XML character data and attribute values (SVG titles and labels).
#pragma once
#include <string>
#include <string_view>

namespace gcx::motion {

/// Escapes & < > " ', replaces control characters that XML 1.0 forbids by spaces and invalid
/// UTF-8 (file names in legacy code pages) by U+FFFD, so the result is always well-formed.
std::string xmlEscape(std::string_view text);

} // namespace gcx::motion
