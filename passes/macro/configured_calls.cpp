// Calls by codes the machine parameters configure (the dialect's ControlFlow::configuredCall;
// NCT nct-macro.md §5.8): macro type (the other words are arguments), modal macro type, or
// subprogram type (the block's NC part runs first).
#include <fmt/format.h>

#include "emit/number.h"
#include "passes/macro/expander.h"

namespace gcx::macro {

bool Expander::insideConfiguredCall() const {
  for (const Frame& f : stack_)
    if (f.configured) return true;
  return false;
}

bool Expander::runConfiguredCall(Frame& f, const ir::Block& b, const ir::Block& flat,
                                 const ConfiguredCall& c) {
  const LoadedProgram* program = library_.byUnit(c.unit, *f.program, c.word->range);
  if (!program) return false;
  const std::string what = fmt::format("{} ({}{} configured call)", library_.label(c.unit),
                                       c.word->address, emit::formatNumber(c.word->number));
  const auto isCallWord = [&](const ir::Word& w) {
    return w.range.begin.offset == c.word->range.begin.offset && w.address == c.word->address;
  };
  if (c.kind != ConfiguredCall::SubprogramM && c.kind != ConfiguredCall::SubprogramLetter) {
    // macro type: the other words are arguments, for a G code P and L too (§5.4)
    ir::Block argsBlock = b;
    std::erase_if(argsBlock.words, isCallWord);
    CallSite site;
    site.block = &argsBlock;
    site.kind = c.kind == ConfiguredCall::MacroM ? CallKind::ConfiguredM : CallKind::ConfiguredG;
    site.callCode = c.word->number;
    std::vector<Value> args;
    if (!bind(site, args)) return false;
    if (c.kind == ConfiguredCall::ModalG) { // a modal registration (an NCT parameter says so)
      ModalCall m;
      m.program = program;
      m.args = std::move(args);
      m.what = what;
      modalCalls_.push_back(std::move(m));
      ++f.pc;
      return true;
    }
    if (!pushFrame(f, program, LocalFrame::Arguments, std::move(args), 1, what, b.range,
                   f.modalVisible))
      return false;
    stack_.back().configured = true;
    return true;
  }
  // subprogram type: the block's NC part runs first, then the call in the caller's frame
  ir::Block nc = flat;
  std::erase_if(nc.words, isCallWord);
  if (c.valueVariable) commons_[c.valueVariable] = Value::of(c.word->number); // §5.8
  bool stopped = false;
  const bool ok = runNcPart(b, std::move(nc), stopped);
  if (stopped) return ok;
  if (!pushFrame(f, program, LocalFrame::Shared, {}, 1, what, b.range, f.modalVisible))
    return false;
  stack_.back().configured = true;
  return true;
}

} // namespace gcx::macro
