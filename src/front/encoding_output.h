// The other direction of front/encoding.h: text gcx writes in UTF-8 (its internal encoding),
// converted to a dialect's encoding on the way out, so a WL4 program comes out in KOI8-R as
// its control reads it (wl4.md §1.1) and reads back as written.
#pragma once
#include <cstdint>
#include <optional>
#include <ostream>
#include <streambuf>
#include <string>
#include <string_view>
#include <vector>

#include "front/encoding.h"

namespace gcx::front {

/// A stream buffer that converts the UTF-8 written into it to `encoding` and passes it to
/// `out`, in chunks (memory does not grow with the text). A character the encoding has no code
/// for stops the conversion: ok() turns false and error() says which character, on which
/// output line; nothing after it is written. UTF-8 passes through unchanged.
class EncodingOutput : public std::streambuf {
public:
  EncodingOutput(std::ostream& out, Encoding encoding);
  ~EncodingOutput() override;
  EncodingOutput(const EncodingOutput&) = delete;
  EncodingOutput& operator=(const EncodingOutput&) = delete;

  /// Converts and passes on what is buffered; false if a character had no code.
  bool finish();
  bool ok() const { return error_.empty(); }
  /// "line 3 holds U+20AC, which koi8-r has no code for"; empty while ok.
  const std::string& error() const { return error_; }

protected:
  int_type overflow(int_type c) override;
  int sync() override;

private:
  bool drain(bool last);
  bool convert(bool last);

  std::ostream& out_;
  Encoding encoding_;
  void* cd_ = nullptr;       // iconv_t
  std::vector<char> buffer_; // the put area
  std::string pending_;      // UTF-8 not converted yet (a sequence cut at the buffer's end stays)
  std::string converted_;
  std::uint64_t line_ = 1;
  std::string error_;
};

/// `utf8` converted to `encoding`; nullopt with `why` set (as EncodingOutput::error) if a
/// character has no code there.
std::optional<std::string> encodeText(std::string_view utf8, Encoding encoding, std::string& why);

} // namespace gcx::front
