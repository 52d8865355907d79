#include "front/encoding.h"

#include <array>
#include <cerrno>
#include <iconv.h>

namespace gcx::front {

namespace {

constexpr std::size_t kChunk = 1 << 16;
// the most UTF-8 bytes one input byte becomes in the single-byte encodings (U+2116 in CP1251)
constexpr std::size_t kMaxGrowth = 3;

struct Named {
  Encoding encoding;
  std::string_view name;
  const char* iconvName;
};
constexpr std::array<Named, 3> kEncodings = {{
    {Encoding::Utf8, "utf-8", "UTF-8"},
    {Encoding::Koi8R, "koi8-r", "KOI8-R"},
    {Encoding::Cp1251, "cp1251", "CP1251"},
}};

const Named& named(Encoding e) {
  for (const Named& n : kEncodings)
    if (n.encoding == e) return n;
  return kEncodings[0];
}

iconv_t handle(void* cd) {
  return static_cast<iconv_t>(cd);
}

} // namespace

std::string_view encodingName(Encoding e) {
  return named(e).name;
}

std::optional<Encoding> encodingByName(std::string_view name) {
  for (const Named& n : kEncodings)
    if (n.name == name) return n.encoding;
  return std::nullopt;
}

std::vector<std::string> encodingNames() {
  std::vector<std::string> out;
  for (const Named& n : kEncodings)
    out.emplace_back(n.name);
  return out;
}

DecodingInput::DecodingInput(std::istream& in, Encoding encoding) : in_(in) {
  if (encoding == Encoding::Utf8) return; // the internal encoding: pass through
  iconv_t cd = iconv_open("UTF-8", named(encoding).iconvName);
  if (cd == reinterpret_cast<iconv_t>(-1)) {
    unavailable_ = true; // glibc without its gconv modules: read() says so
    return;
  }
  cd_ = cd;
}

DecodingInput::~DecodingInput() {
  if (cd_) iconv_close(handle(cd_));
}

// Appends the next bytes of the stream after the unconverted rest; false at its end.
bool DecodingInput::refill() {
  if (eof_) return false;
  raw_.erase(0, rawPos_);
  rawPos_ = 0;
  const std::size_t kept = raw_.size();
  raw_.resize(kept + kChunk);
  in_.read(raw_.data() + kept, static_cast<std::streamsize>(kChunk));
  raw_.resize(kept + static_cast<std::size_t>(in_.gcount()));
  if (raw_.size() == kept) {
    eof_ = true;
    return false;
  }
  sawAnyByte_ = true;
  return true;
}

DecodingInput::Status DecodingInput::read(std::string& out) {
  if (unavailable_) return Status::Unavailable;
  if (!cd_) { // UTF-8: the bytes as they are
    if (!refill()) return Status::End;
    out.swap(raw_);
    raw_.clear();
    return Status::Data;
  }
  rawLineStarts_.clear();
  if (rawPos_ >= raw_.size() && !refill()) return Status::End;
  for (;;) {
    out.resize(kChunk * kMaxGrowth);
    char* in = raw_.data() + rawPos_;
    std::size_t inLeft = raw_.size() - rawPos_;
    char* to = out.data();
    std::size_t outLeft = out.size();
    const std::size_t rc = iconv(handle(cd_), &in, &inLeft, &to, &outLeft);
    const int err = rc == static_cast<std::size_t>(-1) ? errno : 0;
    const std::size_t consumed = static_cast<std::size_t>(in - (raw_.data() + rawPos_));
    for (std::size_t i = 0; i < consumed; ++i)
      if (raw_[rawPos_ + i] == '\n') rawLineStarts_.push_back(rawOffset_ + i + 1);
    rawPos_ += consumed;
    rawOffset_ += consumed;
    out.resize(out.size() - outLeft);
    if (!out.empty()) return Status::Data;   // an invalid byte is reported on the next call
    if (err == EINVAL && refill()) continue; // a sequence cut by the end of the chunk
    if (err != 0) {                          // EILSEQ, or a sequence cut by the end of the file
      invalidByte_ = static_cast<unsigned char>(raw_[rawPos_]);
      return Status::Invalid;
    }
    if (!refill()) return Status::End; // all converted
  }
}

} // namespace gcx::front
