// An output file whose every write is checked: a failed write, flush or close is remembered
// with its reason, and all output files of a run share one byte budget (--max-output).
#pragma once
#include <cstdint>
#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

namespace gcx::cli {

/// The byte budget of every output of this run: -o files, standard output, traces, --print.
void setOutputBudget(std::uint64_t bytes);
std::uint64_t outputBudget();
/// True once the outputs together exceeded the budget.
bool outputBudgetExceeded();

class CheckedFile : public std::streambuf {
public:
  CheckedFile() { buffer_.resize(1 << 16); }
  ~CheckedFile() override;
  CheckedFile(const CheckedFile&) = delete;
  CheckedFile& operator=(const CheckedFile&) = delete;

  /// Opens (truncates) path for writing; false with error() set if it cannot.
  bool open(const std::string& path);
  bool isOpen() const { return fd_ >= 0; }
  /// Flushes and closes; false if any write, the flush or the close failed.
  bool close();
  /// Why a write failed ("No space left on device", "exceeded --max-output ..."); empty if none.
  const std::string& error() const { return error_; }

protected:
  int_type overflow(int_type c) override;
  int sync() override;

private:
  bool flushBuffer();

  int fd_ = -1;
  std::vector<char> buffer_;
  std::string error_;
};

} // namespace gcx::cli
