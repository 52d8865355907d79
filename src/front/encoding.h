// Text encodings of program files, and a streaming decoder to UTF-8, the reader's internal
// encoding. WL4 files are KOI8-R and shops write CP1251; glibc's iconv does the conversion.
#pragma once
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gcx::front {

enum class Encoding : unsigned char { Utf8, Koi8R, Cp1251 };

/// The name the command line uses (--encoding): "utf-8", "koi8-r", "cp1251".
std::string_view encodingName(Encoding e);
std::optional<Encoding> encodingByName(std::string_view name);
std::vector<std::string> encodingNames();

/// Reads a byte stream in one encoding and hands it out as UTF-8 in chunks of bounded size, so
/// memory does not grow with the file. UTF-8 input passes through without conversion.
class DecodingInput {
public:
  enum class Status { Data, End, Invalid, Unavailable };

  DecodingInput(std::istream& in, Encoding encoding);
  ~DecodingInput();
  DecodingInput(const DecodingInput&) = delete;
  DecodingInput& operator=(const DecodingInput&) = delete;

  /// Replaces out with the next chunk. Invalid: the next input byte (invalidByte()) is not
  /// valid in the encoding; every byte before it was handed out already. Unavailable: this
  /// system's iconv cannot convert the encoding.
  Status read(std::string& out);
  unsigned char invalidByte() const { return invalidByte_; }
  bool sawAnyByte() const { return sawAnyByte_; }
  /// True when the text is converted: then line starts in the file (rawLineStarts) differ from
  /// line starts in the text handed out.
  bool converts() const { return cd_ != nullptr; }
  /// File offsets just after each LF of the last chunk, in order (only when converting).
  const std::vector<std::uint64_t>& rawLineStarts() const { return rawLineStarts_; }

private:
  bool refill();

  std::istream& in_;
  void* cd_ = nullptr; // iconv_t
  std::string raw_;    // bytes read, not converted yet: raw_[rawPos_, raw_.size())
  std::size_t rawPos_ = 0;
  std::uint64_t rawOffset_ = 0; // file offset of raw_[rawPos_]
  bool eof_ = false;
  bool sawAnyByte_ = false;
  bool unavailable_ = false;
  unsigned char invalidByte_ = 0;
  std::vector<std::uint64_t> rawLineStarts_;
};

} // namespace gcx::front
