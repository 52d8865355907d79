#include "dialects/nct/emitter.h"

#include "dialects/nct/printer.h"

namespace gcx::nct {

namespace {

// A program is a file in NCT (nct.md §1.1) and its `%` and O blocks travel as blocks, so a
// program unit adds no text of its own.
class Emitter : public emit::ProgramEmitter {
public:
  explicit Emitter(std::ostream& out) : out_(out) {}
  emit::Capabilities capabilities() const override { return emitterCapabilities(); }
  void beginProgram(const emit::ProgramUnit&) override {}
  void block(const ir::Block& b) override { out_ << printBlock(b) << '\n'; }
  void endProgram() override {}

private:
  std::ostream& out_;
};

} // namespace

emit::Capabilities emitterCapabilities() {
  using emit::Construct;
  return {Construct::CannedCycles, Construct::Subprograms, Construct::Loops, Construct::Variables,
          Construct::ModalCalls};
}

std::unique_ptr<emit::ProgramEmitter> makeEmitter(std::ostream& out) {
  return std::make_unique<Emitter>(out);
}

} // namespace gcx::nct
