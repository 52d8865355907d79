// The text of one output line, composed in place: words are written through a pointer into
// storage that only grows, without a std::string's checks and copies for every append.
#pragma once
#include <algorithm>
#include <cstring>
#include <string_view>
#include <vector>

namespace gcx::emit {

class LineBuffer {
public:
  LineBuffer() : data_(256) {}

  void clear() { size_ = 0; }
  /// Where n more bytes may be written; commit() then says where they end.
  char* room(std::size_t n) {
    if (data_.size() - size_ < n) [[unlikely]]
      grow(n);
    return data_.data() + size_;
  }
  void commit(const char* end) { size_ = static_cast<std::size_t>(end - data_.data()); }
  void append(std::string_view s) {
    std::memcpy(room(s.size()), s.data(), s.size());
    size_ += s.size();
  }
  void push_back(char c) {
    *room(1) = c;
    ++size_;
  }
  std::string_view view() const { return {data_.data(), size_}; }

private:
  // Out of line: inlined, the resize made every word's fast path save registers.
  [[gnu::noinline]] void grow(std::size_t n) {
    data_.resize(std::max(2 * data_.size(), size_ + n));
  }

  std::vector<char> data_;
  std::size_t size_ = 0;
};

} // namespace gcx::emit
