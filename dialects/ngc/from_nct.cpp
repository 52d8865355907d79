#include "dialects/ngc/from_nct.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <set>
#include <utility>

#include "dialects/nct/arguments.h"
#include "dialects/ngc/expression.h"
#include "dialects/ngc/printer.h"
#include "emit/number.h"

namespace gcx::ngc {

namespace {

// Whose local variables #1-#33 a program body sees.
enum class Frame {
  Main,   // the main program's
  Macro,  // a G65 macro's own, like a LinuxCNC o-word call's #1-#30
  Shared, // an M98 subprogram's: its caller's, which LinuxCNC has no form for
};

// NCT's canned cycles that LinuxCNC runs alike (docs/nct-vs-linuxcnc.md, "Drilling cycles").
bool keptCycle(double g) {
  return g == 73 || g == 81 || g == 82 || g == 83 || g == 85 || g == 89;
}

// Why an NCT cycle is not LinuxCNC's, or null when it is not a cycle.
const char* cycleDifference(double g) {
  if (g == 74 || g == 84)
    return "NCT's floating tap reverses the spindle and returns to R; LinuxCNC's G84 dwells and "
           "feeds out to the clear level, and G74 has no LinuxCNC form";
  if (g == 86) return "LinuxCNC's G86 requires a dwell P that NCT's G86 does not make";
  if (g == 76) return "NCT's G76 is fine boring, LinuxCNC's a lathe threading cycle";
  if (g == 87) return "NCT's back boring runs upward from below the bottom; LinuxCNC's differs";
  if (g == 88) return "LinuxCNC's G88 stops for a manual retract that NCT's does not";
  return nullptr;
}

// G codes kept as written: motion, planes, units, compensation off, length offset, work
// systems, distance and feed modes, reference return, cycle cancel and return levels.
bool keptModal(double g) {
  static const double codes[] = {0,  1,  2,  3,  4,  17, 18, 19, 20, 21, 28, 40, 43, 49,
                                 54, 55, 56, 57, 58, 59, 80, 90, 91, 94, 95, 98, 99};
  return std::find(std::begin(codes), std::end(codes), g) != std::end(codes);
}

// M codes LinuxCNC gives the same meaning: stops, spindle, tool change, coolant, ends.
bool keptM(double m) {
  return m == 0 || m == 1 || m == 2 || m == 3 || m == 4 || m == 5 || m == 6 || m == 7 || m == 8 ||
         m == 9 || m == 30;
}

bool isAxis(const ir::Word& w) {
  return w.address.size() == 1 &&
         std::string_view("XYZABC").find(w.address[0]) != std::string::npos;
}

void forEachVariable(const ir::Expr& e, const std::function<void(int)>& f) {
  if (e.kind == ir::ExprKind::Variable) f(static_cast<int>(e.number));
  for (const ir::Expr& a : e.args)
    forEachVariable(a, f);
}

// The local variables (#1-#33) a program reads, and those it writes.
void localUse(const std::vector<ir::Block>& blocks, std::set<int>& read, std::set<int>& written) {
  const auto local = [](int n) { return n >= 1 && n <= 33; };
  const auto reads = [&](const ir::Expr& e) {
    forEachVariable(e, [&](int n) {
      if (local(n)) read.insert(n);
    });
  };
  for (const ir::Block& b : blocks) {
    for (const ir::Word& w : b.words)
      if (w.kind == ir::ValueKind::Expression) reads(w.expr);
    for (const ir::Stmt& s : b.stmts) {
      reads(s.value);
      if (s.cond) reads(s.cond->lhs), reads(s.cond->rhs);
      if (s.target.kind == ir::ExprKind::Variable && local(static_cast<int>(s.target.number)))
        written.insert(static_cast<int>(s.target.number));
    }
  }
}

// G90 or G91 as the text runs (a subprogram's body as its first call sees it)
enum class Distance { Unknown, Absolute, Incremental };

struct Sub {
  Frame frame = Frame::Shared;
  Distance entry = Distance::Unknown, exit = Distance::Unknown; // at its call and its end
  bool written = false; // false while its body is being written (a recursive call)
  std::set<int> reads, writes;
};

class Writer {
public:
  Writer(const FindProgram& find, Unkept& unkept) : find_(find), unkept_(unkept) {}

