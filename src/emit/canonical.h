// Canonical motion as RS274/NGC text (`gcx expand --to canonical`): G0 G1 G2 G3 G4, F, S,
// M3/M4/M5, T M6, coolant, stops; A B C and U V W words once those axes move. Coordinates are the
// machine-frame gauge point, metric, absolute: work offsets, G52/G92 shifts, tool lengths and
// programmable transformations are baked into them, so LinuxCNC's rs274 run with zero offsets and
// no G43 reproduces the path exactly (docs/canonical.md). Spirals, which RS274/NGC cannot express,
// are written as lines within the chord tolerance.
#pragma once
#include <functional>
#include <ostream>
#include <string>
#include <string_view>

#include "emit/line_buffer.h"
#include "emit/repeated_words.h"
#include "motion/event.h"
#include "motion/interpolator.h"

namespace gcx::emit {

struct CanonicalOptions {
  bool provenance = false; // a `(file:line)` comment on each line from a new source block
  double chordTolerance = motion::kDefaultChordTolerance; // mm, for spirals
  std::function<std::string(FileId)> fileName;
};

class CanonicalEmitter : public motion::Sink {
public:
  CanonicalEmitter(std::ostream& out, CanonicalOptions opt = {});
  void event(const motion::Event& e) override;
  void finish() override;

private:
  void begin(std::string_view code);
  void word(char letter, double v);
  void newWord(char letter, double v);
  void xyz(const motion::Vec3& p);
  void end(const motion::Event& e);
  void line(std::string_view text, const motion::Event& e);
  void feedMode(const motion::Event& e);
  void straight(const motion::Event& e, std::string_view code, const motion::Vec3& to,
                const motion::Extra& extraTo, bool withFeed);
  void noteExtraAxes(const motion::Event& e);
  void extraWords(const motion::Extra& x);

  std::ostream& out_;
  CanonicalOptions opt_;
  bool headerDone_ = false;
  bool perRevolution_ = false;
  motion::Plane plane_ = motion::Plane::XY;
  bool rotaryWords_ = false;   // A B C on every move once a rotary axis has moved
  bool parallelWords_ = false; // U V W likewise
  double spindleSpeed_ = 0;
  SourceLoc lastSource_;
  std::string lastChain_;
  LineBuffer line_; // the line being composed
  RepeatedWords words_;

  static constexpr int kDecimals = 6; // of every number written
};

} // namespace gcx::emit
