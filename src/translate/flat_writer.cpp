#include "translate/flat_writer.h"

#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"
#include "emit/spiral_lines.h"
#include "motion/decimal.h"
#include "motion/geometry.h"

namespace gcx::emit {

using motion::Kind;

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kSpiralChordTolerance = 2e-4; // mm

// Arc centre words as the target reads them with no setup: its parameter's fallback
// (FMS-3000: 0 incremental from the start, 1 absolute, 2 absolute under G90).
bool absoluteCentres(const Profile& p) {
  const SettingSpec* s = p.machine.setting(Setting::ArcCentreAbsolute);
  return s && s->fallback != 0; // the output is written under G90
}

// A note as comment lines of at most 60 characters: WL4 blocks hold at most 80 (wl4.md §1.3).
std::vector<std::string> wrapped(const std::string& text) {
  std::vector<std::string> lines(1);
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t next = text.find(' ', pos);
    if (next == std::string::npos) next = text.size();
    const std::string w = text.substr(pos, next - pos);
    if (!lines.back().empty() && lines.back().size() + 1 + w.size() > 60) lines.emplace_back();
    lines.back() += (lines.back().empty() ? "" : " ") + w;
    pos = next + 1;
  }
  return lines;
}

} // namespace

ir::Block lineComment(const std::string& text) {
  ir::Block b;
  b.kind = ir::BlockKind::CommentLine;
  ir::Comment c;
  c.text = text;
  c.kind = ir::CommentKind::ToLineEnd;
  b.comments.push_back(std::move(c));
  return b;
}

FlatWriter::FlatWriter(std::unique_ptr<ProgramEmitter> emitter, FlatSyntax syntax,
                       const MotionWriterOptions& opt, diag::Engine& diags)
    : emitter_(std::move(emitter)), syntax_(std::move(syntax)), opt_(opt), diags_(diags) {}

bool FlatWriter::fail(const motion::Event& e, const char* code, const std::string& message) {
  if (ok_) diags_.error(code, SourceRange{e.from.at, 1}, message);
  ok_ = false;
  return false;
}

double FlatWriter::rounded(double v) const {
  const double scale = std::pow(10.0, syntax_.decimals);
  const double r = std::round(v * scale) / scale;
  return r == 0 ? 0 : r; // no "-0"
}

void FlatWriter::begin() {
  block_ = ir::Block{};
}

void FlatWriter::flush() {
  emitter_->block(block_);
  block_ = ir::Block{};
}

void FlatWriter::word(const char* address, double v) {
  ir::Word w;
  w.address = address;
  w.number = v;
  w.order = static_cast<std::uint32_t>(block_.words.size()); // WL4 prints items in this order
  block_.words.push_back(std::move(w));
}

void FlatWriter::code(char letter, int code10) {
  ir::Word w;
  w.address = std::string(1, letter);
  w.number = code10 / 10.0;
  w.text = fmt::format("{:0{}}", code10 / 10, syntax_.codeDigits);
  if (code10 % 10) w.text += fmt::format(".{}", code10 % 10);
  w.order = static_cast<std::uint32_t>(block_.words.size());
  block_.words.push_back(std::move(w));
}

bool FlatWriter::gcode(GAction a, const motion::Event& e, const char* meaning) {
  for (const GCodeSpec& g : syntax_.profile->gcodes)
    if (g.action == a) {
      code('G', g.code10);
      return true;
    }
  return fail(e, diag::code::TranslateNoCode,
              fmt::format("{} has no G code for {}", syntax_.label, meaning));
}

bool FlatWriter::mcode(MAction a, const motion::Event& e, const char* meaning) {
  for (const MCodeSpec& m : syntax_.profile->machine.mcodes)
    if (m.action == a) {
      code('M', m.code * 10);
      return true;
    }
  return fail(e, diag::code::TranslateNoCode,
              fmt::format("{} has no M code for {}", syntax_.label, meaning));
}

