// Minimal UTF-8 decoding: enough to validate input and recognise the sign aliases.
#pragma once
#include <cstddef>

namespace gcx::front {

/// Decodes one code point at p (n bytes available). Returns its length in bytes, or 0 if the
/// bytes are not well-formed UTF-8 (overlong forms, surrogates and truncation included).
std::size_t decodeUtf8(const char* p, std::size_t n, char32_t& cp);

} // namespace gcx::front
