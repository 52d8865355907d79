// Repeated fragments (FMS-3000 G25 L<n> ... M25, fms3000.md §6.2): the blocks after the opening
// block up to and including the closing one run n times; the opening block runs once. They
// nest as a stack within one program frame.
#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"
#include "passes/macro/expander.h"

namespace gcx::macro {

bool Expander::repeatBlock(Frame& f, const ir::Block& flat, const CodeMatch& m) {
  if (m.row->action == FlowAction::RepeatStart) {
    const ir::Word* count = m.row->repeatWord ? flat.find(m.row->repeatWord) : nullptr;
    if (!count)
      return fail(diag::code::MissingData, m.code->range,
                  fmt::format("{}{} without its repeat count {}", m.code->address, m.code->text,
                              m.row->repeatWord));
    if (count->number < 1 || count->number != std::floor(count->number))
      return fail(diag::code::DataOutOfRange, count->range,
                  "the repeat count is a whole number of runs, 1 or more");
    f.repeats.push_back(Repeat{f.pc, static_cast<std::int64_t>(count->number) - 1});
    ++f.pc;
    return true;
  }
  if (f.repeats.empty())
    return fail(diag::code::BlockNotFound, m.code->range,
                fmt::format("{}{} closes no repeated fragment", m.code->address, m.code->text));
  Repeat& r = f.repeats.back();
  if (r.remaining > 0) {
    --r.remaining;
    f.pc = r.head + 1;
    return true;
  }
  f.repeats.pop_back();
  ++f.pc;
  return true;
}

} // namespace gcx::macro
