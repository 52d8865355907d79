// NC blocks: every word resolved to a literal, then the dialect's remap table decides whether
// the block calls, returns, registers a modal call or simply runs on the machine.
#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"
#include "emit/number.h"
#include "passes/macro/expander.h"
#include "passes/macro/word_values.h"

namespace gcx::macro {

namespace {

// A motion block for a modal call (nct-macro.md §5.5 D3): an NC block with an axis word (one
// of the dialect's coordinate letters).
bool movesAxes(const ir::Block& b, std::string_view axisLetters) {
  for (const ir::Word& w : b.words)
    if (w.address.size() == 1 && axisLetters.find(w.address[0]) != std::string_view::npos)
      return true;
  return false;
}

const ir::Word* wordOf(const ir::Block& b, char letter) {
  return letter ? b.find(letter) : nullptr;
}

bool isModal(FlowAction a) {
  return a == FlowAction::ModalCall || a == FlowAction::ModalCallEveryBlock ||
         a == FlowAction::ModalCancel;
}

} // namespace

Expander::CodeMatch Expander::match(const ir::Word& w, const ir::Block& flat) const {
  CodeMatch m;
  if (w.kind != ir::ValueKind::Number || !flow_.remaps.mayMatch(w.address)) return m;
  const Remap* row = flow_.remaps.find(w.address, w.number);
  if (!row || (row->unlessWord && flat.find(row->unlessWord))) return m;
  if (row->parameterCode)
    for (const ir::Word& x : flat.words) {
      if (&x == &w) break;
      if (x.is('G') && row->parameterCode(x.number)) return m;
    }
  const ir::Word* program = wordOf(flat, row->programWord);
  if (program) // a row for this program only (a system cycle) comes first
    if (const Remap* only = flow_.remaps.find(w.address, w.number, program->number)) row = only;
  m.row = row;
  m.code = &w;
  m.program = program;
  m.repeat = wordOf(flat, row->repeatWord);
  if (row->fileWord)
    for (const ir::Word& x : flat.words)
      if (x.kind == ir::ValueKind::Path) m.file = &x;
  if (row->onlyIfProgramExists) { // a user program overrides the built-in only if it exists
    const std::string unit = row->program == ProgramSource::Word
                                 ? (program ? programDigits(*program) : "")
                                 : programFromDigits(*row, programDigits(w)).unit;
    if (unit.empty() || library_.locate(unit, *stack_.back().program).empty()) return {};
  }
  return m;
}

WordOptions Expander::scanRemaps(const ir::Block& b) {
  bool call = false; // P is a program or sequence number in a call or return
  remapped_ = false; // a word may be remapped: ncBlock looks the words up
  for (const ir::Word& w : b.words) {
    if (!flow_.remaps.mayMatch(w.address)) continue;
    if (!w.isLiteral()) {
      remapped_ = true; // its value decides
      continue;
    }
    if (const Remap* r = flow_.remaps.find(w.address, w.number)) {
      remapped_ = true;
      call = call || r->programWordIsNumber;
    }
  }
  WordOptions opt;
  opt.rules = &flow_.wordValues;
  opt.callNumber = call;
  return opt;
}

// Everything of b but its words, which flatten resolves one by one: copying them first would
// copy every expression tree only to drop it.
void copyAllButWords(const ir::Block& b, ir::Block& flat) {
  flat.kind = b.kind;
  flat.skipLevel = b.skipLevel;
  flat.sequence = b.sequence;
  flat.sequenceText = b.sequenceText;
  flat.sequenceRange = b.sequenceRange;
  flat.programName = b.programName;
  flat.words.clear();
  flat.stmts = b.stmts;
  flat.comments = b.comments;
  flat.range = b.range;
  flat.lastLine = b.lastLine;
}

bool Expander::flatten(const ir::Block& b, ir::Block& flat) {
  // resolve every value; vacant bare references drop their word (§2.5 rule 4)
  copyAllButWords(b, flat);
  const WordOptions opt = scanRemaps(b);
  for (const ir::Word& w : b.words)
    if (!resolveWord(w, opt, flat)) return false;
  return true;
}

bool Expander::resolveWord(const ir::Word& w, const WordOptions& opt, ir::Block& flat) {
  if (w.kind != ir::ValueKind::Expression && w.address != "AX") {
    flat.words.push_back(w);
    return true;
  }
  if (w.address != "AX") {
    WordValue v = wordValue(w, eval_, opt);
    if (v.result == WordResult::Error) return false;
    if (v.result == WordResult::Dropped) return true;
    // the word with its value in place of its expression, whose tree is not copied
    ir::Word& resolved = flat.words.emplace_back();
    resolved.address = w.address;
    resolved.incremental = w.incremental;
    resolved.kind = ir::ValueKind::Number;
    resolved.order = w.order;
    resolved.number = v.number;
    resolved.text = w.text;
    resolved.axisIndex = w.axisIndex;
    resolved.range = w.range;
    return true;
  }
  ir::Word resolved = w;
  { // AX[n]=v: the axis by its number in the channel (§2.6)
    auto n = eval_.number(w.axisIndex.front());
    if (!n) return false;
    const long k = std::lround(*n);
    if (k < 1 || k > static_cast<long>(flow_.channelAxes.size()))
      return fail("2018", w.range, fmt::format("wrong physical axis number {}", k));
    resolved.address = std::string(1, flow_.channelAxes[static_cast<std::size_t>(k - 1)]);
    resolved.axisIndex.clear();
  }
  if (resolved.kind == ir::ValueKind::Number) { // AX[e]=<literal>
    flat.words.push_back(std::move(resolved));
    return true;
  }
  WordValue v = wordValue(resolved, eval_, opt);
  if (v.result == WordResult::Error) return false;
  if (v.result == WordResult::Dropped) return true;
  resolved.kind = ir::ValueKind::Number;
  resolved.number = v.number;
  resolved.expr = ir::Expr{};
  flat.words.push_back(std::move(resolved));
  return true;
}

bool Expander::contour(std::int64_t ns, std::int64_t nf, std::vector<machine::ContourBlock>& out) {
  const Frame& f = stack_.back();
  const LoadedProgram& program = *f.program;
  const std::size_t first = program.find(ns, f.pc);
  const std::size_t last = first == LoadedProgram::npos ? first : program.find(nf, first);
  if (first == LoadedProgram::npos || last == LoadedProgram::npos || last < first) return false;
  for (std::size_t i = first; i <= last; ++i) {
    const ir::Block& b = program.blocks[i];
    machine::ContourBlock c;
    c.from = provenance(b);
    if (!b.stmts.empty())
      c.block = b; // the interpreter reports it
    else if (!flatten(b, c.block))
      return false;
    out.push_back(std::move(c));
  }
  return true;
}

bool Expander::runNcPart(const ir::Block& b, ir::Block nc, bool& stopped) {
  stopped = false;
  if (nc.words.empty()) return true;
  if (onFlat_) onFlat_(nc);
  if (system_) system_->blockRuns(nc);
  if (machine_.execute(nc, provenance(b))) return true;
  stopped = true;
  if (machine_.ended()) done_ = true;
  return machine_.ended();
}

bool Expander::ncBlock(Frame& f, const ir::Block& b) {
  if (!flatten(b, flat_)) return false;
  return ncFlat(f, b, flat_);
}

bool Expander::ncFlat(Frame& f, const ir::Block& b, ir::Block& flat) {
  // inside a configured call, configured codes are ordinary (§5.8 P3, P4); without
  // parameters no code is configured
  if (flow_.configuredCall && machine_.hasParameters() && !insideConfiguredCall()) {
    const std::size_t before = diags_.errorCount();
    if (auto c = flow_.configuredCall(flat, parameters(), diags_))
      return runConfiguredCall(f, b, flat, *c);
    if (diags_.errorCount() != before) return false;
  }
  // the remapped codes of the block: a macro or modal call (the last one written), a
  // subprogram call, a return, a program end (the first one written)
  CodeMatch primary, subprogram, back, end, repeat;
  for (ir::Word& w : flat.words) {
    if (!remapped_) break;
    const CodeMatch m = match(w, flat);
    if (!m.row) continue;
    switch (m.row->action) {
    case FlowAction::Builtin:
      if (!m.row->builtin.empty()) w.address = m.row->builtin;
      break;
    case FlowAction::CallSubprogram:
      if (!subprogram.row) subprogram = m;
      break;
    case FlowAction::Return:
      if (!back.row) back = m;
      break;
    case FlowAction::EndProgram:
      if (!end.row) end = m;
      break;
    case FlowAction::RepeatStart:
    case FlowAction::RepeatEnd:
      if (!repeat.row) repeat = m;
      break;
    default: // CallMacro, CallCycle, Modal*
      primary = m;
    }
  }
  if (primary.row && isModal(primary.row->action)) return modalBlock(f, b, flat, primary);
  if (primary.row && primary.row->action == FlowAction::CallOpenCycle)
    return openCycleCall(f, b, flat, primary);
  // a modal call made by every block: the block's words are the arguments (§5.6 E2)
  if (const ModalCall* m = visibleModalCall(); m && m->everyBlock && !flat.words.empty())
    return everyBlockCall(f, b, flat, *m);
  if (primary.row) return call(f, b, primary);
  if (subprogram.row || back.row || end.row || repeat.row) {
    // the NC part of the block runs first, then the call or return (§1.4 K5)
    ir::Block nc = flat;
    std::erase_if(nc.words, [&](const ir::Word& w) {
      if (w.kind == ir::ValueKind::Path) return true;
      for (const CodeMatch* m : {&subprogram, &back, &end, &repeat})
        if (m->row && (w.range.begin.offset == m->code->range.begin.offset ||
                       (m->row->programWord && w.is(m->row->programWord)) ||
                       (m->row->repeatWord && w.is(m->row->repeatWord))))
          return true;
      return false;
    });
    bool stopped = false;
    const bool ok = runNcPart(b, std::move(nc), stopped);
    if (stopped) return ok;
    if (repeat.row) return repeatBlock(f, flat, repeat);
    if (subprogram.row) return call(f, b, subprogram);
    if (back.row) return returnFromCall(f, flat, back);
    machine_.finish(); // a code that ends the program (an FMS program end)
    done_ = true;
    return true;
  }
  return execute(f, b, flat);
}

bool Expander::execute(Frame& f, const ir::Block& b, const ir::Block& flat) {
  if (onFlat_) onFlat_(flat);
  fillProvenance(b, here_);
  if (system_) system_->blockRuns(flat);
  if (!machine_.execute(flat, here_)) {
    if (machine_.ended()) {
      done_ = true;
      return true;
    }
    return false;
  }
  // G71.7-G73.7 whose contour follows: continue after its last block (cycles.md §4.7)
  if (const auto nf = machine_.takeResumeAfter()) {
    const std::size_t last = f.program->find(*nf, f.pc);
    if (last != LoadedProgram::npos && last > f.pc) {
      f.pc = last + 1;
      return true;
    }
  }
  // a modal call after each motion block: the most recent visible one (§5.5 D2, D3)
  if (const ModalCall* m = visibleModalCall();
      m && !m->everyBlock && movesAxes(flat, flow_.wordValues.coordinateLetters) &&
      !(flow_.axisWordsNoMove && flow_.axisWordsNoMove(flat))) {
    const std::size_t index = static_cast<std::size_t>(m - modalCalls_.data());
    return pushFrame(f, m->program, m->frame, m->args, m->times, m->what, b.range, index);
  }
  return advance(f);
}

} // namespace gcx::macro
