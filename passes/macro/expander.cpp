#include "passes/macro/expander.h"

#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

#include "diag/codes.h"
#include "dialects/nct/arguments.h"
#include "emit/number.h"
#include "passes/macro/cycle_macro.h"
#include "passes/macro/word_values.h"

namespace gcx::macro {

namespace {

bool isLiteral(const ir::Word& w, char letter, double value) {
  return w.is(letter) && w.kind == ir::ValueKind::Number && w.number == value;
}

const ir::Word* findLiteral(const ir::Block& b, char letter, double value) {
  for (const ir::Word& w : b.words)
    if (isLiteral(w, letter, value)) return &w;
  return nullptr;
}

// A motion block for G66 (§5.5 D3): an NC block with an axis word.
bool movesAxes(const ir::Block& b) {
  for (const ir::Word& w : b.words)
    if (w.address.size() == 1 &&
        std::string_view("XYZUVWABC").find(w.address[0]) != std::string_view::npos)
      return true;
  return false;
}

bool bareReference(const ir::Expr& e) {
  const ir::Expr* x = &e;
  if (x->kind == ir::ExprKind::Unary && x->op != ir::Op::Not) x = &x->args[0];
  return x->kind == ir::ExprKind::Variable || x->kind == ir::ExprKind::Indirect ||
         x->kind == ir::ExprKind::Named;
}

} // namespace

Expander::Expander(ProgramLibrary& library, machine::Interpreter& machine, SystemVariables& system,
                   diag::Engine& diags, Limits limits)
    : library_(library), machine_(machine), system_(system), diags_(diags), limits_(limits),
      eval_(*this, diags) {
  for (const auto& [n, v] : machine_.setup().variables)
    if (n >= 100) commons_[n] = Value::of(v);
}

bool Expander::fail(const char* code, const SourceRange& where, std::string message) {
  diag::Diagnostic d{diag::Severity::Error, code, std::move(message), where, {}};
  const motion::Provenance p = provenance(ir::Block{});
  for (auto it = p.chain.rbegin(); it != p.chain.rend(); ++it)
    d.notes.push_back({SourceRange{it->call, 1}, "in " + it->what});
  diags_.report(std::move(d));
  return false;
}

motion::Provenance Expander::provenance(const ir::Block& b) const {
  motion::Provenance p;
  p.at = b.range.begin;
  for (std::size_t i = 0; i < stack_.size(); ++i) {
    const Frame& f = stack_[i];
    if (i > 0) p.chain.push_back({f.callSite, f.what});
    for (const Loop& l : f.loops) {
      const ir::Block& head = f.program->blocks[l.head];
      p.chain.push_back({head.range.begin, fmt::format("loop DO{} iteration {}",
                                                       head.stmts.front().loopId, l.iteration)});
    }
  }
  return p;
}

bool Expander::run(const LoadedProgram& main) {
  Frame f;
  f.program = &main;
  stack_.push_back(std::move(f));
  // #4000: the main program's number when its name is O + digits (nct-macro.md §2.9.3)
  const std::string stem = std::filesystem::path(main.path).stem().string();
  if (stem.size() > 1 && (stem[0] == 'O' || stem[0] == 'o') &&
      stem.find_first_not_of("0123456789", 1) == std::string::npos && stem.size() <= 9)
    system_.setMainProgramNumber(std::stoi(stem.substr(1)));
  locals_.assign(1, {});
  done_ = false;
  machine_.setContourSource(
      [this](std::int64_t ns, std::int64_t nf, auto& out) { return contour(ns, nf, out); });
  while (!done_)
    if (!step()) {
      // errors reported below the pass (evaluator, machine) get the call chain as notes too
      if (diag::Diagnostic* d = diags_.lastError(); d && d->notes.empty()) {
        const motion::Provenance p = provenance(ir::Block{});
        for (auto it = p.chain.rbegin(); it != p.chain.rend(); ++it)
          d->notes.push_back({SourceRange{it->call, 1}, "in " + it->what});
      }
      return false;
    }
  return !diags_.hasErrors();
}

bool Expander::endOfProgram(const Frame& f) {
  if (stack_.size() == 1) { // end of the main file without M2/M30 (nct.md Q31)
    machine_.finish();
    done_ = true;
    return true;
  }
  return fail(diag::code::MissingReturn, SourceRange{f.callSite, 1},
              fmt::format("{} ended without M99 (nct-macro.md §5.2 R7)", f.what));
}

bool Expander::step() {
  Frame& f = stack_.back();
  if (f.pc >= f.program->blocks.size()) return endOfProgram(f);
  const ir::Block& b = f.program->blocks[f.pc];
  if (++blocks_ > limits_.maxBlocks)
    return fail(diag::code::TooManyBlocks, b.range,
                fmt::format("more than {} blocks executed: is this an endless loop? (exceeded "
                            "--max-blocks {}; raise it with --max-blocks N)",
                            limits_.maxBlocks, limits_.maxBlocks));
  if (b.skipLevel && machine_.setup().blockSkip.count(b.skipLevel)) {
    ++f.pc;
    return true;
  }
  if (!b.stmts.empty()) return statement(f, b);
  return ncBlock(f, b);
}

// ---------------------------------------------------------------- statements

bool Expander::statement(Frame& f, const ir::Block& b) {
  const ir::Stmt& s = b.stmts.front(); // an NCT block holds at most one
  switch (s.kind) {
  case ir::StmtKind::Assign:
    if (!assign(s)) return false;
    ++f.pc;
    return true;
  case ir::StmtKind::IfThen: {
    auto c = eval_.condition(*s.cond);
    if (!c) return false;
    if (*c && !assign(s)) return false;
    ++f.pc;
    return true;
  }
  case ir::StmtKind::Goto:
    return jumpTo(f, s.value, s.range);
  case ir::StmtKind::IfGoto: {
    auto c = eval_.condition(*s.cond);
    if (!c) return false;
    if (*c) return jumpTo(f, s.value, s.range);
    ++f.pc;
    return true;
  }
  case ir::StmtKind::While:
  case ir::StmtKind::Do: {
    bool enter = true;
    if (s.kind == ir::StmtKind::While) {
      auto c = eval_.condition(*s.cond);
      if (!c) return false;
      enter = *c;
    }
    const std::size_t here = f.pc;
    auto it =
        std::find_if(f.loops.begin(), f.loops.end(), [&](const Loop& l) { return l.head == here; });
    if (!enter) {
      if (it != f.loops.end()) f.loops.erase(it);
      f.pc = f.program->loopPartner[here] + 1; // after the paired END
      return true;
    }
    if (it == f.loops.end()) f.loops.push_back({here, 1});
    ++f.pc;
    return true;
  }
  case ir::StmtKind::End:
    return loopBack(f, f.program->loopPartner[f.pc], s.loopRange);
  case ir::StmtKind::Print:
    if (!print(s)) return false;
    ++f.pc;
    return true;
  case ir::StmtKind::Popen: // the periphery: `%`, then the first DPRNT names the file
    periphery_ = Periphery::AwaitingName;
    ++f.pc;
    return true;
  case ir::StmtKind::Pclos:
    if (periphery_ == Periphery::Open && print_) *print_ << "%\r\n";
    periphery_ = Periphery::Closed;
    ++f.pc;
    return true;
  case ir::StmtKind::Fopen:
  case ir::StmtKind::Fclos: // the print channel is the run's print output (DPRNT)
    ++f.pc;
    return true;
  case ir::StmtKind::Guard: // other dialects' statements; the NCT front end never builds them
  case ir::StmtKind::Jump:
  case ir::StmtKind::Call:
  case ir::StmtKind::CycleCall:
    return fail(diag::code::NotImplemented, s.range,
                "this statement is not implemented by the macro pass yet");
  }
  return true;
}

bool Expander::loopBack(Frame& f, std::size_t head, const SourceRange& where) {
  if (++jumps_ > limits_.maxJumps)
    return fail(diag::code::RunawayLoop, where,
                fmt::format("loop DO{} repeated more than {} times (exceeded --max-jumps {}; "
                            "raise it with --max-jumps N)",
                            f.program->blocks[head].stmts.front().loopId, limits_.maxJumps,
                            limits_.maxJumps));
  // END returns to the test of its paired WHILE even when the loop was entered by GOTO (W7)
  auto it =
      std::find_if(f.loops.begin(), f.loops.end(), [&](const Loop& l) { return l.head == head; });
  if (it != f.loops.end())
    ++it->iteration;
  else
    f.loops.push_back({head, 2});
  const ir::Stmt& s = f.program->blocks[head].stmts.front();
  if (s.kind == ir::StmtKind::While) {
    auto c = eval_.condition(*s.cond);
    if (!c) return false;
    if (!*c) {
      f.loops.erase(std::find_if(f.loops.begin(), f.loops.end(),
                                 [&](const Loop& l) { return l.head == head; }));
      f.pc = f.program->loopPartner[head] + 1;
      return true;
    }
  }
  f.pc = head + 1;
  return true;
}

bool Expander::jumpTo(Frame& f, const ir::Expr& label, const SourceRange& where) {
  auto v = eval_.value(label);
  if (!v) return false;
  if (v->vacant)
    return fail(diag::code::BlockNotFound, where, "GOTO to a vacant block number (§2.5 rule 5)");
  const double n = roundHalfAway(v->number);
  const bool inRange = n >= 1 && n <= 99999999; // N numbers (nct-macro.md §1.2); no int overflow
  if (!inRange && n > 0)
    return fail(diag::code::BlockNotFound, where,
                fmt::format("block N{:g} not found: block numbers are 1-99999999", n));
  const std::size_t target =
      inRange ? f.program->find(static_cast<std::int64_t>(n), f.pc + 1) : LoadedProgram::npos;
  if (target == LoadedProgram::npos)
    return fail(diag::code::BlockNotFound, where,
                fmt::format("block N{} not found", emit::formatNumber(n)));
  if (target <= f.pc && ++jumps_ > limits_.maxJumps)
    return fail(diag::code::RunawayLoop, where,
                fmt::format("more than {} backward jumps: runaway loop (GOTO N{}; exceeded "
                            "--max-jumps {}; raise it with --max-jumps N)",
                            limits_.maxJumps, emit::formatNumber(n), limits_.maxJumps));
  f.pc = target;
  // loops the jump left are over
  std::erase_if(f.loops, [&](const Loop& l) {
    return target < l.head || target > f.program->loopPartner[l.head];
  });
  return true;
}

bool Expander::assign(const ir::Stmt& s) {
  auto v = eval_.value(s.value);
  if (!v) return false;
  if (s.target.kind == ir::ExprKind::Named) {
    std::optional<int> index;
    if (!s.target.args.empty()) {
      index = eval_.index(s.target.args[0]);
      if (!index) return false;
    }
    const auto number = SystemVariables::numberOf(s.target.name, index);
    if (number && (*number == 3000 || *number == 3006 || *number == 3106 || *number == 3107))
      return message(s, *number, *v); // #_ALM=, #_MSG= ... carry a message
    return system_.writeNamed(s.target.name, index, *v, s.target.range);
  }
  auto n = eval_.variableNumber(s.target);
  if (!n) return false;
  return write(*n, *v, s);
}

bool Expander::write(int number, const Value& v, const ir::Stmt& s) {
  const SourceRange& where = s.target.range;
  if (number == 3000 || number == 3006 || number == 3106 || number == 3107)
    return message(s, number, v);
  if (number >= 1 && number <= 33) {
    locals()[number] = v;
    return true;
  }
  if (number >= 100 && number <= 999) {
    const double low = machine_.parameter("N1702", 0), high = machine_.parameter("N1703", 0);
    if (number >= 500 && low > 0 && number >= low && number <= high)
      return fail(diag::code::WriteProtected, where,
                  fmt::format("#{} is write-protected by N1702/N1703", number));
    commons_[number] = v;
    return true;
  }
  if (number == 0)
    return fail(diag::code::ReadOnlyVariable, where, "#0 is read-only (always vacant)");
  if (number < 100)
    return fail(diag::code::UndefinedVariable, where, fmt::format("#{} does not exist", number));
  return system_.write(number, v, where);
}

bool Expander::message(const ir::Stmt& s, int variable, const Value& v) {
  // the message number has at most three digits (nct-macro.md §2.9.2: alarm 4000 + nnn)
  if (!v.vacant && !(roundHalfAway(v.number) >= 0 && roundHalfAway(v.number) <= 999))
    return fail(diag::code::DataOutOfRange, s.target.range,
                fmt::format("#{} = {} is out of range: a message number is 0-999", variable,
                            emit::formatNumber(v.number)));
  const int n = v.vacant ? 0 : static_cast<int>(roundHalfAway(v.number));
  const motion::Provenance from = provenance(ir::Block{});
  if (variable == 3000) { // alarm: execution stops (§2.9.2)
    diags_.report(diag::Diagnostic{diag::Severity::Error,
                                   fmt::format("{}", 4000 + n),
                                   fmt::format("alarm {}: {}", 4000 + n, s.message),
                                   s.range,
                                   {}});
    return false;
  }
  machine_.message(fmt::format("MSG{}: {}", n, s.message), from, variable == 3006);
  if (variable == 3107) locals(); // the reply is read from #3107 by the system variables
  return true;
}

// DPRNT[...]: text and #v[cd] values (§6): c integer digits, d decimals, rounded, vacant = 0
bool Expander::print(const ir::Stmt& s) {
  // after POPEN the first DPRNT names the output file (§6); gcx writes it to the print output
  if (periphery_ == Periphery::AwaitingName && !s.binaryPrint) {
    std::string name;
    for (const ir::PrintItem& it : s.items)
      name += it.isVariable ? "" : it.text;
    if (print_) *print_ << "(file " << name << ")\r\n%\r\n";
    periphery_ = Periphery::Open;
    return true;
  }
  // N1757 #0 PNT: 0 = '+' and leading zeros as spaces, 1 = omitted
  const bool omit =
      machine_.parameter("N1757.PNT", 0) == 1 || machine_.parameter("N1757.0", 0) == 1;
  std::string line;
  for (const ir::PrintItem& it : s.items) {
    if (!it.isVariable) {
      for (char c : it.text)
        line += c == '*' ? ' ' : c;
      continue;
    }
    auto v = read(it.variable, s.range);
    if (!v) return false;
    const double x = v->orZero(); // vacant prints as 0
    if (s.binaryPrint) {          // #v[c]: round(v * 10^c) as a 4-byte big-endian integer
      const int exponent = it.fracDigits ? it.fracDigits : it.intDigits;
      const auto n = static_cast<std::uint32_t>(
          static_cast<std::int32_t>(std::llround(x * std::pow(10.0, exponent))));
      for (int shift = 24; shift >= 0; shift -= 8)
        line += static_cast<char>((n >> shift) & 0xFF);
      continue;
    }
    // #v[cd]: c integer digits, d decimals, rounded; sign '-' (or a space for '+')
    const std::string digits = fmt::format("{:.{}f}", std::fabs(x), it.fracDigits);
    const std::size_t point = digits.find('.');
    std::string integer = digits.substr(0, point);
    const std::string fraction = point == std::string::npos ? "" : digits.substr(point);
    if (!omit && static_cast<int>(integer.size()) < it.intDigits)
      integer.insert(0, it.intDigits - integer.size(), ' ');
    line += x < 0 ? "-" : omit ? "" : " ";
    line += integer + fraction;
  }
  if (print_) *print_ << line << "\r\n";
  return true;
}

// ---------------------------------------------------------------- NC blocks and calls

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

bool Expander::flatten(const ir::Block& b, ir::Block& flat) {
  // resolve every value; vacant bare references drop their word (§2.5 rule 4)
  flat = b;
  flat.words.clear();
  bool call = false;
  for (const ir::Word& w : b.words)
    if (isLiteral(w, 'M', 98) || isLiteral(w, 'M', 99) ||
        (w.is('G') && w.isLiteral() && (w.number == 65 || w.number == 66)))
      call = true;
  WordOptions opt;
  opt.callNumber = call;
  for (const ir::Word& w : b.words) {
    if (w.kind != ir::ValueKind::Expression && w.address != "AX") {
      flat.words.push_back(w);
      continue;
    }
    ir::Word resolved = w;
    if (w.address == "AX") { // AX[n]=v: the axis by its number in the channel (§2.6)
      auto n = eval_.number(w.axisIndex.front());
      if (!n) return false;
      static const char* const names[] = {"X", "Y", "Z", "A", "B", "C"};
      const long k = std::lround(*n);
      if (k < 1 || k > 6)
        return fail("2018", w.range, fmt::format("wrong physical axis number {}", k));
      resolved.address = names[k - 1];
      resolved.axisIndex.clear();
    }
    if (resolved.kind == ir::ValueKind::Number) { // AX[e]=<literal>
      flat.words.push_back(std::move(resolved));
      continue;
    }
    WordValue v = wordValue(resolved, eval_, opt);
    if (v.result == WordResult::Error) return false;
    if (v.result == WordResult::Dropped) continue;
    resolved.kind = ir::ValueKind::Number;
    resolved.number = v.number;
    resolved.expr = ir::Expr{};
    flat.words.push_back(std::move(resolved));
  }
  return true;
}

bool Expander::ncBlock(Frame& f, const ir::Block& b) {
  ir::Block flat;
  if (!flatten(b, flat)) return false;
  // inside a configured call, configured codes are ordinary (§5.8 P3, P4); without
  // parameters no code is configured
  if (machine_.hasParameters() && !insideConfiguredCall()) {
    const std::size_t before = diags_.errorCount();
    if (auto c = configuredCall(flat)) return runConfiguredCall(f, b, flat, *c);
    if (diags_.errorCount() != before) return false;
  }
  const ir::Word* g65 = nullptr;
  for (const ir::Word& w : flat.words)
    if (w.is('G') && (w.number == 65 || w.number == 66 || w.number == 66.1 || w.number == 67))
      g65 = &w;
  if (g65 && g65->number != 65) return modalBlock(f, b, flat, *g65);
  // G66.1 in force: every following NC block is a call, its words the arguments (§5.6 E2)
  if (const ModalCall* m = visibleModalCall(); m && m->everyBlock && !flat.words.empty()) {
    std::array<Value, 34> args;
    ir::Block argsBlock = flat;
    int gCount = 0;
    for (const ir::Word& w : flat.words)
      if (w.is('G') && ++gCount == 2)
        return fail(diag::code::ForbiddenAddress, w.range,
                    "a second G code in a block under G66.1 (000:14939-14943)");
    std::erase_if(argsBlock.words, [](const ir::Word& w) { return w.is('G'); });
    if (!bindCall(argsBlock, 0, nullptr, args)) return false;
    args[10] = Value::empty();
    for (const ir::Word& w : flat.words) { // G -> #10, L -> #12, P -> #16 in following blocks
      if (w.is('G')) args[10] = Value::of(w.number);
      if (w.is('L')) args[12] = Value::of(w.number);
      if (w.is('P')) args[16] = Value::of(w.number);
    }
    const std::size_t index = static_cast<std::size_t>(m - modalCalls_.data());
    return pushMacro(f, m->program, args, m->times, m->what, b.range, index);
  }
  const ir::Word* m98 = findLiteral(flat, 'M', 98);
  const ir::Word* m99 = findLiteral(flat, 'M', 99);
  const ir::Word* p = flat.find('P');
  const ir::Word* l = flat.find('L');
  const ir::Word* file = nullptr;
  for (const ir::Word& w : flat.words)
    if (w.kind == ir::ValueKind::Path) file = &w;

  if (g65) {
    if (!p && !file) return fail(diag::code::MissingData, g65->range, "G65 without P or <file>");
    const std::int64_t times = l ? static_cast<std::int64_t>(l->number) : 1;
    return callMacro(f, b, p, file, times);
  }
  if (m98 || m99) {
    // the NC part of the block runs first, then the call or return (§1.4 K5)
    ir::Block nc = flat;
    std::erase_if(nc.words, [&](const ir::Word& w) {
      return isLiteral(w, 'M', 98) || isLiteral(w, 'M', 99) || w.is('P') || w.is('L') ||
             w.kind == ir::ValueKind::Path;
    });
    if (!nc.words.empty() && onFlat_) onFlat_(nc);
    if (!nc.words.empty() && !machine_.execute(nc, provenance(b))) {
      if (machine_.ended()) done_ = true;
      return machine_.ended();
    }
    if (m98) {
      if (!p && !file) return fail(diag::code::MissingData, m98->range, "M98 without P or <file>");
      const std::int64_t times = l ? static_cast<std::int64_t>(l->number) : 1;
      if (times < 1)
        return fail(diag::code::DataOutOfRange, l->range, "M98 L must be 1 or more (nct.md Q6)");
      return callSubprogram(f, b, p, file, times);
    }
    return returnFromCall(f, flat);
  }
  if (onFlat_) onFlat_(flat);
  if (!machine_.execute(flat, provenance(b))) {
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
  // G66: after each motion block, the most recent visible modal call (§5.5 D2, D3)
  if (const ModalCall* m = visibleModalCall(); m && !m->everyBlock && movesAxes(flat)) {
    const std::size_t index = static_cast<std::size_t>(m - modalCalls_.data());
    return pushMacro(f, m->program, m->args, m->times, m->what, b.range, index);
  }
  ++f.pc;
  return true;
}

bool Expander::callSubprogram(Frame& f, const ir::Block& b, const ir::Word* p, const ir::Word* file,
                              std::int64_t times) {
  if (static_cast<int>(stack_.size()) > limits_.maxDepth)
    return fail(diag::code::CallNesting, b.range,
                fmt::format("more than {} nested subprogram and macro calls", limits_.maxDepth));
  const LoadedProgram* callee =
      p ? library_.byNumber(static_cast<std::int64_t>(p->number), *f.program, p->range)
        : library_.byName(file->text, *f.program, file->range);
  if (!callee) return false;
  Frame c;
  c.program = callee;
  c.level = f.level; // M98 shares the caller's locals (V2)
  c.remaining = times - 1;
  c.callBlock = f.pc;
  c.callSite = b.range.begin;
  machine_.setCalledProgram(p ? static_cast<int>(p->number) : 0);
  c.what = p ? fmt::format("O{:04} (M98 P{})", static_cast<std::int64_t>(p->number),
                           static_cast<std::int64_t>(p->number))
             : fmt::format("{} (M98 <{}>)", file->text, file->text);
  stack_.push_back(std::move(c));
  return true;
}

bool Expander::bindCall(const ir::Block& b, double callCode, const ir::Word* p,
                        std::array<Value, 34>& args, bool controlPL) {
  // argument values from the source words: a vacant bare reference leaves its local vacant
  std::map<const ir::Word*, Value> values;
  for (const ir::Word& w : b.words) {
    if (w.kind == ir::ValueKind::Number) {
      values[&w] = Value::of(w.number);
    } else if (w.kind == ir::ValueKind::Expression) {
      auto v = eval_.value(w.expr);
      if (!v) return false;
      if (!bareReference(w.expr) && v->vacant) *v = Value::of(0); // [e] is always a number
      values[&w] = *v;
    }
  }
  nct::ArgumentResult bound = nct::bindArguments(
      b, [&](const ir::Word& w) { return values.count(&w) && values[&w].vacant; }, {}, controlPL);
  if (!bound.ok()) return fail(bound.code, bound.offending->range, bound.message);
  args = {};
  bool taken[34] = {};
  for (const nct::ArgumentBinding& a : bound.bindings) {
    args[a.variable] = values[a.word];
    taken[a.variable] = true;
  }
  // the control words' values (§5.3 C3): #10 = the call code, #16 = P, #12 = L
  if (!taken[10]) args[10] = Value::of(callCode);
  if (!controlPL) return true;
  if (!taken[16] && p) args[16] = Value::of(p->number);
  for (const ir::Word& w : b.words)
    if (w.is('L') && !taken[12] && values.count(&w)) args[12] = values[&w];
  return true;
}

bool Expander::insideConfiguredCall() const {
  for (const Frame& f : stack_)
    if (f.configured) return true;
  return false;
}

std::optional<Expander::ConfiguredCall> Expander::configuredCall(const ir::Block& flat) {
  auto prm = [&](int n) { return machine_.parameter(fmt::format("N{:04}", n), 0); };
  auto bit = [&](int n, int b, const char* name) {
    return machine_.parameter(fmt::format("N{:04}.{}", n, b), 0) == 1 ||
           machine_.parameter(fmt::format("N{:04}.{}", n, name), 0) == 1;
  };
  std::optional<ConfiguredCall> found;
  bool conflict = false;
  auto take = [&](ConfiguredCall c) {
    if (found) {
      fail("NCTX09", c.word->range, "two codes configured as calls in one block (§5.8 P6)");
      conflict = true;
      return;
    }
    found = c;
  };
  for (const ir::Word& w : flat.words) {
    if (w.kind != ir::ValueKind::Number || conflict) continue;
    if (w.is('G')) {
      for (int i = 0; i < 10; ++i) { // N1704-N1713: G(9010)...G(9019); 1000 means G0
        const double v = prm(1704 + i);
        if (v == 0) continue;
        const double code = std::fabs(v) == 1000 ? 0 : std::fabs(v);
        if (w.number == code)
          take({v < 0 ? ConfiguredCall::ModalG : ConfiguredCall::MacroG, 9010 + i, &w});
      }
      const double start = prm(1714), first = prm(1715), count = prm(1716);
      const double g = w.number;
      if (count > 0 && g == std::floor(g) && g >= std::fabs(start) && g < std::fabs(start) + count)
        take({start < 0 ? ConfiguredCall::ModalG : ConfiguredCall::MacroG,
              static_cast<std::int64_t>(first + g - std::fabs(start)), &w});
    } else if (w.is('M')) {
      const double m = w.number;
      for (int i = 0; i < 10; ++i) {
        if (prm(1733 + i) != 0 && prm(1733 + i) == m) take({ConfiguredCall::MacroM, 9020 + i, &w});
        if (prm(1720 + i) != 0 && prm(1720 + i) == m)
          take({ConfiguredCall::SubprogramM, 9000 + i, &w});
      }
      if (const double c = prm(1745); c > 0 && m >= prm(1743) && m < prm(1743) + c)
        take({ConfiguredCall::MacroM, static_cast<std::int64_t>(prm(1744) + m - prm(1743)), &w});
      if (const double c = prm(1732); c > 0 && m >= prm(1730) && m < prm(1730) + c)
        take({ConfiguredCall::SubprogramM, static_cast<std::int64_t>(prm(1731) + m - prm(1730)),
              &w});
    } else if (w.address.size() == 1) { // N1746 ABCST: A B C S T call O9030-O9034
      static const char letters[] = {'A', 'B', 'C', 'S', 'T'};
      static const char* const names[] = {"AM", "BM", "CM", "SM", "TM"};
      for (int i = 0; i < 5; ++i)
        if (w.address[0] == letters[i] && bit(1746, i, names[i]))
          take({ConfiguredCall::SubprogramLetter, 9030 + i, &w, 195 + i});
      // N1747-N1750: four letters (their ASCII codes) calling the programs of N1751-N1754,
      // the value in #191-#194
      for (int i = 0; i < 4; ++i)
        if (prm(1747 + i) == static_cast<unsigned char>(w.address[0]) && prm(1751 + i) > 0)
          take({ConfiguredCall::SubprogramLetter, static_cast<std::int64_t>(prm(1751 + i)), &w,
                191 + i});
    }
  }
  if (conflict) return std::nullopt;
  return found;
}

bool Expander::runConfiguredCall(Frame& f, const ir::Block& b, const ir::Block& flat,
                                 const ConfiguredCall& c) {
  const LoadedProgram* program = library_.byNumber(c.program, *f.program, c.word->range);
  if (!program) return false;
  const std::string what = fmt::format("O{:04} ({}{} configured call)", c.program, c.word->address,
                                       emit::formatNumber(c.word->number));
  const auto isCallWord = [&](const ir::Word& w) {
    return w.range.begin.offset == c.word->range.begin.offset && w.address == c.word->address;
  };
  if (c.kind != ConfiguredCall::SubprogramM && c.kind != ConfiguredCall::SubprogramLetter) {
    // G65 type: the other words are arguments, for a G code P and L too (§5.4); #10 = the code
    ir::Block argsBlock = b;
    std::erase_if(argsBlock.words, isCallWord);
    std::array<Value, 34> args;
    if (!bindCall(argsBlock, c.word->number, nullptr, args, c.kind == ConfiguredCall::MacroM))
      return false;
    if (c.kind == ConfiguredCall::ModalG) { // G66 type (N1755 MEQ=0)
      ModalCall m;
      m.program = program;
      m.args = args;
      m.what = what;
      modalCalls_.push_back(m);
      ++f.pc;
      return true;
    }
    if (!pushMacro(f, program, args, 1, what, b.range, f.modalVisible)) return false;
    stack_.back().configured = true;
    return true;
  }
  // subprogram type: the block's NC part runs first, then `M98 P<program>` (§5.8)
  ir::Block nc = flat;
  std::erase_if(nc.words, isCallWord);
  if (c.kind == ConfiguredCall::SubprogramLetter)
    commons_[c.valueVariable] = Value::of(c.word->number); // #195-#199 (§5.8)
  if (!nc.words.empty()) {
    if (onFlat_) onFlat_(nc);
    if (!machine_.execute(nc, provenance(b))) {
      if (machine_.ended()) done_ = true;
      return machine_.ended();
    }
  }
  if (static_cast<int>(stack_.size()) > limits_.maxDepth)
    return fail(diag::code::CallNesting, b.range,
                fmt::format("more than {} nested subprogram and macro calls", limits_.maxDepth));
  Frame callee;
  callee.program = program;
  callee.level = f.level;
  callee.callBlock = f.pc;
  callee.callSite = b.range.begin;
  callee.what = what;
  callee.configured = true;
  callee.modalVisible = f.modalVisible;
  stack_.push_back(std::move(callee));
  return true;
}

bool Expander::pushMacro(Frame& f, const LoadedProgram* program, const std::array<Value, 34>& args,
                         std::int64_t times, std::string what, const SourceRange& site,
                         std::size_t modalVisible) {
  if (static_cast<int>(stack_.size()) > limits_.maxDepth)
    return fail(diag::code::CallNesting, site,
                fmt::format("more than {} nested subprogram and macro calls", limits_.maxDepth));
  Frame c;
  c.program = program;
  c.macro = true;
  c.remaining = times - 1;
  c.callBlock = f.pc;
  c.callSite = site.begin;
  c.args = args;
  c.what = std::move(what);
  c.modalVisible = modalVisible;
  c.level = static_cast<int>(locals_.size());
  locals_.push_back(args);
  stack_.push_back(std::move(c));
  return true;
}

bool Expander::callMacro(Frame& f, const ir::Block& b, const ir::Word* p, const ir::Word* file,
                         std::int64_t times) {
  if (static_cast<int>(stack_.size()) > limits_.maxDepth)
    return fail(diag::code::CallNesting, b.range,
                fmt::format("more than {} nested subprogram and macro calls", limits_.maxDepth));
  if (times < 1) {
    ++f.pc;
    return true;
  }
  std::array<Value, 34> args;
  if (!bindCall(b, 65, p, args)) return false;
  // a system cycle written as a macro (cycles.md §5): its checks come before the call
  const std::int64_t number = p ? static_cast<std::int64_t>(p->number) : 0;
  if (const CycleMacro* c = p ? machine_.profile().cycleMacro(number) : nullptr)
    if (!checkCycleMacroCall(*c, {b, *p, args, *f.program}, machine_, library_, diags_))
      return false;
  const LoadedProgram* callee =
      p ? library_.byNumber(static_cast<std::int64_t>(p->number), *f.program, p->range)
        : library_.byName(file->text, *f.program, file->range);
  if (!callee) return false;
  machine_.setCalledProgram(p ? static_cast<int>(p->number) : 0);
  std::string what = p ? fmt::format("O{:04} (G65 P{})", static_cast<std::int64_t>(p->number),
                                     static_cast<std::int64_t>(p->number))
                       : fmt::format("{} (G65 <{}>)", file->text, file->text);
  return pushMacro(f, callee, args, times, std::move(what), b.range, f.modalVisible);
}

const Expander::ModalCall* Expander::visibleModalCall() const {
  // in a macro started by modal entry j only the entries before j are visible (§5.5 D5)
  const std::size_t visible = std::min(stack_.back().modalVisible, modalCalls_.size());
  return visible ? &modalCalls_[visible - 1] : nullptr;
}

// G66 / G66.1 register a modal call, G67 removes the most recent (§5.5-§5.7)
bool Expander::modalBlock(Frame& f, const ir::Block& b, const ir::Block& flat,
                          const ir::Word& code) {
  if (code.number == 67) {
    if (!modalCalls_.empty()) modalCalls_.pop_back();
    machine_.setModalCode(12, modalCalls_.empty()             ? 670
                              : modalCalls_.back().everyBlock ? 661
                                                              : 660);
    ++f.pc;
    return true;
  }
  const bool everyBlock = code.number == 66.1;
  const ir::Word* p = flat.find('P');
  if (!p) return fail(diag::code::MissingData, code.range, "G66 needs P (program number)");
  ModalCall m;
  m.everyBlock = everyBlock;
  m.program = library_.byNumber(static_cast<std::int64_t>(p->number), *f.program, p->range);
  if (!m.program) return false;
  const ir::Word* l = flat.find('L');
  m.times = l ? static_cast<std::int64_t>(l->number) : 1;
  if (!bindCall(b, everyBlock ? 66.1 : 66, p, m.args)) return false;
  m.what = fmt::format("O{:04} (G{} P{})", static_cast<std::int64_t>(p->number),
                       everyBlock ? "66.1" : "66", static_cast<std::int64_t>(p->number));
  modalCalls_.push_back(m);
  machine_.setModalCode(12, everyBlock ? 661 : 660);
  if (!everyBlock) { // G66 calls nothing and moves nothing in its own block (D1)
    ++f.pc;
    return true;
  }
  // G66.1 also calls at once from its own block (E1); the macro returns to the next block
  if (m.times < 1) {
    ++f.pc;
    return true;
  }
  return pushMacro(f, m.program, m.args, m.times, m.what, b.range, modalCalls_.size() - 1);
}

bool Expander::returnFromCall(Frame& f, const ir::Block& flat) {
  const ir::Word* p = flat.find('P');
  const ir::Word* l = flat.find('L');
  if (stack_.size() == 1) {
    // M99 in the main program: back to its start or to N P (§5.2 R6) - an endless loop
    if (++jumps_ > limits_.maxJumps)
      return fail(
          diag::code::RunawayLoop, flat.range,
          fmt::format("M99 in the main program looped more than {} times (exceeded --max-jumps "
                      "{}; raise it with --max-jumps N)",
                      limits_.maxJumps, limits_.maxJumps));
    if (!p) {
      f.pc = 0;
      return true;
    }
    const std::size_t t = f.program->find(static_cast<std::int64_t>(p->number), 0);
    if (t == LoadedProgram::npos)
      return fail(diag::code::BlockNotFound, p->range,
                  fmt::format("block N{} not found", emit::formatNumber(p->number)));
    f.pc = t;
    return true;
  }
  if (l) f.remaining = static_cast<std::int64_t>(l->number); // §5.2 R5
  if (f.remaining > 0) {
    // each repetition jumps back to the start of the called program
    if (++jumps_ > limits_.maxJumps)
      return fail(diag::code::RunawayLoop, flat.range,
                  fmt::format("{} repeated more than {} times by its L count (exceeded "
                              "--max-jumps {}; raise it with --max-jumps N)",
                              f.what, limits_.maxJumps, limits_.maxJumps));
    --f.remaining;
    f.pc = 0;
    f.loops.clear();
    if (f.macro) locals_[f.level] = f.args; // each run starts from the arguments (C2)
    return true;
  }
  const Frame callee = f;
  if (callee.macro) locals_.pop_back(); // V3: the caller's frame is visible again
  stack_.pop_back();
  Frame& caller = stack_.back();
  if (p) {
    const std::size_t t =
        caller.program->find(static_cast<std::int64_t>(p->number), callee.callBlock + 1);
    if (t == LoadedProgram::npos)
      return fail(
          diag::code::BlockNotFound, p->range,
          fmt::format("block N{} not found in the calling program", emit::formatNumber(p->number)));
    caller.pc = t;
  } else {
    caller.pc = callee.callBlock + 1;
  }
  return true;
}

// ---------------------------------------------------------------- variables

std::optional<Value> Expander::read(int number, const SourceRange& where) {
  if (number == 0) return Value::empty();
  if (number >= 1 && number <= 33) return locals()[number];
  if (number >= 100 && number <= 999) {
    auto it = commons_.find(number);
    return it == commons_.end() ? Value::empty() : it->second;
  }
  if (number < 100) {
    diags_.error(diag::code::UndefinedVariable, where, fmt::format("#{} does not exist", number));
    return std::nullopt;
  }
  return system_.read(number, where);
}

std::optional<Value> Expander::readNamed(const std::string& name, std::optional<int> index,
                                         const SourceRange& where) {
  return system_.readNamed(name, index, where);
}

std::optional<double> Expander::parameter(int id, std::optional<int> bit, std::optional<int> index,
                                          const SourceRange& where) {
  std::string key = fmt::format("N{:04}", id);
  if (bit) key += fmt::format(".{}", *bit);
  (void)index; // one channel, parameters per axis/spindle are not modelled
  const double missing = -1.234e300;
  const double v = machine_.parameter(key, missing);
  if (v == missing) {
    diags_.error(diag::code::ParameterMissing, where,
                 fmt::format("parameter {} is not in the setup", key));
    return std::nullopt;
  }
  return v;
}

std::optional<int> Expander::axisNumber(char letter, const SourceRange& where) {
  static const std::string axes = "XYZABC";
  const auto pos = axes.find(letter);
  if (pos == std::string::npos) {
    diags_.error(diag::code::ForbiddenAddress, where,
                 fmt::format("no axis {} in this channel", letter));
    return std::nullopt;
  }
  return static_cast<int>(pos) + 1;
}

bool mayNeedExpansion(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string chunk(1 << 16, '\0');
  std::string carry;
  // G70.7-G73.7 read their contour blocks by N number, as jumps do
  static const char* const markers[] = {"M98",   "M99",   "G65",   "G66",   "GOTO",  "WHILE",
                                        "DO",    "END",   "IF",    "DPRNT", "BPRNT", "POPEN",
                                        "G70.7", "G71.7", "G72.7", "G73.7"};
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    std::string text = carry + chunk.substr(0, static_cast<std::size_t>(in.gcount()));
    for (char& c : text)
      c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    // '[': an expression, which only the expansion pass evaluates
    if (text.find_first_of("#[") != std::string::npos) return true;
    for (const char* m : markers)
      if (text.find(m) != std::string::npos) return true;
    carry = text.size() > 8 ? text.substr(text.size() - 8) : text;
  }
  return false;
}

} // namespace gcx::macro
