#include "dialects/wl4/emitter.h"

#include "dialects/wl4/printer.h"

namespace gcx::wl4 {

namespace {

// A WL4 file is a sequence of `%name ... %` units. Blocks that carry their own unit lines (gcx
// fmt) print them; a stream of flat blocks (expand --to wl4) gets a unit of its own.
class Emitter : public emit::ProgramEmitter {
public:
  explicit Emitter(std::ostream& out) : out_(out) {}
  emit::Capabilities capabilities() const override { return emitterCapabilities(); }
  void beginProgram(const emit::ProgramUnit& unit) override { name_ = unit.name; }
  void block(const ir::Block& b) override {
    if (b.kind == ir::BlockKind::ProgramStart) open_ = Open::ByBlocks;
    if (open_ == Open::No && b.kind != ir::BlockKind::ProgramEnd) {
      out_ << '%' << (name_.empty() ? "MAIN" : name_) << "\n";
      open_ = Open::ByEmitter;
    }
    out_ << printBlock(b) << "\n";
    if (b.kind == ir::BlockKind::ProgramEnd) open_ = Open::No;
  }
  void endProgram() override {
    if (open_ == Open::ByEmitter) out_ << "%\n";
    open_ = Open::No;
  }

private:
  enum class Open { No, ByBlocks, ByEmitter };
  std::ostream& out_;
  std::string name_;
  Open open_ = Open::No;
};

} // namespace

emit::Capabilities emitterCapabilities() {
  using emit::Construct;
  // G81-G89 are user programs, not cycles of the control; loops are jumps; no macro calls
  return {Construct::Subprograms, Construct::Variables};
}

std::unique_ptr<emit::ProgramEmitter> makeEmitter(std::ostream& out) {
  return std::make_unique<Emitter>(out);
}

} // namespace gcx::wl4