// A value of an address with the target's limits: its range, and whole numbers where the
// address takes no fraction (FMS-3000 E, tenths of a second).
bool FlatWriter::checkedWord(char letter, double v, const motion::Event& e, const char* meaning) {
  const AddressSpec* spec = syntax_.profile->address(std::string_view(&letter, 1));
  if (!spec)
    return fail(e, diag::code::TranslateNoCode,
                fmt::format("{} has no address {} for {}", syntax_.label, letter, meaning));
  double value = v;
  if (!spec->decimal) {
    value = std::round(v);
    if (std::fabs(value - v) > 1e-6)
      return fail(e, diag::code::TranslateValue,
                  fmt::format("{} writes {} as a whole number of {}: {} is not one", syntax_.label,
                              meaning, letter, motion::formatDecimal(v, 6)));
  } else {
    value = rounded(v);
  }
  if (value < spec->min || value > spec->max)
    return fail(e, diag::code::TranslateValue,
                fmt::format("{} {}{} for {} is outside {}'s range {} to {}", syntax_.label, letter,
                            motion::formatDecimal(value, 6), meaning, letter,
                            motion::formatDecimal(spec->min, 6),
                            motion::formatDecimal(spec->max, 6)));
  const char addr[2] = {letter, 0};
  word(addr, value);
  return true;
}

void FlatWriter::header(const motion::Event& e) {
  if (headerDone_) return;
  headerDone_ = true;
  emitter_->beginProgram({syntax_.programName});
  for (const ir::Block& b : syntax_.opening)
    emitter_->block(b);
  for (const std::string& note : opt_.notes)
    for (const std::string& line : wrapped(note))
      emitter_->block(syntax_.comment(line));
  begin();
  gcode(GAction::Absolute, e, "absolute coordinates");
  gcode(GAction::FeedPerMinute, e, "feed per minute");
  gcode(GAction::PlaneXY, e, "the XY plane");
  // the output is metric; a dialect without inch mode has no code for it (FMS G21 is another
  // function, found by meaning it is not written)
  for (const GCodeSpec& g : syntax_.profile->gcodes)
    if (g.action == GAction::Metric) code('G', g.code10);
  flush();
}

bool FlatWriter::feedMode(bool perRevolution, const motion::Event& e) {
  if (perRevolution == perRevolution_) return true;
  perRevolution_ = perRevolution;
  begin();
  if (!gcode(perRevolution ? GAction::FeedPerRevolution : GAction::FeedPerMinute, e,
             perRevolution ? "feed per revolution" : "feed per minute"))
    return false;
  flush();
  return true;
}

bool FlatWriter::position(const motion::Vec3& p, const motion::Extra& x, const motion::Event& e) {
  static const char* const axes[] = {"X", "Y", "Z"};
  for (int i = 0; i < 3; ++i) {
    at_[i] = rounded(p[i]);
    word(axes[i], at_[i]);
  }
  for (int i = 3; i < 6; ++i)
    if (x[i] != 0)
      return fail(e, diag::code::TranslateNoCode,
                  fmt::format("{} has no axis {} parallel to {}: the move cannot be written",
                              syntax_.label, motion::kExtraAxisNames[i], axes[i - 3]));
  if (!extraWords_) return true;
  for (int i = 0; i < 3; ++i) {
    const char name[2] = {motion::kExtraAxisNames[i], 0};
    if (!syntax_.profile->address(name))
      return fail(e, diag::code::TranslateNoCode,
                  fmt::format("{} has no rotary axis {}", syntax_.label, name));
    word(name, rounded(x[i]));
  }
  return true;
}

bool FlatWriter::straight(GAction a, const motion::Vec3& to, const motion::Extra& x,
                          const motion::Event& e) {
  begin();
  if (!gcode(a, e, a == GAction::Rapid ? "a rapid move" : "a linear move")) return false;
  if (!position(to, x, e)) return false;
  if (a != GAction::Rapid) word("F", rounded(e.feed));
  flush();
  return true;
}

