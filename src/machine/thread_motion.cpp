// Spindle-synchronised thread moves (WL4 G32 and G33, wl4.md §3.6). F is the lead along the
// axis with the longest travel, taken when the sequence of thread blocks starts (a new F in a
// later block acts after it). The canonical output says a thread as LinuxCNC's G33 K: a
// constant lead along Z from the spindle's index, so the event carries the lead along Z, and a
// phase P, a lead change I or a thread without Z travel is a located error, never a guess.
// G33 runs to the end point, reverses the spindle, returns to the start on the same lead and
// restores the spindle's direction. FMS-3000's G33 (fms3000.md §3.17, 001:1517-1530) makes one
// G1 block such a move, and the block's modal motion holds after it.
#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"
#include "emit/number.h"
#include "machine/code_names.h"
#include "machine/interpreter.h"

namespace gcx::machine {

bool Interpreter::threadMove(const BlockWords& w, const Vec3& to, const motion::Extra& extraTo) {
  const std::string code = codeName(profile_, state_.motion);
  if (!threadLead_) {
    for (const ir::Word* word : {w.p, w.ijk[0]})
      if (word && word->number != 0)
        return fail(diag::code::Wl4ThreadNotExpressible, word->range,
                    fmt::format("{} {}{}: the canonical output's thread (G33 K) has no {}", code,
                                word->address, emit::formatNumber(word->number),
                                word == w.p ? "spindle phase" : "lead change per revolution"));
    if (state_.feed <= 0)
      return fail(diag::code::MissingData, blockRange_, fmt::format("{} without its lead F", code));
    threadLead_ = state_.feed;
  }
  const Vec3 start = machine_, end = toMachine(to), from = program_;
  const Vec3 travel = (end - start).cwiseAbs();
  if (travel.maxCoeff() < 1e-9) return true;
  if (travel.z() < 1e-9)
    return fail(diag::code::Wl4ThreadNotExpressible, blockRange_,
                fmt::format("{} without travel along Z: the canonical output's thread (G33 K) "
                            "leads along Z only",
                            code));
  // F leads the longest axis; along Z the same revolutions cover |dZ|
  const double leadZ = *threadLead_ * travel.z() / travel.maxCoeff();
  const motion::Extra extraFrom = extra_;
  emitLine(motion::Kind::Feed, end, extraTo, leadZ, leadZ);
  program_ = to;
  if (state_.motion != GAction::ThreadReciprocating) {
    if (profile_.machine.threadSequenceEnds)
      threadEnd_ = ThreadEnd{blockRange_, w.has(GAction::ExactStopOnce)};
    return true;
  }
  const int direction = state_.spindleDirection;
  state_.spindleDirection = -direction;
  emitSpindle();
  emitLine(motion::Kind::Feed, start, extraFrom, leadZ, leadZ);
  state_.spindleDirection = direction;
  emitSpindle();
  program_ = from;
  return true;
}

bool Interpreter::threadOnce(const ir::Word& code) {
  const std::string name = fmt::format("{}{}", code.address, code.text);
  if (state_.motion == GAction::Rapid)
    return fail(diag::code::ThreadAtRapid, code.range,
                fmt::format("{} under a rapid: a spindle-synchronised move runs at the feed F, "
                            "in mm per revolution",
                            name));
  if (state_.motion != GAction::Linear)
    return fail(
        diag::code::NotImplemented, code.range,
        fmt::format("{} with an arc (a spindle-synchronised arc) is not implemented yet", name));
  state_.motion = GAction::ThreadMotion;
  threadLead_.reset(); // F of this block, or the one in force, is the lead
  return true;
}

bool Interpreter::threadSequenceEnd(const BlockWords& w, bool ending) {
  if (!threadEnd_ || (!ending && state_.motion == GAction::ThreadMotion)) return true;
  const ThreadEnd last = *std::exchange(threadEnd_, std::nullopt);
  const std::string thread = codeName(profile_, GAction::ThreadMotion);
  const GAction m = state_.motion;
  if (ending || (m != GAction::Rapid && m != GAction::Linear && m != GAction::ArcCW &&
                 m != GAction::ArcCCW)) {
    const ir::Word* code = ending ? nullptr : w.findAction(m);
    return fail(diag::code::ThreadSequenceOpen, code ? code->range : blockRange_,
                fmt::format("{} the {} sequence before it: a thread sequence ends with {} on "
                            "its last move and then {}-{} (wl4.md §3.6)",
                            ending ? "the program ends inside" : "this code does not end", thread,
                            codeName(profile_, GAction::ExactStopOnce),
                            codeName(profile_, GAction::Rapid),
                            codeName(profile_, GAction::ArcCCW)));
  }
  if (!last.exactStop)
    diags_.warning(diag::code::ThreadSequenceNoStop, last.block,
                   fmt::format("the last move of this {} sequence has no {}: the manual requires "
                               "an exact stop there before {}-{} ends the thread (wl4.md §3.6)",
                               thread, codeName(profile_, GAction::ExactStopOnce),
                               codeName(profile_, GAction::Rapid),
                               codeName(profile_, GAction::ArcCCW)));
  return true;
}

} // namespace gcx::machine
