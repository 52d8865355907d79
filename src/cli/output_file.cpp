#include "cli/output_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

namespace gcx::cli {

namespace {
struct Budget {
  std::uint64_t limit = UINT64_MAX;
  std::uint64_t used = 0;
} budget;
} // namespace

void setOutputBudget(std::uint64_t bytes) {
  budget.limit = bytes;
}
std::uint64_t outputBudget() {
  return budget.limit;
}
bool outputBudgetExceeded() {
  return budget.used > budget.limit;
}

CheckedFile::~CheckedFile() {
  if (fd_ >= 0) ::close(fd_);
}

bool CheckedFile::open(const std::string& path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) {
    error_ = std::strerror(errno);
    return false;
  }
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  return true;
}

bool CheckedFile::flushBuffer() {
  const char* p = pbase();
  std::size_t n = static_cast<std::size_t>(pptr() - pbase());
  setp(buffer_.data(), buffer_.data() + buffer_.size());
  if (!error_.empty() || fd_ < 0) return false;
  budget.used += n;
  if (outputBudgetExceeded()) {
    error_ = fmt::format("the output exceeded --max-output {} bytes; raise it with --max-output N",
                         budget.limit);
    return false;
  }
  while (n > 0) {
    const ssize_t w = ::write(fd_, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      error_ = std::strerror(w < 0 ? errno : EIO);
      return false;
    }
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

CheckedFile::int_type CheckedFile::overflow(int_type c) {
  if (!flushBuffer()) return traits_type::eof();
  if (!traits_type::eq_int_type(c, traits_type::eof())) {
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
  }
  return traits_type::not_eof(c);
}

int CheckedFile::sync() {
  return flushBuffer() ? 0 : -1;
}

bool CheckedFile::close() {
  if (fd_ < 0) return error_.empty();
  flushBuffer();
  if (::close(fd_) != 0 && error_.empty()) error_ = std::strerror(errno);
  fd_ = -1;
  return error_.empty();
}

} // namespace gcx::cli
