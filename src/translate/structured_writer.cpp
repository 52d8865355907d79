#include "translate/structured_writer.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <set>
#include <span>
#include <sstream>

#include "dialect/control_flow.h"
#include "emit/number.h"
#include "translate/counted_loops.h"
#include "translate/expression_lowering.h"
#include "translate/variable_plan.h"

namespace gcx::xlate {

namespace {

bool isAxis(char c) {
  return std::string_view("XYZABCUVW").find(c) != std::string_view::npos;
}

// The structures kept, by kind, with their source blocks.
class KeptLog {
public:
  void add(const std::string& what, const SourceRange& at) {
    auto& v = byKind_[what];
    if (v.empty()) order_.push_back(what);
    if (v.empty() || v.back().line != at.begin.line || v.back().file != at.begin.file)
      v.push_back(at.begin);
  }
  std::vector<KeptStructure> list() const {
    std::vector<KeptStructure> out;
    for (const std::string& k : order_)
      out.push_back({k, byKind_.at(k)});
    return out;
  }

private:
  std::vector<std::string> order_;
  std::map<std::string, std::vector<SourceLoc>> byKind_;
};

bool sameHole(const Hole& a, const Hole& b) {
  const auto same = [](double x, double y) { return std::fabs(x - y) < 1e-9; };
  return a.kind == b.kind && same(a.x, b.x) && same(a.y, b.y) && same(a.start, b.start) &&
         same(a.r, b.r) && same(a.bottom, b.bottom) && same(a.exit, b.exit) &&
         same(a.feed, b.feed) && same(a.retractFeed, b.retractFeed) && same(a.dwell, b.dwell) &&
         same(a.peck, b.peck) && same(a.clearance, b.clearance) && same(a.backOff, b.backOff);
}

class UnitWriter {
public:
  UnitWriter(const StructuredSpelling& t, const StructuredInput& in, const VariablePlan& plan,
             const std::map<std::string, std::string>& unitNames, std::vector<int>& counters,
             int& loopSerial, KeptLog& kept, Unkept& why)
      : t_(t), p_(*t.profile), source_(*in.source), in_(in), plan_(plan), unitNames_(unitNames),
        counters_(counters), kept_(kept), why_(why), holes_(t.holes ? t.holes() : nullptr),
        loopSerial_(loopSerial) {}

  bool unit(const UnitSteps& u, std::vector<ir::Block>& out);

private:
  bool fail(const SourceRange& where, std::string what, std::string why) {
    why_ = {where, std::move(what), std::move(why)};
    return false;
  }
  // building blocks
  ir::Block& open(const SourceRange& at);
  // the step's last block for more words; a new one after a statement where words and
  // statements do not share a block (NCT)
  ir::Block& last(const SourceRange& at) {
    if (out_->empty() || !stepHasBlock_ ||
        (!t_.statementsBesideWords && !out_->back().stmts.empty()))
      return open(at);
    return out_->back();
  }
  void word(ir::Block& b, const std::string& address, double v, const std::string& text = {});
  void code(ir::Block& b, char letter, int code10);
  void stmt(ir::Block& b, ir::Stmt s);
  bool gcode(ir::Block& b, GAction a, int arg, const SourceRange& at, const char* meaning);
  bool mcode(ir::Block& b, const Machine& m);
  bool value(ir::Block& b, char letter, const Value& v, const SourceRange& at);
  std::optional<ir::Expr> expr(const ir::Expr& e, const SourceRange& at);
  std::optional<ir::Expr> condition(const ir::Expr& c, const SourceRange& at);
  // labels
  std::string labelFor(const std::string& source);
  std::string freshLabel();
  void placeLabel(ir::Block& b, const std::string& label);
  ir::Block& labelBlock(const std::string& label, const SourceRange& at);
  // parts of a step
  bool step(const Step& s);
  bool body(const Step& s);
  bool ncPart(const Step& s);
  bool filletAsArc(const Step& s, Step& arc);
  bool flow(const Flow& f, const Step& s);
  bool guarded(const Step& s);
  bool assign(const Flow& f, bool ownBlock);
  bool jump(const std::string& label, const std::optional<ir::Expr>& condition,
            const SourceRange& at, bool ownBlock);
  bool loopHead(const std::optional<ir::Expr>& condition, const SourceRange& at, int counter,
                long times);
  bool loopTail(const SourceRange& at);

  class HoleOut;
  bool drill(const Step& s);
  bool holesOf(const Step& s, std::vector<Hole>& holes, std::set<char>& moving);
  void endCycle(const SourceRange& at);

  const StructuredSpelling& t_;
  const Profile& p_;
  const Profile& source_;
  const StructuredInput& in_;
  const VariablePlan& plan_;
  const std::map<std::string, std::string>& unitNames_;
  std::vector<int>& counters_;
  KeptLog& kept_;
  Unkept& why_;
  std::unique_ptr<HoleLowering> holes_;
  bool inCycle_ = false;         // the target's cycle mode is on after the last hole
  std::optional<bool> absolute_; // G90 as the text runs, when known

