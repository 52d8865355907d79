#include "translate/lift.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <set>

#include "dialect/control_flow.h"
#include "emit/number.h"
#include "ir/items.h"
#include "translate/expression_lowering.h"

namespace gcx::xlate {

namespace {

// The G codes whose words mean the same on every control gcx knows: motion, planes, distance
// and feed modes, work offsets, length and radius compensation, exact stop, cycle cancel.
bool neutralAction(GAction a) {
  switch (a) {
  case GAction::Rapid:
  case GAction::Linear:
  case GAction::ArcCW:
  case GAction::ArcCCW:
  case GAction::Dwell:
  case GAction::ExactStopOnce:
  case GAction::PlaneXY:
  case GAction::PlaneZX:
  case GAction::PlaneYZ:
  case GAction::Metric:
  case GAction::Absolute:
  case GAction::Incremental:
  case GAction::FeedPerMinute:
  case GAction::FeedPerRevolution:
  case GAction::WorkOffset:
  case GAction::LengthPlus:
  case GAction::LengthMinus:
  case GAction::LengthCancel:
  case GAction::RadiusCompOff:
  case GAction::RadiusCompLeft:
  case GAction::RadiusCompRight:
  case GAction::CycleCancel:
  case GAction::ExactStopMode:
  case GAction::ContinuousMode:
  case GAction::ReferenceReturn:
  case GAction::FilletCW:
  case GAction::FilletCCW:
    return true;
  default:
    return false;
  }
}

// A canned drilling cycle's code, or the return level of one (the cycle's words).
bool drillingAction(GAction a) {
  return a == GAction::DrillCycle || a == GAction::LevelDrillCycle || a == GAction::ReturnInitial ||
         a == GAction::ReturnR;
}

// A remapped code that runs a cycle program after each move (WL4 G81 calls %81, wl4.md §5.1).
bool cycleProgramCall(const Remap& r) {
  return r.action == FlowAction::ModalCall && r.program == ProgramSource::CodeDigits;
}

bool isArc(GAction a) {
  return a == GAction::ArcCW || a == GAction::ArcCCW || a == GAction::FilletCW ||
         a == GAction::FilletCCW;
}

// An NCT-style numbered label: the digits of a jump's literal target.
std::string labelDigits(double n) {
  return std::to_string(static_cast<long long>(std::llround(n)));
}

// "010" -> "10": a label's number without its leading zeros (WL4 writes labels with one).
std::string withoutLeadingZeros(const std::string& digits) {
  const std::size_t first = digits.find_first_not_of('0');
  return first == std::string::npos ? "0" : digits.substr(first);
}

int afterRank(FlowKind k) {
  switch (k) {
  case FlowKind::Assign:
    return 0;
  case FlowKind::Call:
    return 1;
  case FlowKind::Return:
  case FlowKind::EndProgram:
  case FlowKind::RepeatStart:
  case FlowKind::RepeatEnd:
    return 2;
  default:
    return 3;
  }
}

class Lifter {
public:
  Lifter(const Profile& p, const SettingLookup& settings, Unkept& why)
      : p_(p), flow_(*p.controlFlow), settings_(settings), why_(why) {}

  bool unit(const std::vector<ir::Block>& blocks, UnitSteps& out);

private:
  bool fail(const SourceRange& where, std::string what, std::string why) {
    why_ = {where, std::move(what), std::move(why)};
    return false;
  }
  bool block(const ir::Block& b, Step& s);
  bool statement(const ir::Stmt& st, Step& s, bool afterNc);
  bool remapped(const ir::Word& w, const Remap& r, const ir::Block& b, Step& s,
                std::set<const ir::Word*>& consumed);
  bool gcode(const ir::Word& w, const ir::Block& b, Step& s, std::set<const ir::Word*>& consumed);
  bool mcode(const ir::Word& w, Step& s);
  bool operand(const ir::Word& w, Step& s);
  bool value(const ir::Word& w, Value& v);
  bool isLabel(const ir::Block& b) const;