  bool body(const std::vector<ir::Block>& blocks, Frame frame, int sub, std::string& out);
  std::string subs() const { return subText_; }
  std::vector<std::string> kept() const { return {kept_.begin(), kept_.end()}; }
  bool ended() const { return ended_; }

private:
  bool fail(const SourceRange& where, std::string what, std::string why) {
    unkept_ = {where, std::move(what), std::move(why)};
    return false;
  }
  VariableText variables(Frame frame) const;
  bool block(const ir::Block& b, Frame frame, bool last, int sub, std::string& out);
  bool statement(const ir::Stmt& s, Frame frame, std::string& out);
  bool words(const ir::Block& b, Frame frame, std::string& out);
  bool cycleWords(const ir::Block& b, double cycle, Frame frame, std::string& line);
  bool callM98(const ir::Block& b, std::string& out);
  bool workOffset(const ir::Block& b, Frame frame, std::string& out);
  bool callG65(const ir::Block& b, Frame frame, std::string& out);
  bool defineSub(const ir::Word& p, Frame frame, int& number);
  bool value(const ir::Word& w, Frame frame, std::string& out) {
    std::string why;
    if (!wordValueText(w, variables(frame), out, why))
      return fail(w.range, w.address + " word value", why);
    if (w.kind == ir::ValueKind::Expression) kept_.insert("variables and expressions");
    return true;
  }