  std::vector<ir::Block>* out_ = nullptr;
  bool stepHasBlock_ = false; // the current step has opened a block
  std::string pendingLabel_, pendingSequence_;
  std::map<std::string, std::string> labels_; // source label -> target label
  std::set<long> labelNumbers_;               // labels and jump targets of the unit, and fresh ones
  std::set<long> sequenceNumbers_;            // block numbers the source writes that are no labels
  std::size_t firstBlock_ = 0;                // the current step's first block
  long nextFresh_ = 0;
  int labelCount_ = 0;
  struct Loop {
    int counter = 0;       // a repeat's counter variable (0: a WHILE)
    ir::Expr condition;    // WHILE: its condition
    std::string top, exit; // WL4 labels
    int id = 0;            // NCT DO number
  };
  std::vector<Loop> loops_;
  int& loopSerial_;          // loops named in the file so far (StructuredSpelling::uniqueLoopIds)
  bool lastContent_ = false; // the step is the unit's last that does something
};

ir::Block& UnitWriter::open(const SourceRange& at) {
  ir::Block b;
  b.range = at;
  if (!pendingLabel_.empty()) {
    placeLabel(b, pendingLabel_);
    pendingLabel_.clear();
  } else if (!pendingSequence_.empty()) {
    b.sequence = std::stoll(pendingSequence_);
    b.sequenceText = pendingSequence_;
  }
  pendingSequence_.clear();
  out_->push_back(std::move(b));
  stepHasBlock_ = true;
  return out_->back();
}

void UnitWriter::word(ir::Block& b, const std::string& address, double v, const std::string& text) {
  ir::Word w;
  w.address = address;
  w.number = v;
  w.text = text;
  w.order = static_cast<std::uint32_t>(b.words.size() + b.stmts.size());
  b.words.push_back(std::move(w));
}

void UnitWriter::code(ir::Block& b, char letter, int code10) {
  std::string text = fmt::format("{:0{}}", code10 / 10, t_.codeDigits);
  if (code10 % 10) text += fmt::format(".{}", code10 % 10);
  word(b, std::string(1, letter), code10 / 10.0, text);
}

void UnitWriter::stmt(ir::Block& b, ir::Stmt s) {
  s.order = static_cast<std::uint32_t>(b.words.size() + b.stmts.size());
  b.stmts.push_back(std::move(s));
}

bool UnitWriter::gcode(ir::Block& b, GAction a, int arg, const SourceRange& at,
                       const char* meaning) {
  for (const GCodeSpec& g : p_.gcodes)
    if (g.action == a && g.arg == arg) {
      code(b, 'G', g.code10);
      return true;
    }
  // a cycle cancel that the control's remap table holds (WL4 G80 ends the modal cycle call)
  if (a == GAction::CycleCancel)
    for (const Remap& r : p_.controlFlow->remaps.rows)
      if (r.action == FlowAction::ModalCancel && r.code && r.address == "G") {
        code(b, 'G', static_cast<int>(std::lround(*r.code * 10)));
        return true;
      }
  // millimetres on a control that has no other unit need no code
  const auto has = [&](GAction x) {
    return std::any_of(p_.gcodes.begin(), p_.gcodes.end(),
                       [x](const GCodeSpec& g) { return g.action == x; });
  };
  if (a == GAction::Metric && !has(GAction::Inch)) return true;
  return fail(at, meaning, fmt::format("{} has no G code with this meaning", t_.label));
}

bool UnitWriter::mcode(ir::Block& b, const Machine& m) {
  for (const MCodeSpec& spec : p_.machine.mcodes)
    if (spec.action == m.action && (m.action != MAction::Coolant || spec.code == m.code)) {
      code(b, 'M', spec.code * 10);
      return true;
    }
  return fail(m.range, fmt::format("M{}", m.code),
              fmt::format("{} has no M code with its meaning", t_.label));
}

std::optional<ir::Expr> UnitWriter::expr(const ir::Expr& e, const SourceRange& at) {
  std::string why;
  std::optional<ir::Expr> l = lowerExpression(e, plan_, t_, why);
  if (!l) fail(at, "an expression", why);
  return l;
}

std::optional<ir::Expr> UnitWriter::condition(const ir::Expr& c, const SourceRange& at) {
  std::string why;
  std::optional<ir::Expr> l = lowerCondition(c, plan_, t_, why);
  if (!l) fail(at, "a condition", why);
  return l;
}

bool UnitWriter::value(ir::Block& b, char letter, const Value& v, const SourceRange& at) {
  const std::string address(1, letter);
  const AddressSpec* spec = p_.address(address);
  if (!spec)
    return fail(at, address + " word", fmt::format("{} has no address {}", t_.label, letter));
  std::optional<double> number = v.literal ? std::optional<double>(v.number) : std::nullopt;
  if (!number && !t_.writes) {
    std::string why;
    const std::optional<ir::Expr> folded = lowerExpression(v.expr, plan_, t_, why);
    if (!folded) return fail(at, address + " word", why);
    number = folded->number;
  }
  if (number) {
    const double scale = std::pow(10.0, spec->decimal ? t_.decimals : 0);
    double r = std::round(*number * scale) / scale;
    if (std::fabs(r - *number) > 1e-9)
      return fail(at, address + " word",
                  fmt::format("{} writes {} to {} decimals: {} is not such a value", t_.label,
                              address, spec->decimal ? t_.decimals : 0,
                              emit::formatNumber(*number)));
    if (r == 0) r = 0; // no "-0"
    if (r < spec->min || r > spec->max)
      return fail(at, address + " word",
                  fmt::format("{}{} is outside {}'s range of {}", address, emit::formatNumber(r),
                              address, t_.label));
    word(b, address, r);
    return true;
  }
  const std::optional<ir::Expr> e = expr(v.expr, at);
  if (!e) return false;
  ir::Word w;
  w.address = address;
  w.kind = ir::ValueKind::Expression;
  w.expr = *e;
  w.order = static_cast<std::uint32_t>(b.words.size() + b.stmts.size());
  b.words.push_back(std::move(w));
  kept_.add("variables", at);
  return true;
}

std::string UnitWriter::labelFor(const std::string& source) {
  auto it = labels_.find(source);
  if (it != labels_.end()) return it->second;
  return labels_[source] = source;
}

std::string UnitWriter::freshLabel() {
  while (labelNumbers_.count(nextFresh_) || sequenceNumbers_.count(nextFresh_))
    ++nextFresh_;
  labelNumbers_.insert(nextFresh_);
  return std::to_string(nextFresh_++);
}

void UnitWriter::placeLabel(ir::Block& b, const std::string& label) {
  b.sequence = std::stoll(label);
  b.sequenceText = t_.guardJumps ? "0" + label : label; // WL4: a label has a leading zero
  ++labelCount_;
}

ir::Block& UnitWriter::labelBlock(const std::string& label, const SourceRange& at) {
  ir::Block b;
  b.range = at;
  placeLabel(b, label);
  out_->push_back(std::move(b));
  stepHasBlock_ = true;
  return out_->back();
}

// The blocks a hole lowering writes, as blocks of the step being written.
class UnitWriter::HoleOut : public BlockOut {
public:
  HoleOut(UnitWriter& w, const SourceRange& at) : w_(w), at_(at) {}
  const Profile& profile() const override { return w_.p_; }
  void writeCode(char letter, int code10) override { w_.code(block(), letter, code10); }
  void writeValue(const char* address, double value) override {
    const auto at = overrides_.find(address);
    if (at == overrides_.end()) {
      w_.word(block(), address, rounded(value));
    } else if (!w_.value(block(), address[0], at->second, at->second.range)) {
      failed_ = true;
    }
  }
  /// The words written for `address` instead of the hole's value (a position each run moves).
  void position(const std::string& address, const Value& v) { overrides_[address] = v; }
  bool failed() const { return failed_; }
  void writeExact(const char* address, double value) override { w_.word(block(), address, value); }
  void writeAssign(int variable, double value) override {
    ir::Stmt st;
    st.kind = ir::StmtKind::Assign;
    st.target = ir::Expr::variable(variable);
    st.value = ir::Expr::literal(rounded(value));
    w_.stmt(block(), std::move(st));
  }
  double rounded(double value) const override {
    const double scale = std::pow(10.0, w_.t_.decimals);
    const double r = std::round(value * scale) / scale;
    return r == 0 ? 0 : r;
  }
  void endBlock() override { index_.reset(); }

private:
  ir::Block& block() {
    if (!index_) {
      w_.open(at_);
      index_ = w_.out_->size() - 1;
    }
    return (*w_.out_)[*index_];
  }
  UnitWriter& w_;
  SourceRange at_;
  std::optional<std::size_t> index_;
  std::map<std::string, Value> overrides_;
  bool failed_ = false;
};

void UnitWriter::endCycle(const SourceRange& at) {
  if (!inCycle_) return;
  HoleOut out(*this, at);
  holes_->cancel(out);
  inCycle_ = false;
}

// The holes every run of the step drilled: the same holes each time, and nothing else; or one
// hole a run that moves only in X and Y, which `moving` names (the step's words give them).
bool UnitWriter::holesOf(const Step& s, std::vector<Hole>& holes, std::set<char>& moving) {
  const BlockRuns* runs = in_.runs ? in_.runs(s.range.begin) : nullptr;
  if (!runs || runs->empty()) {
    if (!s.cycleMoves) return true; // a cycle's mode alone: nothing drilled here
    return fail(s.range, "a drilling cycle",
                "the proving run does not reach it, so the holes it drills are not known");
  }
  const auto same = [](double a, double b) { return std::fabs(a - b) < 1e-9; };
  for (std::size_t r = 0; r < runs->size(); ++r) {
    const std::vector<motion::Event>& ev = (*runs)[r];
    std::vector<Hole> found;
    std::size_t pos = 0;
    while (pos < ev.size()) {
      const HoleMatch m =
          matchHole(std::span(ev).subspan(pos), true, pos > 0 ? &ev[pos - 1] : nullptr);
      if (m.status != HoleMatch::Found)
        return fail(s.range, "a drilling cycle",
                    "it drills no single hole that the target's cycles take");
      found.push_back(m.hole);
      pos += m.length;
    }
    if (r == 0) {
      holes = std::move(found);
      continue;
    }
    if (found.size() != holes.size())
      return fail(s.range, "a drilling cycle", "it drills another number of holes each run");
    for (std::size_t i = 0; i < found.size(); ++i) {
      Hole moved = found[i];
      if (!same(moved.x, holes[i].x)) moving.insert('X');
      if (!same(moved.y, holes[i].y)) moving.insert('Y');
      moved.x = holes[i].x;
      moved.y = holes[i].y;
      // where the tool comes from: the cycle block starts there in the target too
      moved.start = holes[i].start;
      if (!sameHole(moved, holes[i]))
        return fail(s.range, "a drilling cycle",
                    "its levels, feed or dwell differ between its runs");
    }
  }
  if (moving.empty()) return true;
  const bool ownWords = std::all_of(moving.begin(), moving.end(), [&](char c) {
    return std::any_of(s.cyclePositions.begin(), s.cyclePositions.end(),
                       [c](const Operand& o) { return o.letter == c; });
  });
  if (holes.size() != 1 || !ownWords || !absolute_ || !*absolute_)
    return fail(s.range, "a drilling cycle",
                "it drills elsewhere each time it runs, not at absolute positions of its own "
                "words");
  return true;
}

// A step of a drilling cycle: its other modes and M codes, then its holes as the target's cycle.
bool UnitWriter::drill(const Step& s) {
  if (!holes_)
    return fail(s.range, "a drilling cycle", fmt::format("{} keeps no cycles", t_.label));
  for (const Mode& m : s.modes)
    if (m.action == GAction::Absolute || m.action == GAction::Incremental)
      absolute_ = m.action == GAction::Absolute;
  std::vector<Hole> holes;
  std::set<char> moving;
  if (!holesOf(s, holes, moving)) return false;
  Step rest = s;
  rest.cycle = false;
  if (rest.hasNcPart() && !ncPart(rest)) return false;
  if (holes.empty()) return true;
  if (!absolute_)
    return fail(s.range, "a drilling cycle",
                "the distance mode it runs in is not known where the program is written");
  if (!*absolute_) { // the holes are written at absolute positions
    endCycle(s.range);
    if (!gcode(open(s.range), GAction::Absolute, 0, s.range, "absolute positions")) return false;
  }
  for (const Hole& h : holes) {
    HoleOut out(*this, s.range);
    for (const Operand& o : s.cyclePositions)
      if (moving.count(o.letter)) out.position(std::string(1, o.letter), o.value);
    if (const std::optional<std::string> why = holes_->refuse(h, out))
      return fail(s.range, "a drilling cycle", *why);
    if (!moving.empty()) endCycle(s.range); // each run writes its whole cycle block
    holes_->write(h, out);
    if (out.failed()) return false;
    inCycle_ = true;
    kept_.add(std::string(holeKindName(h.kind)), s.range);
  }
  if (!*absolute_) {
    endCycle(s.range);
    if (!gcode(open(s.range), GAction::Incremental, 0, s.range, "incremental positions"))
      return false;
  }
  return true;
}

bool UnitWriter::unit(const UnitSteps& u, std::vector<ir::Block>& out) {
  out_ = &out;
  if (u.main) absolute_ = true; // at power-on

  // the unit's block numbers: labels keep their numbers, a kept N must not be taken for one
  for (const Step& s : u.steps) {
    if (!s.label.empty()) labelNumbers_.insert(std::stol(s.label));
    if (!s.sequence.empty()) sequenceNumbers_.insert(std::stol(s.sequence));
    for (const Flow& f : s.after)
      if (f.kind == FlowKind::Jump) labelNumbers_.insert(std::stol(f.label));
  }
  nextFresh_ = 9000;
  std::size_t lastContent = 0;
  for (std::size_t i = 0; i < u.steps.size(); ++i)
    if (u.steps[i].hasNcPart() || !u.steps[i].before.empty() || !u.steps[i].after.empty())
      lastContent = i;
  for (std::size_t i = 0; i < u.steps.size(); ++i) {
    lastContent_ = i == lastContent;
    if (!step(u.steps[i])) return false;
  }
  if (!loops_.empty()) return fail(u.steps.back().range, "a loop", "it is not closed");
  endCycle(u.steps.empty() ? SourceRange{} : u.steps.back().range);
  if (t_.maxLabels && labelCount_ > t_.maxLabels)
    return fail(u.steps.empty() ? SourceRange{} : u.steps.front().range, "the labels of a program",
                fmt::format("{} allows {} labels in a program, this one needs {}", t_.label,
                            t_.maxLabels, labelCount_));
  return true;
}

bool UnitWriter::step(const Step& s) {
  stepHasBlock_ = false;
  firstBlock_ = out_->size();
  pendingLabel_ = s.label.empty() ? std::string() : labelFor(s.label);
  pendingSequence_.clear();
  if (!s.sequence.empty() && pendingLabel_.empty()) {
    const long n = std::stol(s.sequence);
    if (n >= p_.minSequenceNumber && n <= p_.maxSequenceNumber && !labelNumbers_.count(n) &&
        (!t_.guardJumps || s.sequence[0] != '0'))
      pendingSequence_ = std::to_string(n);
  }
  if (!s.label.empty() && !t_.gotoJumps && !t_.guardJumps)
    return fail(s.range, "a jump target", fmt::format("{} has no jumps", t_.label));
  if (!t_.blockComment) { // comments on lines of their own, before the step
    for (const std::string& c : s.comments)
      out_->push_back(t_.commentLine(c));
    firstBlock_ = out_->size();
  }
  // the target's cycle mode ends before anything but the next hole of the same run
  const bool content = s.hasNcPart() || !s.before.empty() || !s.after.empty() || s.guard ||
                       !s.label.empty() || s.cycle;
  const bool continues = s.cycle && s.before.empty() && s.label.empty() && !s.guard;
  if (content && !continues && inCycle_) {
    endCycle(s.range);
    // a cycle cancel of the source is the one just written
    Step rest = s;
    if (std::erase_if(rest.modes, [](const Mode& m) { return m.action == GAction::CycleCancel; }))
      return body(rest);
  }
  return body(s);
}

bool UnitWriter::body(const Step& s) {
  for (const Flow& f : s.before)
    if (!flow(f, s)) return false;
  if (s.cycle) {
    if (s.guard) return fail(s.range, "a drilling cycle", "a condition guards it");
    if (!drill(s)) return false;
    for (const Flow& f : s.after)
      if (!flow(f, s)) return false;
  } else if (s.guard) {
    if (!guarded(s)) return false;
  } else {
    if (s.hasNcPart() && !ncPart(s)) return false;
    for (const Flow& f : s.after)
      if (!flow(f, s)) return false;
  }
  if (!pendingLabel_.empty() || !pendingSequence_.empty() ||
      (t_.blockComment && !s.comments.empty() && out_->size() == firstBlock_))
    open(s.range);       // a label, a number or a comment of a step without blocks of its own
  if (t_.blockComment) { // on the step's first block, after its words
    ir::Block& first = (*out_)[firstBlock_];
    for (const std::string& c : s.comments) {
      ir::Comment cm = t_.blockComment(c);
      cm.order = static_cast<std::uint32_t>(first.words.size() + first.stmts.size() +
                                            first.comments.size());
      first.comments.push_back(std::move(cm));
    }
  }
  return true;
}

// A fillet on a target without one: the arc it is, its centre offset from where each run
// started (the same in every run: the fillet's legs are its own words).
bool UnitWriter::filletAsArc(const Step& s, Step& arc) {
  const BlockRuns* runs = in_.runs ? in_.runs(s.range.begin) : nullptr;
  if (!runs || runs->empty())
    return fail(s.range, "a fillet",
                "the proving run does not reach it, so the centre of its arc is not known");
  std::optional<motion::Vec3> offset;
  motion::Plane plane = motion::Plane::XY;
  for (const std::vector<motion::Event>& run : *runs) {
    std::vector<const motion::Event*> arcs;
    for (const motion::Event& e : run)
      if (e.kind == motion::Kind::Arc) arcs.push_back(&e);
    if (arcs.size() != 1) return fail(s.range, "a fillet", "it runs as no single arc");
    const motion::Vec3 o = arcs[0]->center - arcs[0]->start;
    if (offset && (o - *offset).norm() > 1e-9)
      return fail(s.range, "a fillet", "its centre lies elsewhere each time it runs");
    offset = o;
    plane = arcs[0]->plane;
  }
  arc = s;
  arc.fillet.reset();
  std::erase_if(arc.modes, [](const Mode& m) {
    return m.action == GAction::FilletCW || m.action == GAction::FilletCCW;
  });
  arc.modes.push_back({*s.fillet == GAction::FilletCW ? GAction::ArcCW : GAction::ArcCCW, 0,
                       "circular interpolation", s.range});
  const char* letters = plane == motion::Plane::XY   ? "IJ"
                        : plane == motion::Plane::ZX ? "IK"
                                                     : "JK";
  const auto index = [](char c) { return c == 'I' ? 0 : c == 'J' ? 1 : 2; };
  for (const char* c = letters; *c; ++c) {
    Operand o;
    o.letter = *c;
    o.value.number = (*offset)[index(*c)];
    o.value.range = s.range;
    arc.words.push_back(o);
  }
  kept_.add("fillets as arcs", s.range);
  return true;
}

// The NC part: modes, words, dwell, M codes; M S T that the two controls act on at different
// sides of the motion go into a block before or after it.
bool UnitWriter::ncPart(const Step& s) {
  if (s.fillet && !std::any_of(p_.gcodes.begin(), p_.gcodes.end(),
                               [&](const GCodeSpec& g) { return g.action == *s.fillet; })) {
    Step arc;
    return filletAsArc(s, arc) && ncPart(arc);
  }
  bool motion = false;
  for (const Operand& o : s.words)
    motion = motion || isAxis(o.letter);
  const MachineRules& from = source_.machine;
  const MachineRules& to = p_.machine;
  ir::Block pre, post;
  ir::Block& b = open(s.range);
  // a return to machine zero on a control that goes through an intermediate point: G91 with
  // every axis 0 (the point is the tool's position), G90 again after it
  bool backToAbsolute = false;
  for (const Mode& m : s.modes)
    if (m.action == GAction::ReferenceReturn && !to.directReferencePointKey) {
      if (!absolute_)
        return fail(m.range, m.meaning, "the distance mode it runs in is not known here");
      if (*absolute_ && !gcode(b, GAction::Incremental, 0, m.range, "incremental positions"))
        return false;
      backToAbsolute = *absolute_;
    }
  // modes first, dwell code where its word goes
  bool dwellInBlock = false;
  for (const Mode& m : s.modes) {
    if (m.action == GAction::Absolute || m.action == GAction::Incremental)
      absolute_ = m.action == GAction::Absolute;
    if (m.action == GAction::Dwell) {
      if (motion && !to.dwellAfterMotion) continue; // in the block after the motion
      dwellInBlock = true;
    }
    if (!gcode(b, m.action, m.arg, m.range, m.meaning)) return false;
  }
  for (const Operand& o : s.words) {
    const bool speed = o.letter == 'S', tool = o.letter == 'T';
    const MTiming fromTiming = speed ? from.speedTiming : from.toolTiming;
    const MTiming toTiming = speed ? to.speedTiming : to.toolTiming;
    ir::Block& into = (speed || tool) && motion && fromTiming != toTiming
                          ? (fromTiming == MTiming::BeforeMotion ? pre : post)
                          : b;
    if (!value(into, o.letter, o.value, o.value.range)) return false;
  }
  if (s.dwellSeconds) {
    ir::Block& into = dwellInBlock ? b : post;
    if (!dwellInBlock && !gcode(into, GAction::Dwell, 0, s.range, "a dwell")) return false;
    Value v = *s.dwellSeconds;
    if (v.literal) {
      v.number /= to.dwell.secondsPerUnit;
    } else if (to.dwell.secondsPerUnit != 1) {
      ir::Expr d;
      d.kind = ir::ExprKind::Binary;
      d.op = ir::Op::Div;
      d.args = {bracketed(v.expr), ir::Expr::literal(to.dwell.secondsPerUnit)};
      v.expr = d;
    }
    if (!value(into, to.dwell.word, v, v.range)) return false;
  }
  for (const Machine& m : s.machine) {
    int code10 = 0;
    ir::Block probe;
    if (!mcode(probe, m)) return false;
    code10 = static_cast<int>(std::lround(probe.words.back().number * 10));
    const MCodeSpec* spec = to.mcode(code10 / 10);
    const bool apart = motion && spec && spec->timing != m.timing;
    ir::Block& into = apart ? (m.timing == MTiming::BeforeMotion ? pre : post) : b;
    code(into, 'M', code10);
  }
  (void)from;
  if (backToAbsolute && !gcode(post, GAction::Absolute, 0, s.range, "absolute positions"))
    return false;
  if (!pre.words.empty()) {
    // before the motion block: it keeps the step's label
    pre.range = b.range;
    pre.sequence = b.sequence;
    pre.sequenceText = b.sequenceText;
    b.sequence.reset();
    b.sequenceText.clear();
    out_->insert(out_->end() - 1, std::move(pre));
  }
  if (!post.words.empty()) {
    post.range = s.range;
    out_->push_back(std::move(post));
  }
  return true;
}

bool UnitWriter::guarded(const Step& s) {
  const bool jumpOnly = !s.hasNcPart() && s.after.size() == 1 &&
                        s.after[0].kind == FlowKind::Jump && !s.after[0].condition;
  if (jumpOnly) {
    kept_.add("jumps", s.after[0].range);
    return jump(labelFor(s.after[0].label), s.guard, s.after[0].range, true);
  }
  if (!t_.gotoJumps && !t_.guardJumps)
    return fail(s.range, "a conditional block", fmt::format("{} has no conditions", t_.label));
  const bool oneAssign =
      !s.hasNcPart() && s.after.size() == 1 && s.after[0].kind == FlowKind::Assign;
  if (oneAssign && t_.gotoJumps) { // NCT IF [c] THEN #n = e
    const std::optional<ir::Expr> c = condition(*s.guard, s.range);
    const std::optional<ir::Expr> target = expr(s.after[0].target, s.range);
    const std::optional<ir::Expr> v = expr(s.after[0].value, s.range);
    if (!c || !target || !v) return false;
    ir::Stmt st;
    st.kind = ir::StmtKind::IfThen;
    st.cond = asCondition(*c);
    st.target = *target;
    st.value = *v;
    stmt(open(s.range), std::move(st));
    kept_.add("variables", s.range);
    return true;
  }
  if (s.otherwise) { // if ... else: the whole block when it holds, the words before IF when not
    if (!t_.gotoJumps)
      return fail(s.range, "IF in the middle of a block",
                  fmt::format("{} has no jumps to write its two branches with", t_.label));
    const std::string otherwise = freshLabel(), end = freshLabel();
    Step taken = s;
    taken.guard.reset();
    taken.otherwise.reset();
    if (!jump(otherwise, negated(*s.guard), s.range, true) || !ncPart(taken) ||
        !jump(end, std::nullopt, s.range, true))
      return false;
    pendingLabel_ = otherwise; // on the first block of the other branch
    if (!ncPart(*s.otherwise)) return false;
    labelBlock(end, s.range);
    kept_.add("conditions", s.range);
    return true;
  }
  // anything else: jump over the step when the condition fails
  const std::string skip = freshLabel();
  if (!jump(skip, negated(*s.guard), s.range, true)) return false;
  if (s.hasNcPart() && !ncPart(s)) return false;
  for (const Flow& f : s.after)
    if (!flow(f, s)) return false;
  labelBlock(skip, s.range);
  kept_.add("conditions", s.range);
  return true;
}

bool UnitWriter::assign(const Flow& f, bool ownBlock) {
  const std::optional<ir::Expr> target = expr(f.target, f.range);
  const std::optional<ir::Expr> v = expr(f.value, f.range);
  if (!target || !v) return false;
  ir::Stmt st;
  st.kind = ir::StmtKind::Assign;
  st.target = *target;
  st.value = *v;
  stmt(ownBlock || !t_.statementsBesideWords ? open(f.range) : last(f.range), std::move(st));
  kept_.add("variables", f.range);
  return true;
}

// A jump to `label`, when `condition` holds if given: NCT `IF [c] GOTO n`, WL4 `IF (c) Nn`.
bool UnitWriter::jump(const std::string& label, const std::optional<ir::Expr>& condition,
                      const SourceRange& at, bool ownBlock) {
  std::optional<ir::Expr> c;
  if (condition && !(c = this->condition(*condition, at))) return false;
  if (t_.gotoJumps) {
    ir::Stmt st;
    st.kind = c ? ir::StmtKind::IfGoto : ir::StmtKind::Goto;
    st.value = ir::Expr::literal(std::stod(label));
    if (c) st.cond = asCondition(*c);
    stmt(open(at), std::move(st));
    return true;
  }
  if (!t_.guardJumps) return fail(at, "a jump", fmt::format("{} has no jumps", t_.label));
  // WL4: a jump is a block number after the block's first item; alone it follows IF (1)
  ir::Block& b = ownBlock || c || !stepHasBlock_ ? open(at) : last(at);
  if (c || (b.words.empty() && b.stmts.empty() && !b.sequence)) {
    ir::Stmt g;
    g.kind = ir::StmtKind::Guard;
    g.value = c ? *c : ir::Expr::literal(1);
    stmt(b, std::move(g));
  }
  ir::Stmt j;
  j.kind = ir::StmtKind::Jump;
  j.label = label;
  j.value = ir::Expr::literal(std::stod(label));
  stmt(b, std::move(j));
  return true;
}

// The head of a loop: a WHILE (`condition`), or a repeat of `times` passes counted in `counter`.
bool UnitWriter::loopHead(const std::optional<ir::Expr>& condition, const SourceRange& at,
                          int counter, long times) {
  Loop l;
  l.counter = counter;
  if (counter) { // the counter counts down to 0: a do-while of `times` passes
    Flow set;
    set.kind = FlowKind::Assign;
    set.range = at;
    ir::Stmt st;
    st.kind = ir::StmtKind::Assign;
    st.target = ir::Expr::variable(counter);
    st.value = ir::Expr::literal(static_cast<double>(times));
    stmt(open(at), std::move(st));
  }
  if (t_.maxWhileNesting) {
    if (static_cast<int>(loops_.size()) >= t_.maxWhileNesting)
      return fail(
          at, "a loop",
          fmt::format("{} nests WHILE loops {} deep at most", t_.label, t_.maxWhileNesting));
    l.id = t_.uniqueLoopIds ? ++loopSerial_ : static_cast<int>(loops_.size()) + 1;
    ir::Stmt w;
    w.kind = ir::StmtKind::While;
    if (counter) {
      w.cond = ir::Condition{ir::Expr::variable(counter), ir::RelOp::Gt, ir::Expr::literal(0)};
    } else {
      const std::optional<ir::Expr> c = this->condition(*condition, at);
      if (!c) return false;
      w.cond = asCondition(*c);
    }
    w.loopId = l.id;
    stmt(open(at), std::move(w));
  } else if (t_.guardJumps) {
    l.top = freshLabel();
    if (!counter) { // tested first: out when it does not hold
      const std::optional<ir::Expr> c = this->condition(*condition, at);
      if (!c) return false;
      l.condition = *c;
      l.exit = freshLabel();
      if (!jump(l.exit, negated(*condition), at, true)) return false;
    }
    labelBlock(l.top, at);
  } else {
    return fail(at, "a loop", fmt::format("{} has no loops of this kind", t_.label));
  }
  loops_.push_back(std::move(l));
  return true;
}

bool UnitWriter::loopTail(const SourceRange& at) {
  if (loops_.empty()) return fail(at, "the end of a loop", "no loop is open");
  const Loop l = loops_.back();
  loops_.pop_back();
  if (l.counter) {
    ir::Stmt dec;
    dec.kind = ir::StmtKind::Assign;
    dec.target = ir::Expr::variable(l.counter);
    ir::Expr minus;
    minus.kind = ir::ExprKind::Binary;
    minus.op = ir::Op::Sub;
    minus.args = {ir::Expr::variable(l.counter), ir::Expr::literal(1)};
    dec.value = t_.guardJumps ? bracketed(minus) : minus;
    stmt(open(at), std::move(dec));
  }
  if (t_.maxWhileNesting) {
    ir::Stmt e;
    e.kind = ir::StmtKind::End;
    e.loopId = l.id;
    stmt(open(at), std::move(e));
    return true;
  }
  ir::Expr again;
  if (l.counter) {
    again.kind = ir::ExprKind::Binary;
    again.op = ir::Op::Gt;
    again.args = {ir::Expr::variable(l.counter), ir::Expr::literal(0)};
  } else {
    again = l.condition;
  }
  ir::Block& b = open(at);
  ir::Stmt g;
  g.kind = ir::StmtKind::Guard;
  g.value = again;
  stmt(b, std::move(g));
  ir::Stmt j;
  j.kind = ir::StmtKind::Jump;
  j.label = l.top;
  j.value = ir::Expr::literal(std::stod(l.top));
  stmt(b, std::move(j));
  if (!l.exit.empty()) labelBlock(l.exit, at);
  return true;
}

bool UnitWriter::flow(const Flow& f, const Step& s) {
  const ControlFlow& cf = *p_.controlFlow;
  const auto row = [&](FlowAction a) -> const Remap* {
    for (const Remap& r : cf.remaps.rows)
      if (r.action == a && r.code && !r.onlyProgram) return &r;
    return nullptr;
  };
  switch (f.kind) {
  case FlowKind::Assign:
    return assign(f, !s.hasNcPart());
  case FlowKind::Call: {
    const auto it = unitNames_.find(f.unit);
    if (it == unitNames_.end()) return fail(f.range, "the called program", "it was not loaded");
    // the target names its main program by its file or a heading, not as a call names a
    // subprogram (FMS-3000 `P019`): a program that calls itself keeps no structure (found by
    // the translate_nct fuzz target: the FMS-3000 call read 'O0001' as a number)
    if (f.unit == in_.units.front().name)
      return fail(f.range, "a call of the main program", "the target calls only subprograms");
    kept_.add("subprogram calls", f.range);
    if (!t_.maxCallTimes || f.times <= t_.maxCallTimes) {
      t_.call(t_.callsAlone ? open(f.range) : last(f.range), it->second, f.times);
      return true;
    }
    // more repeats than one call writes: the call alone in a repeat of the target
    if (const Remap* r = row(FlowAction::RepeatStart)) { // FMS-3000 G25 L<n> ... M25
      const Remap* end = row(FlowAction::RepeatEnd);
      ir::Block& head = open(f.range);
      code(head, r->address[0], static_cast<int>(std::lround(*r->code * 10)));
      word(head, std::string(1, r->repeatWord), static_cast<double>(f.times));
      t_.call(open(f.range), it->second, 1);
      code(open(f.range), end->address[0], static_cast<int>(std::lround(*end->code * 10)));
      return true;
    }
    if (counters_.empty()) return fail(f.range, "a call", "no counter is left for its repeats");
    const int counter = counters_.back();
    counters_.pop_back();
    if (!loopHead(std::nullopt, f.range, counter, f.times)) return false;
    t_.call(open(f.range), it->second, 1);
    return loopTail(f.range);
  }
  case FlowKind::Return:
  case FlowKind::EndProgram: {
    if (f.kind == FlowKind::Return) {
      const Remap* r = row(FlowAction::Return);
      if (!r && t_.returnAtEnd && lastContent_) return true; // the unit's closing line returns
      if (!r)
        return fail(f.range, "a return",
                    fmt::format("{} returns only at the end of a program", t_.label));
      code(last(f.range), r->address[0], static_cast<int>(std::lround(*r->code * 10)));
      return true;
    }
    return mcode(last(f.range), Machine{MAction::End, 2, MTiming::AfterMotion, f.range});
  }
  case FlowKind::RepeatStart:
    kept_.add("loops", f.range);
    if (const Remap* r = row(FlowAction::RepeatStart)) { // FMS-3000 G25 L<n>
      ir::Block& b = open(f.range);
      code(b, r->address[0], static_cast<int>(std::lround(*r->code * 10)));
      word(b, std::string(1, r->repeatWord), static_cast<double>(f.times));
      loops_.push_back(Loop{});
      return true;
    }
    if (counters_.empty()) return fail(f.range, "a repeat", "no counter is left for it");
    {
      const int counter = counters_.back();
      counters_.pop_back();
      return loopHead(std::nullopt, f.range, counter, f.times);
    }
  case FlowKind::RepeatEnd:
    if (const Remap* r = row(FlowAction::RepeatEnd)) { // FMS-3000 M25
      if (loops_.empty()) return fail(f.range, "the end of a repeat", "no repeat is open");
      loops_.pop_back();
      code(last(f.range), r->address[0], static_cast<int>(std::lround(*r->code * 10)));
      return true;
    }
    return loopTail(f.range);
  case FlowKind::WhileStart:
    kept_.add("loops", f.range);
    return loopHead(f.condition, f.range, 0, 0);
  case FlowKind::WhileEnd:
    return loopTail(f.range);
  case FlowKind::DoStart: {
    if (!t_.doWhileLoops)
      return fail(f.range, "a loop", fmt::format("{} has no such loop", t_.label));
    kept_.add("loops", f.range);
    Loop l;
    l.id = ++loopSerial_;
    ir::Stmt d;
    d.kind = ir::StmtKind::Do;
    d.loopId = l.id;
    stmt(open(f.range), std::move(d));
    loops_.push_back(std::move(l));
    return true;
  }
  case FlowKind::DoEnd: {
    if (loops_.empty()) return fail(f.range, "the end of a loop", "no loop is open");
    const std::optional<ir::Expr> c = condition(*f.condition, f.range);
    if (!c) return false;
    ir::Stmt e;
    e.kind = ir::StmtKind::End;
    e.loopId = loops_.back().id;
    e.cond = asCondition(*c);
    loops_.pop_back();
    stmt(open(f.range), std::move(e));
    return true;
  }
  case FlowKind::Jump:
    kept_.add("jumps", f.range);
    return jump(labelFor(f.label), f.condition, f.range, !s.hasNcPart() || t_.gotoJumps);
  }
  return false;
}

// The target's name of every unit, the main program's first.
bool nameUnits(const std::vector<UnitSteps>& units, const StructuredSpelling& t,
               const std::string& stem, std::map<std::string, std::string>& names, Unkept& why) {
  std::set<std::string> taken;
  for (std::size_t i = 1; i < units.size(); ++i) {
    const std::string n = t.subprogramName(units[i].name, taken);
    if (n.empty()) {
      why = {{}, "program " + units[i].name, fmt::format("{} has no name left for it", t.label)};
      return false;
    }
    taken.insert(n);
    names[units[i].name] = n;
  }
  names[units.front().name] = t.mainName(stem, taken);
  return true;
}

bool hasRow(const StructuredSpelling& t, FlowAction a) {
  const std::vector<Remap>& rows = t.profile->controlFlow->remaps.rows;
  return std::any_of(rows.begin(), rows.end(), [a](const Remap& r) { return r.action == a; });
}

// Counters the target needs: for each repeat it has no repeat of its own for, and each call
// repeated more often than one of its calls says.
int countersNeeded(const std::vector<UnitSteps>& units, const StructuredSpelling& t) {
  if (hasRow(t, FlowAction::RepeatStart)) return 0;
  int n = 0;
  for (const UnitSteps& u : units)
    for (const Step& s : u.steps)
      for (const Flow& f : s.after)
        n += f.kind == FlowKind::RepeatStart ||
             (f.kind == FlowKind::Call && t.maxCallTimes && f.times > t.maxCallTimes);
  return n;
}

// Assignments to variables no unit reads (a WL4 cycle's #2 #3, read by the cycle program whose
// holes are written as the target's cycle): a target without variables leaves them out.
void dropUnreadAssignments(std::vector<UnitSteps>& units) {
  std::set<int> read;
  for (const UnitSteps& u : units)
    for (const Step& s : u.steps)
      forEachVariable(s, [&](int n, const SourceRange&, bool written) {
        if (!written) read.insert(n);
      });
  const auto unread = [&](const Flow& f) {
    return f.kind == FlowKind::Assign && !read.count(static_cast<int>(f.target.number));
  };
  for (UnitSteps& u : units)
    for (Step& s : u.steps) {
      std::erase_if(s.before, unread);
      std::erase_if(s.after, unread);
    }
}

bool endsProgram(const UnitSteps& main) {
  for (const Step& s : main.steps) {
    for (const Machine& m : s.machine)
      if (m.action == MAction::End || m.action == MAction::EndRewind) return true;
    for (const Flow& f : s.after)
      if (f.kind == FlowKind::EndProgram) return true;
  }
  return false;
}

} // namespace

bool writeStructured(StructuredInput in, const StructuredSpelling& t, EmitterMaker emitter,
                     StructuredResult& out, Unkept& why) {
  if (t.doWhileLoops && !t.gotoJumps && !t.guardJumps)
    for (UnitSteps& u : in.units)
      backwardJumpsAsDoLoops(u);
  if (!t.profile->controlFlow->hasVariables) {
    if (hasRow(t, FlowAction::RepeatStart))
      for (UnitSteps& u : in.units)
        countedLoopsAsRepeats(u);
    dropUnreadAssignments(in.units);
  }
  VariablePlan plan;
  if (!planVariables(in.units, *in.source->controlFlow, *t.profile->controlFlow,
                     countersNeeded(in.units, t), plan, why))
    return false;
  std::map<std::string, std::string> names;
  if (!nameUnits(in.units, t, in.mainStem, names, why)) return false;
  // a target that must end its program gets the end the source leaves to its file's end
  if (t.profile->machine.endOfFileError && !endsProgram(in.units.front())) {
    Step end;
    end.range =
        in.units.front().steps.empty() ? SourceRange{} : in.units.front().steps.back().range;
    end.machine.push_back(Machine{MAction::End, 2, MTiming::AfterMotion, end.range});
    in.units.front().steps.push_back(std::move(end));
  }
  KeptLog kept;
  std::vector<int> counters = plan.counters;
  int loopSerial = 0;
  std::ostringstream shared; // the units of a dialect that holds them in one file
  std::string mainText;      // the main program's, when it comes after its subprograms
  for (std::size_t i = 0; i < in.units.size(); ++i) {
    const UnitSteps& u = in.units[i];
    const std::string& name = names[u.name];
    std::vector<ir::Block> blocks = t.opening(name, u.main);
    if (u.main) {
      for (const std::string& n : in.notes)
        blocks.push_back(t.commentLine(n));
      for (int v : plan.zeroAtStart) {
        ir::Block b;
        ir::Stmt st;
        st.kind = ir::StmtKind::Assign;
        st.target = ir::Expr::variable(v);
        st.value = ir::Expr::literal(0);
        b.stmts.push_back(std::move(st));
        blocks.push_back(std::move(b));
      }
    }
    UnitWriter w(t, in, plan, names, counters, loopSerial, kept, why);
    if (!w.unit(u, blocks)) return false;
    for (ir::Block& b : t.closing(name, u.main))
      blocks.push_back(std::move(b));
    std::ostringstream text;
    const bool apart = !t.unitsInOneFile || (u.main && t.subprogramsFirst);
    std::ostream& to = apart ? text : static_cast<std::ostream&>(shared);
    std::unique_ptr<emit::ProgramEmitter> e = emitter(to);
    e->beginProgram({t.unitsInOneFile ? name : std::string()});
    for (const ir::Block& b : blocks)
      e->block(b);
    e->endProgram();
    if (!t.unitsInOneFile)
      out.files.push_back({u.main ? std::string() : t.fileName(name), text.str()});
    else if (apart)
      mainText = text.str();
  }
  if (t.unitsInOneFile) out.files.push_back({std::string(), shared.str() + mainText});
  out.kept = kept.list();
  return true;
}

} // namespace gcx::xlate