// One arc of at most one turn beyond its sweep (turns > 0 only where the target counts turns).
bool FlatWriter::arcPiece(const motion::Event& e, const motion::Vec3& to, const motion::Extra& x,
                          double sweep, int turns) {
  const motion::PlaneAxes ax = motion::axesOf(e.plane);
  const motion::Vec3 from = at_;
  begin();
  if (!gcode(e.clockwise ? GAction::ArcCW : GAction::ArcCCW, e,
             e.clockwise ? "a clockwise arc" : "a counter-clockwise arc"))
    return false;
  if (!position(to, x, e)) return false;
  static const char* const centre[] = {"I", "J", "K"};
  const bool absolute = absoluteCentres(*syntax_.profile);
  for (int a : {0, 1, 2})
    if (a == ax.first || a == ax.second)
      word(centre[a], absolute ? rounded(e.center[a]) : rounded(e.center[a] - from[a]));
  const double rise = at_[ax.normal] - from[ax.normal];
  bool qualified = false;
  for (const GCodeSpec& g : syntax_.profile->gcodes)
    if (g.action == GAction::HelicalQualifier && rise != 0 && !qualified) {
      // a helix names its pitch, the travel per turn, in the normal axis's centre letter
      code('G', g.code10);
      word(centre[ax.normal], std::round(rise * kTwoPi / sweep * 1e6) / 1e6);
      qualified = true;
    }
  if (turns > 0) word("L", turns + 1);
  word("F", rounded(e.feed));
  flush();
  return true;
}

bool FlatWriter::arc(const motion::Event& e) {
  if (!feedMode(e.perRevolution, e)) return false;
  const motion::ArcGeometry geo(e);
  if (isSpiral(e)) {
    // lines, as canonical motion writes spirals, but closer to the curve: the points rounded to
    // 0.001 mm may move 0.0007 mm in the plane, and chord plus rounding must stay within the
    // proof's 0.001 mm
    for (const LinePoint& p : spiralLines(e, geo, kSpiralChordTolerance))
      if (!straight(GAction::Linear, p.at, p.extra, e)) return false;
    return true;
  }
  if (e.plane != plane_) {
    begin();
    const GAction plane = e.plane == motion::Plane::XY   ? GAction::PlaneXY
                          : e.plane == motion::Plane::ZX ? GAction::PlaneZX
                                                         : GAction::PlaneYZ;
    if (!gcode(plane, e, motion::planeCode(e.plane))) return false;
    flush();
    plane_ = e.plane;
  }
  if (e.turns == 0 || syntax_.profile->machine.arcL == ArcLMeaning::Turns)
    return arcPiece(e, e.end, e.extraEnd, geo.sweep(), e.turns);
  // a target without a turn count gets one full circle per extra turn, then the rest
  for (int k = 1; k <= e.turns; ++k) {
    const double t = k * kTwoPi / geo.sweep();
    const motion::Extra x = e.extraStart + (e.extraEnd - e.extraStart) * t;
    if (!arcPiece(e, geo.point(t), x, kTwoPi, 0)) return false;
  }
  return arcPiece(e, e.end, e.extraEnd, geo.sweep() - e.turns * kTwoPi, 0);
}

bool FlatWriter::spindle(const motion::Event& e) {
  begin();
  if (!checkedWord('S', e.value, e, "the spindle speed")) return false;
  const MAction a = e.direction > 0   ? MAction::SpindleCW
                    : e.direction < 0 ? MAction::SpindleCCW
                                      : MAction::SpindleStop;
  if (!mcode(a, e,
             e.direction > 0   ? "the spindle clockwise"
             : e.direction < 0 ? "the spindle counter-clockwise"
                               : "a spindle stop"))
    return false;
  flush();
  return true;
}

// The coolant event's value is its meaning as canonical motion and the equivalence engine read
// it: 7 mist, 8 flood, 9 off.
bool FlatWriter::coolant(const motion::Event& e) {
  const int meaning = static_cast<int>(e.value);
  const char* name = meaning == 7 ? "mist coolant" : meaning == 8 ? "flood coolant" : "coolant off";
  for (const MCodeSpec& m : syntax_.profile->machine.mcodes)
    if (m.action == MAction::Coolant && m.code == meaning) {
      begin();
      code('M', m.code * 10);
      flush();
      return true;
    }
  return fail(e, diag::code::TranslateNoCode,
              fmt::format("{} has no M code for {} (its coolant is machine-specific)",
                          syntax_.label, name));
}

