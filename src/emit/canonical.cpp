#include "emit/canonical.h"

#include <fmt/format.h>

#include "emit/spiral_lines.h"
#include "motion/decimal.h"
#include "motion/geometry.h"
#include "motion/interpolator.h"

namespace gcx::emit {

using motion::Kind;

namespace {
// What ostream::write does for a good stream that is neither tied nor unit-buffered (a file,
// a string): hand the line to its buffer in one call. Its sentry object per line cost more
// than the copy.
void writeLine(std::ostream& out, std::string_view line) {
  const auto n = static_cast<std::streamsize>(line.size());
  if (!out.good() || out.tie() || (out.flags() & std::ios::unitbuf)) {
    out.write(line.data(), n);
    return;
  }
  if (out.rdbuf()->sputn(line.data(), n) != n) out.setstate(std::ios::badbit);
}
} // namespace

CanonicalEmitter::CanonicalEmitter(std::ostream& out, CanonicalOptions opt)
    : out_(out), opt_(std::move(opt)) {}

// Each line is composed in line_, whose storage every line reuses, and written with one call:
// the output budget (--max-output) still sees every line as soon as it is complete.
void CanonicalEmitter::begin(std::string_view code) {
  line_.clear();
  char* to = line_.room(code.size());
  for (const char c : code) // a code of two or three letters: no library call
    *to++ = c;
  line_.commit(to);
}

// A word not repeated from the line before. Out of line, so that a repeated word, copied,
// saves no registers for the calls here.
[[gnu::noinline]] void CanonicalEmitter::newWord(char letter, double v) {
  char* to = line_.room(motion::kWordRoom);
  if (char* end = motion::putWord(to, letter, v, kDecimals)) {
    words_.store(letter, v, to, end);
    line_.commit(end);
    return;
  }
  std::string text; // a number beyond the integer fast path
  motion::appendWord(text, letter, v, kDecimals);
  line_.append(text);
}

void CanonicalEmitter::word(char letter, double v) {
  if (char* end = words_.repeat(line_.room(motion::kWordRoom), letter, v))
    line_.commit(end);
  else
    newWord(letter, v);
}

void CanonicalEmitter::xyz(const motion::Vec3& p) {
  word('X', p.x());
  word('Y', p.y());
  word('Z', p.z());
}

void CanonicalEmitter::end(const motion::Event& e) {
  if (!headerDone_) {
    out_ << "(gcx canonical motion: machine frame, mm, absolute; offsets and tool lengths are "
            "in the coordinates)\n"
            "G21 G90 G94 G17 G40 G49 G80 G54\n";
    headerDone_ = true;
  }
  const SourceLoc& at = e.from.at;
  if (opt_.provenance && at.valid()) {
    // a new source line, or the same one in another call, loop iteration, hole or pass
    std::string chain;
    for (auto it = e.from.chain.rbegin(); it != e.from.chain.rend(); ++it)
      chain += fmt::format(", in {}", it->what);
    if (at.line != lastSource_.line || at.file != lastSource_.file || chain != lastChain_) {
      std::string where = opt_.fileName ? opt_.fileName(at.file) : std::string("line");
      line_.append(fmt::format(" ({}:{}{})", where, at.line, chain));
      lastSource_ = at;
      lastChain_ = std::move(chain);
    }
  }
  line_.push_back('\n');
  writeLine(out_, line_.view());
}

void CanonicalEmitter::line(std::string_view text, const motion::Event& e) {
  begin(text);
  end(e);
}

void CanonicalEmitter::feedMode(const motion::Event& e) {
  if (e.perRevolution == perRevolution_) return;
  perRevolution_ = e.perRevolution;
  line(perRevolution_ ? "G95" : "G94", e);
}

// Most programs never move an extra axis and keep to X Y Z. Once one has moved, all three words
// of its group (A B C or U V W) are written on every move, so each line states the whole target.
void CanonicalEmitter::noteExtraAxes(const motion::Event& e) {
  for (int i = 0; i < 6; ++i)
    if (e.extraStart[i] != e.extraEnd[i]) (i < 3 ? rotaryWords_ : parallelWords_) = true;
}

void CanonicalEmitter::extraWords(const motion::Extra& x) {
  for (int i = 0; i < 6; ++i)
    if (i < 3 ? rotaryWords_ : parallelWords_) word(motion::kExtraAxisNames[i], x[i]);
}

void CanonicalEmitter::straight(const motion::Event& e, std::string_view code,
                                const motion::Vec3& to, const motion::Extra& extraTo,
                                bool withFeed) {
  begin(code);
  xyz(to);
  extraWords(extraTo);
  if (withFeed) word('F', e.feed);
  end(e);
}

void CanonicalEmitter::event(const motion::Event& e) {
  if (motion::isMotion(e)) noteExtraAxes(e);
  switch (e.kind) {
  case Kind::Rapid:
    straight(e, "G0", e.end, e.extraEnd, false);
    return;
  case Kind::Feed:
    if (e.lead > 0) { // spindle-synchronised: G33 with the lead per revolution as K
      begin("G33");
      xyz(e.end);
      extraWords(e.extraEnd);
      word('K', e.lead);
      end(e);
      return;
    }
    feedMode(e);
    straight(e, "G1", e.end, e.extraEnd, true);
    return;
  case Kind::Arc: {
    feedMode(e);
    if (!declaredCircle(e) && isSpiral(e)) {
      for (const LinePoint& p : spiralLines(e, motion::ArcGeometry(e), opt_.chordTolerance))
        straight(e, "G1", p.at, p.extra, true);
      return;
    }
    if (e.plane != plane_) {
      plane_ = e.plane;
      line(motion::planeCode(plane_), e);
    }
    const motion::Vec3 d = e.center - e.start;
    const motion::PlaneAxes ax = motion::axesOf(e.plane);
    static const char letters[] = {'I', 'J', 'K'};
    begin(e.clockwise ? "G2" : "G3");
    xyz(e.end);
    extraWords(e.extraEnd);
    for (int a : {0, 1, 2})
      if (a == ax.first || a == ax.second) word(letters[a], d[a]);
    if (e.turns > 0) line_.append(fmt::format(" P{}", e.turns + 1));
    word('F', e.feed);
    end(e);
    return;
  }
  case Kind::Dwell: {
    double seconds = e.value;
    if (e.perRevolution) {
      if (spindleSpeed_ <= 0) {
        line(fmt::format("(dwell of {} revolutions with the spindle stopped)",
                         motion::formatDecimal(e.value, kDecimals)),
             e);
        return;
      }
      seconds = e.value * 60.0 / spindleSpeed_;
    }
    begin("G4");
    word('P', seconds);
    end(e);
    return;
  }
  case Kind::Spindle:
    spindleSpeed_ = e.value;
    line(fmt::format("S{} {}", motion::formatDecimal(e.value, kDecimals),
                     e.direction > 0   ? "M3"
                     : e.direction < 0 ? "M4"
                                       : "M5"),
         e);
    return;
  case Kind::SpindleOrient: // LinuxCNC acts on M19 only with R (a bare M19 is ignored)
    line(fmt::format("M19 R{}", motion::formatDecimal(e.value, kDecimals)), e);
    return;
  case Kind::ToolChange:
    line(fmt::format("T{} M6", motion::formatDecimal(e.value, kDecimals)), e);
    return;
  case Kind::Coolant:
    line(fmt::format("M{}", motion::formatDecimal(e.value, kDecimals)), e);
    return;
  case Kind::Stop:
    line(e.optional ? "M1" : "M0", e);
    return;
  case Kind::End:
    line(e.value == 30 ? "M30" : "M2", e);
    return;
  case Kind::Message:
    line("(MSG," + e.text + ")", e);
    return;
  case Kind::OverrideLock: // LinuxCNC: M49 disables the feed and speed overrides, M48 enables
    line(e.value != 0 ? "M49" : "M48", e);
    return;
  case Kind::RadiusComp: // LinuxCNC compensates itself: G41.1/G42.1 take the tool diameter
    if (e.value == 0) {
      line("G40", e);
      return;
    }
    plane_ = e.plane;
    line(fmt::format("{} {} D{}", motion::planeCode(plane_), e.value > 0 ? "G41.1" : "G42.1",
                     motion::formatDecimal(2 * e.startRadius, kDecimals)),
         e);
    return;
  case Kind::PlaneChange:
  case Kind::UnitsChange:
  case Kind::FeedModeChange:
    // The output is always mm, and G17-G19 / G94-G95 are written from the moves that need them.
    return;
  }
}

void CanonicalEmitter::finish() {
  out_.flush();
}

} // namespace gcx::emit
