// Modal calls (NCT: nct-macro.md §5.5-§5.7): a registration calls its program after every
// motion block or after every NC block, the most recent visible one wins, and a cancel removes
// the most recent.
#include <algorithm>
#include <fmt/format.h>

#include "diag/codes.h"
#include "emit/number.h"
#include "passes/macro/expander.h"

namespace gcx::macro {

const ModalCall* Expander::visibleModalCall() const {
  // in a macro started by modal entry j only the entries before j are visible (§5.5 D5)
  const std::size_t visible = std::min(stack_.back().modalVisible, modalCalls_.size());
  return visible ? &modalCalls_[visible - 1] : nullptr;
}

bool Expander::modalBlock(Frame& f, const ir::Block& b, const ir::Block& flat, const CodeMatch& m) {
  const Remap& r = *m.row;
  if (r.action == FlowAction::ModalCancel) {
    if (!modalCalls_.empty()) modalCalls_.pop_back();
    if (r.modalGroup)
      machine_.setModalCode(r.modalGroup,
                            modalCalls_.empty() ? r.modalCode10 : modalCalls_.back().code10);
    return advance(f);
  }
  const bool everyBlock = r.action == FlowAction::ModalCallEveryBlock;
  const ir::Word* p = m.program;
  if (r.program == ProgramSource::Word && !p)
    return fail(diag::code::MissingData, m.code->range,
                fmt::format("{}{} needs {} (program number)", m.code->address,
                            emit::formatNumber(m.code->number), r.programWord));
  ModalCall call;
  call.everyBlock = everyBlock;
  call.code10 = r.modalCode10;
  call.frame = r.frame;
  const std::string unit = r.program == ProgramSource::Word
                               ? programDigits(*p)
                               : programFromDigits(r, programDigits(*m.code)).unit;
  call.program = library_.byUnit(unit, *f.program, (p ? p : m.code)->range);
  if (!call.program) return false;
  call.times = m.repeat ? static_cast<std::int64_t>(m.repeat->number) : 1;
  if (r.frame == LocalFrame::Arguments) {
    CallSite site;
    site.block = &b;
    site.callCode = m.code->number;
    site.programWord = p;
    if (!bind(site, call.args)) return false;
  }
  call.what = describe(m, unit);
  if (r.replacesModalCall && !modalCalls_.empty()) modalCalls_.pop_back();
  modalCalls_.push_back(call);
  if (r.modalGroup) machine_.setModalCode(r.modalGroup, r.modalCode10);
  if (r.registerRunsBlock) { // the block's own words run, a move among them calls (WL4)
    ir::Block nc = flat;
    std::erase_if(nc.words, [&](const ir::Word& w) {
      return w.range.begin.offset == m.code->range.begin.offset ||
             (r.programWord && w.is(r.programWord)) || (r.repeatWord && w.is(r.repeatWord));
    });
    return execute(f, b, nc);
  }
  if (!everyBlock) { // a registration calls nothing and moves nothing in its own block (D1)
    return advance(f);
  }
  // an every-block registration also calls at once from its own block (E1); the macro
  // returns to the next block
  if (call.times < 1) {
    return advance(f);
  }
  return pushFrame(f, call.program, call.frame, call.args, call.times, call.what, b.range,
                   modalCalls_.size() - 1);
}

bool Expander::everyBlockCall(Frame& f, const ir::Block& b, const ir::Block& flat,
                              const ModalCall& m) {
  CallSite site;
  site.block = &flat;
  site.kind = CallKind::EveryBlock;
  std::vector<Value> args;
  if (!bind(site, args)) return false;
  const std::size_t index = static_cast<std::size_t>(&m - modalCalls_.data());
  return pushFrame(f, m.program, m.frame, std::move(args), m.times, m.what, b.range, index);
}

} // namespace gcx::macro