// A dwell in the target's word and unit (NCT G4 P seconds, FMS-3000 G04 E tenths of a second,
// WL4 G4 E seconds); in revolutions under feed per revolution, as every dialect reads it then.
bool FlatWriter::dwell(const motion::Event& e) {
  if (!feedMode(e.perRevolution, e)) return false;
  const DwellRule& rule = syntax_.profile->machine.dwell;
  begin();
  if (!gcode(GAction::Dwell, e, "a dwell")) return false;
  const std::string meaning =
      e.perRevolution ? std::string("a dwell in revolutions")
      : rule.secondsPerUnit == 1
          ? std::string("a dwell in seconds")
          : fmt::format("a dwell in units of {} s", motion::formatDecimal(rule.secondsPerUnit, 6));
  if (!checkedWord(rule.word, e.value / rule.secondsPerUnit, e, meaning.c_str())) return false;
  flush();
  return true;
}

// The program end by the source's meaning of its code (FMS-3000 M98 ends a program, NCT M98
// calls one): with rewind (M30) or without.
bool FlatWriter::end(const motion::Event& e) {
  const MCodeSpec* source =
      opt_.source ? opt_.source->machine.mcode(static_cast<int>(e.value)) : nullptr;
  const bool rewind = source ? source->action == MAction::EndRewind : e.value == 30;
  begin();
  if (!mcode(rewind ? MAction::EndRewind : MAction::End, e,
             rewind ? "the program end with rewind" : "the program end"))
    return false;
  flush();
  ended_ = true;
  return true;
}

// The target's blocks as a hole's lowering writes them.
class FlatWriter::HoleOut : public xlate::BlockOut {
public:
  explicit HoleOut(FlatWriter& w) : w_(w) {}
  const Profile& profile() const override { return *w_.syntax_.profile; }
  void writeCode(char letter, int code10) override { w_.code(letter, code10); }
  void writeValue(const char* address, double value) override {
    w_.word(address, w_.rounded(value));
  }
  void writeExact(const char* address, double value) override { w_.word(address, value); }
  void writeAssign(int variable, double value) override {
    ir::Stmt s;
    s.kind = ir::StmtKind::Assign;
    s.target = ir::Expr::variable(variable);
    s.value = ir::Expr::literal(w_.rounded(value));
    s.order = static_cast<std::uint32_t>(w_.block_.words.size() + w_.block_.stmts.size());
    w_.block_.stmts.push_back(std::move(s));
  }
  double rounded(double value) const override { return w_.rounded(value); }
  void endBlock() override { w_.flush(); }

private:
  FlatWriter& w_;
};

void FlatWriter::record(const xlate::Hole& h, const std::string& why) {
  if (opt_.structures)
    opt_.structures->push_back({h.at, std::string(xlate::holeKindName(h.kind)), why});
}

// A hole as the target's cycle, when it has one of the same meaning here; false (nothing
// written) when not.
bool FlatWriter::lowerHole(const xlate::Hole& h, const motion::Event& first) {
  HoleOut out(*this);
  if (const std::optional<std::string> why = syntax_.holes->refuse(h, out)) {
    record(h, *why);
    return false;
  }
  if (!feedMode(false, first)) return false;
  if (plane_ != motion::Plane::XY) { // the cycle drills along the plane's normal: Z
    begin();
    if (!gcode(GAction::PlaneXY, first, "the XY plane")) return false;
    flush();
    plane_ = motion::Plane::XY;
  }
  syntax_.holes->write(h, out);
  inCycle_ = true;
  at_ = motion::Vec3(rounded(h.x), rounded(h.y), rounded(h.exit));
  record(h, "");
  return true;
}