  const FindProgram& find_;
  Unkept& unkept_;
  std::map<int, Sub> subs_;
  std::string subText_;
  std::set<std::string> kept_;
  std::vector<std::pair<int, std::string>> loops_; // open WHILE: DO number, o-word
  int labels_ = 0;
  // the cycle state as the text runs, for what LinuxCNC asks again or means otherwise
  double cycle_ = 0;
  bool retractR_ = false;     // G99
  std::string lastR_, lastZ_; // the R level and the bottom (on the drilling axis)
  char drill_ = 'Z';          // the drilling axis of the plane (G17 Z, G18 Y, G19 X)
  int motion_ = -1;           // G0-G3 as the text runs; -1: not known
  bool backOff_ = false;      // the last E was LinuxCNC's fixed 0.254 mm
  bool ended_ = false;        // M2 or M30 written
  Distance distance_ = Distance::Absolute;
};

VariableText Writer::variables(Frame frame) const {
  return [frame](int n, std::string& why) -> std::string {
    if (n >= 1 && n <= 33) {
      if (frame == Frame::Shared) {
        why = "an M98 subprogram shares its caller's local variables #1-#33; a LinuxCNC o-word "
              "call gives the subroutine its own";
        return {};
      }
      // #31-#33 are global in LinuxCNC: a named parameter without `_` is local like NCT's
      return n <= 30 ? fmt::format("#{}", n) : fmt::format("#<l{}>", n);
    }
    if ((n >= 100 && n <= 199) || (n >= 500 && n <= 999)) return fmt::format("#{}", n);
    why = n == 0 ? "#0 is NCT's vacant value; LinuxCNC has no vacant value"
                 : fmt::format("#{} is an NCT system variable; LinuxCNC's parameters there mean "
                               "other things",
                               n);
    return {};
  };
}

bool Writer::body(const std::vector<ir::Block>& blocks, Frame frame, int sub, std::string& out) {
  std::size_t lastWords = blocks.size();
  for (std::size_t i = 0; i < blocks.size(); ++i)
    if (!blocks[i].words.empty() || !blocks[i].stmts.empty()) lastWords = i;
  for (std::size_t i = 0; i < blocks.size(); ++i)
    if (!block(blocks[i], frame, i == lastWords, sub, out)) return false;
  if (!loops_.empty())
    return fail(blocks.empty() ? SourceRange{} : blocks.back().range, "WHILE",
                "a loop without its END");
  return true;
}

bool Writer::block(const ir::Block& b, Frame frame, bool last, int sub, std::string& out) {
  if (b.kind == ir::BlockKind::ProgramStart || b.kind == ir::BlockKind::ProgramEnd) return true;
  if (b.kind == ir::BlockKind::Data)
    return fail(b.range, "data entry (G10 L52 ... G11)", "LinuxCNC has no parameter entry mode");
  if (b.skipLevel)
    return fail(b.range, "block skip /",
                "LinuxCNC's block delete is a switch of its own, not "
                "NCT's skip levels");
  std::string comments;
  for (const ir::Comment& c : b.comments)
    comments += (comments.empty() ? "" : " ") + commentText(c.text);
  std::string text;
  if (!b.stmts.empty()) {
    if (!b.words.empty())
      return fail(b.range, "a statement with words", "the order of the two has no LinuxCNC form");
    if (!statement(b.stmts.front(), frame, text)) return false;
  } else if (const ir::Word* m = b.find('M'); m && m->isLiteral() && m->number == 99) {
    if (!sub || !last || b.words.size() != 1 || !loops_.empty())
      return fail(m->range, "M99",
                  sub ? "a return before the end of the subprogram"
                      : "M99 in a main program restarts it");
    text = fmt::format("o{} endsub\n", sub);
  } else if (!words(b, frame, text)) {
    return false;
  }
  if (text.empty()) {
    if (!comments.empty()) out += comments + '\n';
    return true;
  }
  // the comment goes on the block's first line
  const std::size_t eol = text.find('\n');
  if (!comments.empty()) text.insert(eol, " " + comments);
  out += text;
  return true;
}

bool Writer::statement(const ir::Stmt& s, Frame frame, std::string& out) {
  const VariableText vars = variables(frame);
  std::string why;
  const auto assignment = [&](std::string& line) {
    if (s.target.kind != ir::ExprKind::Variable)
      return fail(s.range, "assignment", "the target is not a numbered variable");
    std::string target, rhs;
    if (!expressionText(s.target, vars, target, why)) return fail(s.range, "variable", why);
    ir::Word w;
    w.kind = ir::ValueKind::Expression;
    w.expr = s.value;
    if (!wordValueText(w, vars, rhs, why)) return fail(s.range, "expression", why);
    line += target + " = " + rhs + '\n';
    kept_.insert("variables and expressions");
    return true;
  };
  switch (s.kind) {
  case ir::StmtKind::Assign:
    return assignment(out);
  case ir::StmtKind::IfThen: {
    std::string cond;
    if (!conditionText(*s.cond, vars, cond, why)) return fail(s.range, "IF condition", why);
    const std::string label = fmt::format("o<if{}>", ++labels_);
    out += label + " if " + cond + '\n';
    if (!assignment(out)) return false;
    out += label + " endif\n";
    kept_.insert("IF THEN as o-word if");
    return true;
  }
  case ir::StmtKind::While: {
    std::string cond;
    if (!conditionText(*s.cond, vars, cond, why)) return fail(s.range, "WHILE condition", why);
    loops_.emplace_back(s.loopId, fmt::format("o<w{}>", ++labels_));
    out += loops_.back().second + " while " + cond + '\n';
    kept_.insert("WHILE loops as o-word while");
    return true;
  }
  case ir::StmtKind::End:
    if (loops_.empty() || loops_.back().first != s.loopId)
      return fail(s.range, fmt::format("END{}", s.loopId), "it closes no WHILE of the program");
    out += loops_.back().second + " endwhile\n";
    loops_.pop_back();
    return true;
  case ir::StmtKind::Do:
    return fail(s.range, "DO without WHILE", "an endless loop leaves only by a jump or an end");
  case ir::StmtKind::Goto:
  case ir::StmtKind::IfGoto:
    return fail(s.range, "GOTO", "LinuxCNC has no jump to a block number");
  default:
    return fail(s.range, "the statement", "LinuxCNC has no statement with its meaning");
  }
}

bool Writer::words(const ir::Block& b, Frame frame, std::string& out) {
  // a call's other words are its arguments
  for (const ir::Word& w : b.words)
    if (w.isLiteral() && ((w.is('M') && w.number == 98) || (w.is('G') && w.number == 65)))
      return w.is('M') ? callM98(b, out) : callG65(b, frame, out);
  if (const ir::Word* g = b.find('G'); g && g->isLiteral() && g->number == 10)
    return workOffset(b, frame, out);
  std::vector<const ir::Word*> gs, ms;
  double cycle = 0;
  bool motion = false, cancel = false;
  for (const ir::Word& w : b.words) {
    if (w.is('G') && w.isLiteral() && (w.number == 90 || w.number == 91))
      distance_ = w.number == 90 ? Distance::Absolute : Distance::Incremental;
    if (w.is('G') && w.isLiteral() && w.number <= 3) motion_ = static_cast<int>(w.number);
    if (w.is('G') && w.isLiteral() && w.number >= 17 && w.number <= 19) // the drilling axis
      drill_ = w.number == 17 ? 'Z' : w.number == 18 ? 'Y' : 'X';
  }
  for (const ir::Word& w : b.words) {
    if (w.incremental && (!isAxis(w) || distance_ == Distance::Unknown))
      return fail(w.range, "the I operator",
                  "LinuxCNC has no incremental form of one word, and the distance mode here is "
                  "known only at run time");
    if (w.is('G') || w.is('M')) {
      if (!w.isLiteral())
        return fail(w.range, w.address + " with a variable", "its code is known only at run time");
      const double v = w.number;
      if (w.is('M')) {
        if (v == 99)
          return fail(w.range, "M99 with other words",
                      "only a lone M99 at the end of a subprogram is LinuxCNC's endsub");
        if (!keptM(v))
          return fail(w.range, "M" + emit::formatNumber(v), "a function of the NCT machine");
        ms.push_back(&w);
        continue;
      }
      if (keptCycle(v))
        cycle = v;
      else if (const char* why = cycleDifference(v))
        return fail(w.range, "G" + emit::formatNumber(v) + " cycle", why);
      else if (!keptModal(v))
        return fail(w.range, "G" + emit::formatNumber(v), "LinuxCNC has no code with its meaning");
      if (v <= 3 || v == 4 || v == 28) motion = true;
      if (v <= 3 || v == 80) cancel = true;
      if (v == 98 || v == 99) retractR_ = v == 99;
      gs.push_back(&w);
      continue;
    }
    if (w.address.size() != 1 ||
        std::string_view("XYZABCIJKRFPQLHSTED").find(w.address[0]) == std::string_view::npos)
      return fail(w.range, w.address + " word", "LinuxCNC has no word with its meaning");
    if (w.is('D')) return fail(w.range, "D word", "cutter compensation is written flat");
    if (isAxis(w)) motion = true;
  }
  if (cycle)
    cycle_ = cycle;
  else if (cancel)
    cycle_ = 0;
  const bool inCycle = cycle_ && !cancel && (cycle || motion || b.find('R'));
  std::string line, after;
  for (const ir::Word* g : gs)
    line += (line.empty() ? "G" : " G") + emit::formatNumber(g->number);
  // NCT returns to the initial level (G98) when cycle mode ends; LinuxCNC keeps G99
  if (cancel && retractR_) {
    line += " G98";
    retractR_ = false;
  }
  for (const ir::Word& w : b.words) {
    if (w.is('G') || w.is('M')) continue;
    if (inCycle && (w.is('E') || w.is('I') || w.is('R') || w.is(drill_))) continue;
    // NCT's turns of an arc (L) are LinuxCNC's P
    const bool turns = w.is('L') && !inCycle && (motion_ == 2 || motion_ == 3);
    if (w.is('E') || (w.is('L') && !inCycle && !turns))
      return fail(w.range, w.address + " word", "it has no meaning outside a cycle, arc or call");
    std::string v;
    if (!value(w, frame, v)) return false;
    if (w.incremental && distance_ == Distance::Absolute) // from LinuxCNC's current position
      v = fmt::format("[#{}{}{}]", 5420 + std::string_view("XYZABC").find(w.address[0]),
                      v.front() == '-' ? "" : "+", v);
    std::string& to = (motion || inCycle) && (w.is('S') || w.is('T')) ? after : line;
    to += (to.empty() ? "" : " ") + (turns ? std::string("P") : w.address) + v;
  }
  if (inCycle && !cycleWords(b, cycle, frame, line)) return false;
  for (const ir::Word* m : ms) {
    std::string& to = motion || inCycle ? after : line;
    to += (to.empty() ? "M" : " M") + emit::formatNumber(m->number);
    if (m->number == 2 || m->number == 30) ended_ = true;
  }
  // NCT acts on M, S and T after the block's motion, LinuxCNC before it
  if (!line.empty()) out += line + '\n';
  if (!after.empty()) out += after + '\n';
  return true;
}

// The R level and the bottom of a cycle block (LinuxCNC asks R again when the cycle code changes)
// and the cycle-specific words that must mean the same.
bool Writer::cycleWords(const ir::Block& b, double cycle, Frame frame, std::string& line) {
  const auto literal = [](const ir::Word* w) -> std::string {
    return w->isLiteral() ? emit::formatNumber(w->number) : std::string();
  };
  for (auto [letter, last] : {std::pair{'R', &lastR_}, std::pair{drill_, &lastZ_}}) {
    if (const ir::Word* w = b.find(letter)) {
      std::string v;
      if (!value(*w, frame, v)) return false;
      *last = v;
    }
    if (cycle || b.find(letter)) line += fmt::format(" {}{}", letter, *last);
  }
  if (const ir::Word* e = b.find('E')) {
    backOff_ = literal(e) == "0.254";
    if (!backOff_)
      return fail(e->range, "E word of G73/G83",
                  "LinuxCNC's back-off and clearance are fixed at 0.254 mm");
  }
  if ((cycle_ == 73 || cycle_ == 83) && !backOff_)
    return fail(b.range, fmt::format("G{} without E0.254", cycle_),
                "its back-off comes from the setup (N1500/N1501); LinuxCNC's is fixed at 0.254 "
                "mm");
  if (const ir::Word* i = b.find('I'); i && !(cycle_ == 85 && literal(i) == "100"))
    return fail(i->range, "I word of a cycle", "LinuxCNC retracts at the feed F only");
  if (cycle_ == 89 && !retractR_)
    return fail(b.range, "G89 with G98",
                "LinuxCNC's G89 feeds all the way out to the initial level");
  kept_.insert(fmt::format("canned cycle G{}", cycle_));
  return true;
}

// G10 L2 P1-P6 X Y Z: the work offset G54-G59 set absolutely, LinuxCNC's G10 L2 (P0, NCT's
// common offset, has no LinuxCNC counterpart).
bool Writer::workOffset(const ir::Block& b, Frame frame, std::string& out) {
  const ir::Word* l = b.find('L');
  const ir::Word* p = b.find('P');
  if (!l || !l->isLiteral() || l->number != 2 || !p || !p->isLiteral() || p->number < 1 ||
      p->number > 6 || distance_ != Distance::Absolute)
    return fail(b.range, "G10", "only G10 L2 P1-P6 under G90 sets a work offset as LinuxCNC's");
  std::string line = "G10 L2 P" + emit::formatNumber(p->number);
  for (const ir::Word& w : b.words) {
    if (&w == l || &w == p || w.is('G')) continue;
    if (!isAxis(w) || w.incremental)
      return fail(w.range, w.address + " word of G10", "LinuxCNC's G10 L2 has no such word");
    std::string v;
    if (!value(w, frame, v)) return false;
    line += " " + w.address + v;
  }
  out += line + '\n';
  kept_.insert("work offsets by G10 L2");
  return true;
}

bool Writer::defineSub(const ir::Word& p, Frame frame, int& number) {
  if (!p.isLiteral()) return fail(p.range, "P with a variable", "the program is known at run time");
  number = static_cast<int>(p.number);
  auto it = subs_.find(number);
  if (it != subs_.end()) {
    if (!it->second.written)
      return fail(p.range, "a recursive call",
                  "a subprogram is defined once, before the main program, and its recursion "
                  "depth is known only at run time");
    if (it->second.frame != frame)
      return fail(p.range, "a program called by both M98 and G65",
                  "its local variables differ between the two");
    if (it->second.entry != distance_)
      return fail(p.range, "a subprogram called under G90 and under G91",
                  "its I operator words are written for one of them");
    distance_ = it->second.exit;
    return true;
  }
  const std::vector<ir::Block>* blocks =
      find_(p.text.empty() ? std::to_string(number) : p.text, p.range);
  if (!blocks) return fail(p.range, "the called program", "it was not found");
  Sub& sub = subs_[number];
  sub.frame = frame;
  localUse(*blocks, sub.reads, sub.writes);
  std::string text;
  // a body has its own loops
  std::vector<std::pair<int, std::string>> outer;
  std::swap(outer, loops_);
  // the body is written once, for the distance mode of its first call; other calls must match
  sub.entry = distance_;
  const bool ok = body(*blocks, frame, number, text);
  sub.exit = distance_;
  std::swap(outer, loops_);
  if (!ok) return false;
  if (text.find(fmt::format("o{} endsub", number)) == std::string::npos)
    return fail(p.range, "the called program", "it does not end with M99");
  distance_ = sub.exit;
  subText_ += fmt::format("o{} sub\n", number) + text;
  sub.written = true;
  kept_.insert(fmt::format("{} O{:04} as o{} sub", frame == Frame::Macro ? "macro" : "subprogram",
                           number, number));
  return true;
}

bool Writer::callM98(const ir::Block& b, std::string& out) {
  const ir::Word* p = b.find('P');
  const ir::Word* l = b.find('L');
  if (!p || b.words.size() != (l ? 3u : 2u))
    return fail(b.range, "M98 with other words", "only P and L are kept in a call block");
  if (l && (!l->isLiteral() || l->number < 1))
    return fail(l->range, "L of M98", "a repeat count LinuxCNC's repeat must be given");
  int number = 0;
  if (!defineSub(*p, Frame::Shared, number)) return false;
  const int times = l ? static_cast<int>(l->number) : 1;
  if (times == 1) {
    out += fmt::format("o{} call\n", number);
    return true;
  }
  const std::string label = fmt::format("o<r{}>", ++labels_);
  out += fmt::format("{} repeat [{}]\no{} call\n{} endrepeat\n", label, times, number, label);
  return true;
}

bool Writer::callG65(const ir::Block& b, Frame frame, std::string& out) {
  const nct::ArgumentResult args = nct::bindArguments(b, [](const ir::Word&) { return false; });
  if (!args.ok()) return fail(args.offending->range, "G65 arguments", args.message);
  const ir::Word* p = b.find('P');
  const ir::Word* l = b.find('L');
  if (!p) return fail(b.range, "G65 without P", "no program to call");
  if (l && (!l->isLiteral() || l->number < 1))
    return fail(l->range, "L of G65", "a repeat count LinuxCNC's repeat must be given");
  std::map<int, std::string> bound;
  for (const nct::ArgumentBinding& a : args.bindings) {
    if (a.variable > 30)
      return fail(a.word->range, "argument #" + std::to_string(a.variable),
                  "LinuxCNC passes #1-#30 only");
    std::string v;
    if (!value(*a.word, frame, v)) return false;
    bound[a.variable] = v;
  }
  int number = 0;
  if (!defineSub(*p, Frame::Macro, number)) return false;
  for (int n : subs_[number].reads)
    if (!bound.count(n) && !subs_[number].writes.count(n))
      return fail(b.range, fmt::format("G65 without the argument #{}", n),
                  fmt::format("O{:04} reads it vacant; LinuxCNC has no vacant value", number));
  std::string call = fmt::format("o{} call", number);
  const int last = bound.empty() ? 0 : bound.rbegin()->first;
  for (int n = 1; n <= last; ++n)
    call += " [" + (bound.count(n) ? bound[n] : std::string("0")) + "]";
  const int times = l ? static_cast<int>(l->number) : 1;
  if (times == 1) {
    out += call + '\n';
  } else {
    const std::string label = fmt::format("o<r{}>", ++labels_);
    out += fmt::format("{} repeat [{}]\n{}\n{} endrepeat\n", label, times, call, label);
  }
  return true;
}

} // namespace

bool writeFromNct(const std::vector<ir::Block>& main, const FindProgram& find, Structured& out,
                  Unkept& unkept) {
  Writer w(find, unkept);
  std::string body;
  if (!w.body(main, Frame::Main, 0, body)) return false;
  out.text = "(written by gcx translate --to ngc: the structure LinuxCNC gives the same meaning "
             "is kept)\n";
  out.text += w.subs();
  out.text += body;
  // LinuxCNC needs an end; NCT ends at the last block too
  if (!w.ended()) out.text += "M2\n";
  out.kept = w.kept();
  return true;
}

} // namespace gcx::ngc