  const Profile& p_;
  const ControlFlow& flow_;
  const SettingLookup& settings_;
  Unkept& why_;
  std::set<std::string> jumpTargets_; // numbered targets of the unit's jumps (NCT GOTO)
  std::vector<int> loops_;            // open WHILE loops: their ids
  int nextLoop_ = 0;
  std::optional<GAction> motion_; // the motion mode as the text runs, when known
  bool main_ = false;
  bool cycleMode_ = false;       // a drilling cycle drills at every position, as the text runs
  std::optional<bool> absolute_; // G90 as the text runs, when known
  bool referenceReturn(const ir::Word& w, const GCodeSpec& g, const ir::Block& b);
  bool cycleBlock(const ir::Block& b, const std::set<const ir::Word*>& consumed, bool registers);
};

bool Lifter::isLabel(const ir::Block& b) const {
  if (!b.sequence) return false;
  if (flow_.isLabel) return flow_.isLabel(b.sequenceText);
  return jumpTargets_.count(labelDigits(static_cast<double>(*b.sequence))) > 0;
}

bool Lifter::value(const ir::Word& w, Value& v) {
  v.range = w.range;
  if (w.incremental)
    return fail(w.range, w.address + " with the I operator",
                "an incremental word in an absolute block has no form on the other controls");
  if (w.kind == ir::ValueKind::Path)
    return fail(w.range, "a program named by its file", "the other controls name programs only");
  v.literal = w.isLiteral();
  v.number = w.number;
  if (!v.literal) v.expr = w.expr;
  return true;
}

bool Lifter::unit(const std::vector<ir::Block>& blocks, UnitSteps& out) {
  main_ = out.main;
  if (main_) absolute_ = true; // at power-on
  for (const ir::Block& b : blocks)
    for (const ir::Stmt& st : b.stmts)
      if (st.kind == ir::StmtKind::Goto || st.kind == ir::StmtKind::IfGoto) {
        if (st.value.kind != ir::ExprKind::Number)
          return fail(st.range, "a computed jump", "its target is known only at run time");
        jumpTargets_.insert(labelDigits(st.value.number));
      }
  for (const ir::Block& b : blocks) {
    if (b.kind == ir::BlockKind::ProgramStart || b.kind == ir::BlockKind::ProgramEnd) continue;
    Step s;
    s.range = b.range;
    if (!block(b, s)) return false;
    out.steps.push_back(std::move(s));
  }
  if (!loops_.empty())
    return fail(blocks.empty() ? SourceRange{} : blocks.back().range, "WHILE",
                "a loop without its END");
  return true;
}

bool Lifter::block(const ir::Block& b, Step& s) {
  if (b.kind == ir::BlockKind::Data)
    return fail(b.range, "a data-entry section", "the other controls set parameters otherwise");
  if (b.kind == ir::BlockKind::ContourEnd)
    return fail(b.range, "a contour end", "it belongs to a cycle, which is run out into motion");
  if (b.skipLevel)
    return fail(b.range, "block skip /", "the controls' skip switches differ in number and sense");
  if (b.sequence) {
    if (isLabel(b))
      s.label = withoutLeadingZeros(
          b.sequenceText.empty() ? labelDigits(static_cast<double>(*b.sequence)) : b.sequenceText);
    else
      s.sequence =
          b.sequenceText.empty() ? labelDigits(static_cast<double>(*b.sequence)) : b.sequenceText;
  }
  for (const ir::Comment& c : b.comments)
    s.comments.push_back(c.text);

  // remapped words (calls, returns, repeats) and the words they consume
  std::set<const ir::Word*> consumed;
  for (const ir::Word& w : b.words) {
    if (!w.isLiteral() || !flow_.remaps.mayMatch(w.address) || consumed.count(&w)) continue;
    const Remap* r = flow_.remaps.find(w.address, w.number);
    if (!r || r->onlyIfProgramExists) continue;
    bool parameter = false; // a word after a cycle's code is its parameter (FMS G150 ... P10)
    if (r->parameterCode)
      for (const ir::Word& x : b.words) {
        if (&x == &w) break;
        parameter = parameter || (x.is('G') && x.isLiteral() && r->parameterCode(x.number));
      }
    if (parameter) continue;
    if (!remapped(w, *r, b, s, consumed)) return false;
    consumed.insert(&w);
  }
  // the block's motion mode first: it says what I J K R L mean
  for (const ir::Word& w : b.words)
    if (w.is('G') && w.isLiteral() && !consumed.count(&w))
      if (const GCodeSpec* g = p_.gcode(w.number))
        if (g->action == GAction::Rapid || g->action == GAction::Linear || isArc(g->action))
          motion_ = g->action;

  const bool drills = cycleBlock(b, consumed, s.cycle);
  s.cycle = drills;
  if (motion_ && (*motion_ == GAction::FilletCW || *motion_ == GAction::FilletCCW))
    for (const ir::Word& w : b.words)
      if (w.address.size() == 1 &&
          std::string_view("XYZUVW").find(w.address[0]) != std::string_view::npos)
        s.fillet = motion_;
  for (const ir::Word& w : b.words)
    if (drills && w.address.size() == 1 &&
        std::string_view("XYZABCUVW").find(w.address[0]) != std::string_view::npos)
      s.cycleMoves = true;

  // items in source order: statements before the first word run before the NC part; a
  // statement after a word runs after it (WL4 evaluates a block left to right, wl4.md §1.9)
  bool ncSeen = false, afterStatement = false, failed = false;
  ir::forEachItem(b, [&](ir::ItemRef r) {
    if (failed) return;
    if (r.kind == ir::ItemKind::Stmt) {
      const ir::Stmt& st = b.stmts[r.index];
      const bool after = ncSeen || s.guard.has_value();
      if (!statement(st, s, after)) failed = true;
      if (after && st.kind != ir::StmtKind::Guard) afterStatement = true;
      return;
    }
    if (r.kind != ir::ItemKind::Word) return;
    const ir::Word& w = b.words[r.index];
    if (consumed.count(&w)) return;
    if (afterStatement) { // a word after a statement would act in another order here
      failed = !fail(w.range, w.address + " after a statement",
                     "the words of one block would act in another order");
      return;
    }
    if (w.is('O')) return; // the program's number: the target names its programs itself
    ncSeen = true;
    if (w.is('G')) {
      failed = !gcode(w, b, s, consumed);
    } else if (w.is('M')) {
      failed = !mcode(w, s);
    } else if (drills && !w.is('S')) {
      // a position or a word of the cycle: in the holes its runs drill
      if (w.address.size() == 1 &&
          std::string_view("XYZABC").find(w.address[0]) != std::string_view::npos) {
        Operand o;
        o.letter = w.address[0];
        failed = !value(w, o.value);
        s.cyclePositions.push_back(std::move(o));
      }
      return;
    } else if (!consumed.count(&w)) {
      failed = !operand(w, s);
    }
  });
  if (failed) return false;
  if (s.otherwise) {
    // the words after the IF replace those of their letter before it: one move with the final
    // values (wl4.md §1.9); what follows the IF is words only
    if (s.modes.size() != s.otherwise->modes.size() || !s.after.empty() ||
        s.machine.size() != s.otherwise->machine.size() ||
        s.dwellSeconds.has_value() != s.otherwise->dwellSeconds.has_value())
      return fail(s.range, "IF in the middle of a block",
                  "only axis and value words may follow it to be kept");
    std::vector<Operand> merged;
    for (std::size_t i = 0; i < s.words.size(); ++i) {
      bool later = false;
      for (std::size_t j = i + 1; j < s.words.size(); ++j)
        later = later || s.words[j].letter == s.words[i].letter;
      if (!later) merged.push_back(s.words[i]);
    }
    s.words = std::move(merged);
  }
  // a return straight to machine zero names its axes; their values mean nothing
  for (const Mode& m : s.modes)
    if (m.action == GAction::ReferenceReturn && p_.machine.directReferencePointKey)
      for (Operand& o : s.words)
        if (std::string_view("XYZABC").find(o.letter) != std::string_view::npos)
          o.value = Value{true, 0, {}, o.value.range};
  if (s.dwellSeconds && !p_.machine.dwellAfterMotion)
    for (const Operand& o : s.words)
      if (std::string_view("XYZABC").find(o.letter) != std::string_view::npos)
        return fail(o.value.range, std::string(1, o.letter) + " in a dwell block",
                    "the dwell's block does not move on this control");
  // after the NC part: assignments as scanned, then calls and returns, then jumps (a call is
  // made after all other commands of its block, the jump after the return; wl4.md §1.9)
  std::stable_sort(s.after.begin(), s.after.end(), [](const Flow& x, const Flow& y) {
    return afterRank(x.kind) < afterRank(y.kind);
  });
  return !failed;
}

// Whether b drills: a drilling cycle's code (or `registers`, a cycle program's modal call), or a
// position while a cycle is in force. Updates the cycle mode as the text runs.
bool Lifter::cycleBlock(const ir::Block& b, const std::set<const ir::Word*>& consumed,
                        bool registers) {
  bool code = registers, cancel = false, motion = false;
  for (const ir::Word& w : b.words) {
    if (!w.is('G') || !w.isLiteral() || consumed.count(&w)) continue;
    const GCodeSpec* g = p_.gcode(w.number);
    if (!g) continue;
    if (g->action == GAction::DrillCycle) {
      code = true;
      cycleMode_ = true;
    } else if (g->action == GAction::LevelDrillCycle) {
      // a level cycle is modal only where the machine says so (fms3000.md §5.1)
      code = true;
      const int bit = g->arg - 81;
      cycleMode_ = bit >= 0 && bit < 8 &&
                   ((static_cast<long>(settings_(Setting::ModalLevelCycles)) >> bit) & 1);
    } else if (g->action == GAction::ReturnInitial || g->action == GAction::ReturnR) {
      code = code || cycleMode_;
    } else if (g->action == GAction::CycleCancel) {
      cancel = true;
    } else if (g->action == GAction::Rapid || g->action == GAction::Linear || isArc(g->action)) {
      motion = true;
    }
  }
  if (cancel || (motion && !code && p_.machine.motionCancelsCycle)) cycleMode_ = false;
  if (code) return true;
  if (!cycleMode_) return false;
  for (const ir::Word& w : b.words)
    if (w.address.size() == 1 &&
        std::string_view("XYZABCUVW").find(w.address[0]) != std::string::npos)
      return true;
  return false;
}

bool Lifter::statement(const ir::Stmt& st, Step& s, bool afterNc) {
  Flow f;
  f.range = st.range;
  std::vector<Flow>& to = afterNc ? s.after : s.before;
  switch (st.kind) {
  case ir::StmtKind::Assign:
    if (st.target.kind != ir::ExprKind::Variable)
      return fail(st.range, "an assignment to a computed variable",
                  "its number is known only at run time");
    f.kind = FlowKind::Assign;
    f.target = st.target;
    f.value = st.value;
    to.push_back(std::move(f));
    return true;
  case ir::StmtKind::IfThen:
    if (st.target.kind != ir::ExprKind::Variable)
      return fail(st.range, "an assignment to a computed variable",
                  "its number is known only at run time");
    s.guard = conditionExpr(*st.cond);
    f.kind = FlowKind::Assign;
    f.target = st.target;
    f.value = st.value;
    s.after.push_back(std::move(f));
    return true;
  case ir::StmtKind::Guard:
    if (st.precision)
      return fail(st.range, fmt::format("IF{}", *st.precision),
                  "a comparison rounded to a precision has no form on the other controls");
    if (!s.after.empty() || s.guard)
      return fail(st.range, "IF after the block's statements",
                  "the statements before it act whatever the condition says");
    if (s.hasNcPart()) { // the words so far run alone when it fails, with the rest when it holds
      s.otherwise = std::make_shared<Step>();
      s.otherwise->range = s.range;
      s.otherwise->modes = s.modes;
      s.otherwise->words = s.words;
      s.otherwise->dwellSeconds = s.dwellSeconds;
      s.otherwise->machine = s.machine;
    }
    s.guard = st.value;
    return true;
  case ir::StmtKind::Goto:
  case ir::StmtKind::IfGoto:
    f.kind = FlowKind::Jump;
    f.label = labelDigits(st.value.number);
    if (st.cond) f.condition = conditionExpr(*st.cond);
    s.after.push_back(std::move(f));
    return true;
  case ir::StmtKind::Jump:
    f.kind = FlowKind::Jump;
    f.label = withoutLeadingZeros(st.label);
    s.after.push_back(std::move(f));
    return true;
  case ir::StmtKind::While:
    f.kind = FlowKind::WhileStart;
    f.condition = conditionExpr(*st.cond);
    f.loop = ++nextLoop_;
    loops_.push_back(f.loop);
    s.before.push_back(std::move(f));
    return true;
  case ir::StmtKind::End:
    if (loops_.empty()) return fail(st.range, "END", "it closes no WHILE of the program");
    f.kind = FlowKind::WhileEnd;
    f.loop = loops_.back();
    loops_.pop_back();
    s.after.push_back(std::move(f));
    return true;
  case ir::StmtKind::Call:
    if (st.value.kind != ir::ExprKind::Number)
      return fail(st.range, "a call repeated a computed number of times",
                  "the count is known only at run time");
    f.kind = FlowKind::Call;
    f.unit = st.callee;
    f.times = std::lround(st.value.number);
    s.after.push_back(std::move(f));
    return true;
  case ir::StmtKind::Do:
    return fail(st.range, "DO without WHILE", "an endless loop leaves only by a jump or an end");
  default:
    return fail(st.range, "the statement", "the other controls have no statement with its meaning");
  }
}

bool Lifter::remapped(const ir::Word& w, const Remap& r, const ir::Block& b, Step& s,
                      std::set<const ir::Word*>& consumed) {
  const std::string code = w.address + emit::formatNumber(w.number);
  const ir::Word* program = r.programWord ? b.find(r.programWord) : nullptr;
  const ir::Word* repeat = r.repeatWord ? b.find(r.repeatWord) : nullptr;
  Flow f;
  f.range = w.range;
  switch (r.action) {
  case FlowAction::CallSubprogram: {
    if (r.frame != LocalFrame::Shared)
      return fail(w.range, code, "a call whose local variables differ from its caller's");
    f.kind = FlowKind::Call;
    if (r.program == ProgramSource::Word) {
      if (!program || !program->isLiteral())
        return fail(w.range, code, "the program it calls is known only at run time");
      f.unit = programDigits(*program);
      consumed.insert(program);
    } else if (r.program == ProgramSource::CodeDigits) {
      const ProgramCall pc = programFromDigits(r, programDigits(w));
      f.unit = pc.unit;
      if (pc.times) f.times = *pc.times;
    } else {
      return fail(w.range, code, "a call of a fixed program of the control");
    }
    if (repeat) {
      if (!repeat->isLiteral() || repeat->number < 1)
        return fail(repeat->range, "the repeat count of " + code,
                    "a positive number must be given");
      f.times = std::lround(repeat->number);
      consumed.insert(repeat);
    }
    s.after.push_back(std::move(f));
    return true;
  }
  case FlowAction::Return:
    if (program)
      return fail(program->range, code + " with " + program->address,
                  "a return to another block than the call's next");
    if (main_ && !flow_.returnInMainEnds)
      return fail(w.range, code + " in the main program",
                  "it restarts the program or is an error, as each control has it");
    f.kind = main_ ? FlowKind::EndProgram : FlowKind::Return; // FMS-3000: it ends the program
    s.after.push_back(std::move(f));
    return true;
  case FlowAction::EndProgram:
    f.kind = FlowKind::EndProgram;
    s.after.push_back(std::move(f));
    return true;
  case FlowAction::RepeatStart:
    if (!repeat || !repeat->isLiteral() || repeat->number < 1)
      return fail(w.range, code, "a repeat count known only at run time");
    f.kind = FlowKind::RepeatStart;
    f.times = std::lround(repeat->number);
    consumed.insert(repeat);
    s.after.push_back(std::move(f));
    return true;
  case FlowAction::RepeatEnd:
    f.kind = FlowKind::RepeatEnd;
    s.after.push_back(std::move(f));
    return true;
  case FlowAction::ModalCall:
    if (!cycleProgramCall(r)) break;
    s.cycle = true; // the holes it drills are written from its runs
    cycleMode_ = true;
    return true;
  case FlowAction::ModalCancel:
    s.modes.push_back({GAction::CycleCancel, 0, "cycle cancel", w.range});
    cycleMode_ = false;
    return true;
  case FlowAction::Builtin:
    return fail(w.range, code, "a built-in code called under another address");
  default:
    break;
  }
  return fail(w.range, code,
              "a macro, cycle or modal call: its arguments bind differently on each control");
}

bool Lifter::gcode(const ir::Word& w, const ir::Block& b, Step& s,
                   std::set<const ir::Word*>& consumed) {
  if (!w.isLiteral())
    return fail(w.range, "G with a variable", "its meaning is known only at run time");
  const GCodeSpec* g = p_.gcode(w.number);
  const std::string code = "G" + emit::formatNumber(w.number);
  if (!g) return fail(w.range, code, "no code of the dialect");
  if (drillingAction(g->action)) return true; // the cycle's: in the holes (Step::cycle)
  if (!neutralAction(g->action))
    return fail(w.range, code,
                fmt::format("{}: structured translation keeps it not yet", g->meaning));
  if (s.cycle && (g->action == GAction::Rapid || g->action == GAction::Linear)) return true;
  if (g->action == GAction::Absolute || g->action == GAction::Incremental)
    absolute_ = g->action == GAction::Absolute;
  if (g->action == GAction::ReferenceReturn && !referenceReturn(w, *g, b)) return false;
  s.modes.push_back({g->action, g->arg, g->meaning, w.range});
  if (g->action != GAction::Dwell) return true;
  const DwellRule& d = p_.machine.dwell;
  const ir::Word* time = b.find(d.word);
  if (!time && d.alternateWord) time = b.find(d.alternateWord);
  if (!time) return fail(w.range, code, "a dwell without its time");
  Value v;
  if (!value(*time, v)) return false;
  if (d.secondsPerUnit != 1) {
    if (v.literal) {
      v.number *= d.secondsPerUnit;
    } else {
      ir::Expr times;
      times.kind = ir::ExprKind::Binary;
      times.op = ir::Op::Mul;
      ir::Expr inner;
      inner.kind = ir::ExprKind::Bracket;
      inner.args = {v.expr};
      times.args = {inner, ir::Expr::literal(d.secondsPerUnit)};
      v.expr = times;
    }
  }
  s.dwellSeconds = v;
  consumed.insert(time);
  return true;
}

// A return to machine zero on the axes it names: straight there where the control goes so
// (FMS-3000, WL4), or NCT's through an intermediate point that is the tool's own position (G91
// with every axis 0), the only one every control can take.
bool Lifter::referenceReturn(const ir::Word& w, const GCodeSpec& g, const ir::Block& b) {
  const std::string code = "G" + emit::formatNumber(w.number);
  if (g.arg != 0)
    return fail(w.range, code, "a reference point of the machine's own setup, not its zero");
  if (p_.machine.directReferencePointKey) return true;
  bool zeros = absolute_ && !*absolute_;
  for (const ir::Word& x : b.words)
    if (x.address.size() == 1 && std::string_view("XYZABC").find(x.address[0]) != std::string::npos)
      zeros = zeros && x.isLiteral() && x.number == 0;
  if (!zeros)
    return fail(w.range, code,
                "its intermediate point is not the tool's position (G91 with every axis 0)");
  return true;
}

bool Lifter::mcode(const ir::Word& w, Step& s) {
  if (!w.isLiteral())
    return fail(w.range, "M with a variable", "its meaning is known only at run time");
  const int code = static_cast<int>(std::lround(w.number));
  const MCodeSpec* m = p_.machine.mcode(code);
  if (!m || m->action == MAction::Subprogram || m->action == MAction::GearRange ||
      m->action == MAction::SpindleOrient)
    return fail(w.range, "M" + emit::formatNumber(w.number), "a function of this machine only");
  s.machine.push_back({m->action, code, m->timing, w.range});
  return true;
}

bool Lifter::operand(const ir::Word& w, Step& s) {
  if (w.address.size() != 1)
    return fail(w.range, w.address + " word", "no word of the other controls has its meaning");
  const char letter = w.address[0];
  const bool arc = motion_ && isArc(*motion_);
  const std::string_view axes = "XYZABC";
  if (axes.find(letter) != std::string_view::npos) {
    if (letter == 'X' && settings_(Setting::DiameterX) != 0)
      return fail(w.range, "X on diameter", "the other controls read X as a radius");
  } else if (letter == 'U' || letter == 'V' || letter == 'W') {
    const Setting parallel = letter == 'U'   ? Setting::ParallelAxisU
                             : letter == 'V' ? Setting::ParallelAxisV
                                             : Setting::ParallelAxisW;
    if (!p_.uvwIncremental || settings_(parallel) != 0)
      return fail(w.range, w.address + " word", "an axis of this machine only");
  } else if (letter == 'I' || letter == 'J' || letter == 'K') {
    if (!arc)
      return fail(w.range, w.address + " word",
                  "outside an arc block it means something else on each control");
    if (settings_(Setting::ArcCentreAbsolute) != 0)
      return fail(w.range, "arc centre " + w.address,
                  "absolute arc centres (a machine setting) read from the start point only at "
                  "run time");
  } else if (letter == 'R') {
    if (!arc)
      return fail(w.range, "R word",
                  "outside an arc block it means something else on each "
                  "control");
  } else if (letter == 'L') {
    if (!arc || p_.machine.arcL != ArcLMeaning::Turns)
      return fail(w.range, "L word", "it has no meaning outside a call, a repeat or an arc");
  } else if (std::string_view("FSTDH").find(letter) == std::string_view::npos) {
    return fail(w.range, w.address + " word", "no word of the other controls has its meaning");
  }
  Operand o;
  o.letter = letter;
  if (!value(w, o.value)) return false;
  s.words.push_back(std::move(o));
  return true;
}

} // namespace

bool liftUnit(const std::vector<ir::Block>& blocks, const Profile& source,
              const SettingLookup& settings, UnitSteps& out, Unkept& why) {
  if (!source.controlFlow) {
    why = {{}, "the program", "its dialect has no control-flow table"};
    return false;
  }
  Lifter l(source, settings, why);
  return l.unit(blocks, out);
}

} // namespace gcx::xlate
