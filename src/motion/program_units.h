// The program-units view of a motion stream: after a G20 (UnitsChange 20) every length, feed
// and thread lead is written in inches again, as the program gave it; G21 returns to mm. The
// events of the interpreter are always in mm (event.h); this is the last adapter of the chain
// machine → work → program frame, for a consumer that wants the program's own numbers.
#pragma once
#include "motion/event.h"

namespace gcx::motion {

class ProgramUnits : public Sink {
public:
  /// inch: the units in force before the first UnitsChange (the setup's power-on units).
  explicit ProgramUnits(Sink& next, bool inch = false) : next_(next), inch_(inch) {}
  void event(const Event& e) override;
  void finish() override { next_.finish(); }

private:
  Sink& next_;
  bool inch_;
};

} // namespace gcx::motion