// Writes the events that can no longer become part of a hole; the rest wait for the next
// event (or the end, `complete`).
void FlatWriter::drain(bool complete) {
  while (ok_ && !ended_ && !pending_.empty()) {
    const std::vector<motion::Event> window(pending_.begin(), pending_.end());
    const xlate::HoleMatch m = extraWords_
                                   ? xlate::HoleMatch{}
                                   : xlate::matchHole(window, complete, last_ ? &*last_ : nullptr);
    if (m.status == xlate::HoleMatch::NeedMore) return;
    std::size_t taken = 1;
    if (m.status == xlate::HoleMatch::Found) {
      taken = m.length;
      if (!lowerHole(m.hole, window.front()))
        for (std::size_t i = 0; i < taken && ok_; ++i) // the cycle's own motion
          write(window[i]);
    } else {
      write(window.front());
    }
    last_ = window[taken - 1];
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(taken));
  }
}

void FlatWriter::event(const motion::Event& e) {
  if (!ok_ || ended_) return;
  header(e);
  if (motion::isMotion(e))
    for (int i = 0; i < 3; ++i)
      if (e.extraStart[i] != e.extraEnd[i]) extraWords_ = true;
  if (!syntax_.holes) {
    write(e);
    return;
  }
  pending_.push_back(e);
  drain(false);
}

void FlatWriter::write(const motion::Event& e) {
  if (!ok_ || ended_) return;
  if (inCycle_) { // a block that is no hole ends the target's cycle mode first
    HoleOut out(*this);
    syntax_.holes->cancel(out);
    inCycle_ = false;
  }
  switch (e.kind) {
  case Kind::Rapid:
    straight(GAction::Rapid, e.end, e.extraEnd, e);
    return;
  case Kind::Feed:
    if (e.lead > 0) {
      fail(e, diag::code::TranslateNoCode,
           fmt::format("a spindle-synchronised move (thread, rigid tapping) is not written to {} "
                       "yet",
                       syntax_.label));
      return;
    }
    if (feedMode(e.perRevolution, e)) straight(GAction::Linear, e.end, e.extraEnd, e);
    return;
  case Kind::Arc:
    arc(e);
    return;
  case Kind::Dwell:
    dwell(e);
    return;
  case Kind::Spindle:
    spindle(e);
    return;
  case Kind::SpindleOrient:
    if (e.value != 0) {
      fail(e, diag::code::TranslateNoCode,
           fmt::format("a spindle orientation to {} degrees is not written to {} yet",
                       motion::formatDecimal(e.value, 6), syntax_.label));
      return;
    }
    begin();
    if (mcode(MAction::SpindleOrient, e, "a spindle orientation")) flush();
    return;
  case Kind::ToolChange:
    begin();
    if (!checkedWord('T', e.value, e, "the tool number")) return;
    if (mcode(MAction::ToolChange, e, "a tool change")) flush();
    return;
  case Kind::Coolant:
    coolant(e);
    return;
  case Kind::Stop:
    begin();
    if (mcode(e.optional ? MAction::OptionalStop : MAction::Stop, e,
              e.optional ? "an optional stop" : "a program stop"))
      flush();
    return;
  case Kind::End:
    end(e);
    return;
  case Kind::Message:
    emitter_->block(syntax_.comment(e.text));
    return;
  case Kind::OverrideLock:
    fail(e, diag::code::TranslateNoCode,
         fmt::format("locking the feed and speed overrides is not written to {} yet",
                     syntax_.label));
    return;
  case Kind::RadiusComp:
    fail(e, diag::code::TranslateNoCode,
         fmt::format("radius compensation is written to {} as the compensated path only",
                     syntax_.label));
    return;
  case Kind::PlaneChange:
  case Kind::UnitsChange:
  case Kind::FeedModeChange:
    return; // the output is metric; planes and feed modes are written where moves need them
  }
}

void FlatWriter::finish() {
  if (syntax_.holes) drain(true);
  if (!ok_) return;
  motion::Event last;
  if (inCycle_ && !ended_) {
    HoleOut out(*this);
    syntax_.holes->cancel(out);
    inCycle_ = false;
  }
  header(last);
  // a program of the target ends with its end code (FMS-3000 requires one, 001:3880)
  if (!ended_) {
    last.value = 2;
    if (!end(last)) return;
  }
  for (const ir::Block& b : syntax_.closing)
    emitter_->block(b);
  emitter_->endProgram();
}

} // namespace gcx::emit
