// Open cycles (FlowAction::CallOpenCycle): a code whose program does the moving. The block's
// axis words are the cycle's target, not a move; its other words (F, S, M, G95 ...) run first;
// the system variables take the target, and the program runs once with a copy of the locals
// and no modal call visible (WL4 G31, G70-G78 and %1, wl4.md §5.1, §5.3).
#include <string_view>

#include "passes/macro/expander.h"

namespace gcx::macro {

namespace {

bool isAxisWord(const ir::Word& w) {
  return w.address.size() == 1 &&
         std::string_view("XYZUVWABC").find(w.address[0]) != std::string_view::npos;
}

} // namespace

bool Expander::openCycleCall(Frame& f, const ir::Block& b, const ir::Block& flat,
                             const CodeMatch& m) {
  ir::Block nc = flat;
  std::erase_if(nc.words, [&](const ir::Word& w) {
    return w.range.begin.offset == m.code->range.begin.offset || isAxisWord(w) ||
           (w.address.size() == 1 && m.row->cycleWords.find(w.address[0]) != std::string::npos);
  });
  bool stopped = false;
  const bool ok = runNcPart(b, std::move(nc), stopped);
  if (stopped) return ok;
  if (system_ && !system_->openCycle(flat, *m.code)) return false;
  return call(f, b, m);
}

} // namespace gcx::macro
