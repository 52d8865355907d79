#include "dialects/fms3000/emitter.h"

#include "dialects/fms3000/printer.h"

namespace gcx::fms3000 {

namespace {

// A program is a file named by its digits (fms3000.md §1.3): a unit adds no text of its own.
class Emitter : public emit::ProgramEmitter {
public:
  explicit Emitter(std::ostream& out) : out_(out) {}
  emit::Capabilities capabilities() const override { return emitterCapabilities(); }
  void beginProgram(const emit::ProgramUnit&) override {}
  void block(const ir::Block& b) override { out_ << printBlock(b) << "\r\n"; }
  void endProgram() override {}

private:
  std::ostream& out_;
};

} // namespace

emit::Capabilities emitterCapabilities() {
  // the cycles G81-G88 and G150-G167 stay one block each, P calls and G25 ... M25 repeats as
  // written (fms3000.md §6); no variables (the user-cycle language is refused, §6.4)
  return {emit::Construct::CannedCycles, emit::Construct::Subprograms, emit::Construct::Loops};
}

std::unique_ptr<emit::ProgramEmitter> makeEmitter(std::ostream& out) {
  return std::make_unique<Emitter>(out);
}

} // namespace gcx::fms3000
