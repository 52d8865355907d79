#include "cli/equiv_program.h"

#include <ostream>
#include <streambuf>

#include "cli/execute.h"
#include "cli/session.h"

namespace gcx::cli {

namespace {

/// A stream buffer that discards what it is given (DPRNT output of a compared program).
class NullBuffer : public std::streambuf {
protected:
  int overflow(int c) override { return c; }
};

class SessionProgram : public equiv::GcxProgram {
public:
  explicit SessionProgram(const CommonOptions& opt) : opt_(opt) {}

  bool open(const std::string& path, const std::string& setup, bool canonicalSubset) override {
    // gcx reads the canonical subset of RS274/NGC (docs/canonical.md) as NCT
    if (canonicalSubset && opt_.dialect.empty()) opt_.dialect = "nct";
    session_ = std::make_unique<Session>(opt_);
    return openWithSetup(*session_, path, setup, setup_) == Ok;
  }
  FileId file() const override { return session_->file(); }
  const machine::Setup& setup() const override { return setup_; }
  const SourceManager& sources() const override { return session_->sources(); }
  diag::Engine& diags() override { return session_->diags(); }
  bool run(motion::Sink& sink) override {
    return executeProgram(*session_, opt_, setup_, sink, null_);
  }

private:
  CommonOptions opt_;
  std::unique_ptr<Session> session_;
  machine::Setup setup_;
  NullBuffer nullBuffer_;
  std::ostream null_{&nullBuffer_};
};

} // namespace

std::function<std::unique_ptr<equiv::GcxProgram>()> gcxProgramMaker(const CommonOptions& opt) {
  return [opt] { return std::make_unique<SessionProgram>(opt); };
}

} // namespace gcx::cli
