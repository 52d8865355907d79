#include "front/encoding_output.h"

#include <cerrno>
#include <fmt/format.h>
#include <iconv.h>
#include <sstream>

namespace gcx::front {

namespace {

constexpr std::size_t kChunk = 1 << 16;

iconv_t handle(void* cd) {
  return static_cast<iconv_t>(cd);
}

const char* iconvName(Encoding e) {
  switch (e) {
  case Encoding::Koi8R:
    return "KOI8-R";
  case Encoding::Cp1251:
    return "CP1251";
  case Encoding::Utf8:
    break;
  }
  return "UTF-8";
}

// The code point of the UTF-8 sequence at s (at least one byte), and its length.
std::pair<std::uint32_t, std::size_t> codePoint(std::string_view s) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
  const unsigned char b = byte(0);
  const std::size_t n = b < 0x80 ? 1 : b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : b >= 0xC0 ? 2 : 1;
  if (n > s.size()) return {b, 1};
  std::uint32_t cp = n == 1 ? b : b & (0x7F >> n);
  for (std::size_t i = 1; i < n; ++i)
    cp = cp << 6 | (byte(i) & 0x3F);
  return {cp, n};
}

} // namespace

EncodingOutput::EncodingOutput(std::ostream& out, Encoding encoding)
    : out_(out), encoding_(encoding), buffer_(kChunk) {
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  if (encoding == Encoding::Utf8) return;
  iconv_t cd = iconv_open(iconvName(encoding), "UTF-8");
  if (cd == reinterpret_cast<iconv_t>(-1)) {
    error_ = fmt::format("this system cannot convert text to {}", encodingName(encoding));
    return;
  }
  cd_ = cd;
}

EncodingOutput::~EncodingOutput() {
  if (cd_) iconv_close(handle(cd_));
}

EncodingOutput::int_type EncodingOutput::overflow(int_type c) {
  if (!drain(false)) return traits_type::eof();
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  *pptr() = traits_type::to_char_type(c);
  pbump(1);
  return c;
}

int EncodingOutput::sync() {
  return drain(false) && out_.flush() ? 0 : -1;
}

bool EncodingOutput::finish() {
  return drain(true) && out_.flush() && error_.empty();
}

// Hands what the put area holds to the conversion, and empties it.
bool EncodingOutput::drain(bool last) {
  if (!error_.empty()) return false;
  const std::size_t n = static_cast<std::size_t>(pptr() - pbase());
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  if (!cd_) { // UTF-8: as it is
    out_.write(buffer_.data(), static_cast<std::streamsize>(n));
    return static_cast<bool>(out_);
  }
  pending_.append(buffer_.data(), n);
  return convert(last);
}

bool EncodingOutput::convert(bool last) {
  if (!error_.empty()) return false;
  if (!cd_ || pending_.empty()) return true;
  converted_.resize(pending_.size()); // the single-byte encodings never grow UTF-8
  char* in = pending_.data();
  std::size_t inLeft = pending_.size();
  char* to = converted_.data();
  std::size_t outLeft = converted_.size();
  const std::size_t rc = iconv(handle(cd_), &in, &inLeft, &to, &outLeft);
  const int err = rc == static_cast<std::size_t>(-1) ? errno : 0;
  const std::size_t done = pending_.size() - inLeft;
  for (std::size_t i = 0; i < done; ++i)
    line_ += pending_[i] == '\n';
  out_.write(converted_.data(), static_cast<std::streamsize>(converted_.size() - outLeft));
  if (err == EILSEQ || (err == EINVAL && last)) {
    // ASCII only: the message may itself become a comment of a program in this encoding
    const std::uint32_t cp = codePoint(std::string_view(pending_).substr(done)).first;
    error_ = fmt::format("line {} holds U+{:04X}, which {} has no code for", line_, cp,
                         encodingName(encoding_));
    pending_.clear();
    return false;
  }
  pending_.erase(0, done); // EINVAL: a sequence cut at the end waits for its rest
  return static_cast<bool>(out_);
}

std::optional<std::string> encodeText(std::string_view utf8, Encoding encoding, std::string& why) {
  std::ostringstream out;
  EncodingOutput enc(out, encoding);
  std::ostream in(&enc);
  in.write(utf8.data(), static_cast<std::streamsize>(utf8.size()));
  if (!enc.finish()) {
    why = enc.error();
    return std::nullopt;
  }
  return out.str();
}

} // namespace gcx::front
