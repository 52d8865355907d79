// The interpreter's side of the FMS-3000 turning cycles whose parameters follow the code
// (fms3000.md §5.3): the parameters' X-type values from diameter to radius (Setting::DiameterX),
// the modal G0/G1 of the chamfer's straight part, and the ops from cycles/level_turning.h.
#include <fmt/format.h>

#include <limits>

#include "cycles/level_turning.h"
#include "diag/codes.h"
#include "machine/code_names.h"
#include "machine/interpreter.h"
#include "motion/geometry.h"

namespace gcx::machine {

bool Interpreter::levelTurning(const SourceRange& code, const cycles::Profile* profile) {
  if (levelCycle_ == cycles::LevelCycle::Fillet && state_.plane != motion::Plane::ZX)
    return fail(diag::code::FmsCycleParameters, code,
                fmt::format("{} turns its fillet in the lathe plane: {} first (fms3000.md "
                            "§5.3.2)",
                            levelCode_, codeName(profile_, GAction::PlaneZX)));
  cycles::LevelTurnRequest req;
  req.cycle = *levelCycle_;
  req.code = levelCode_;
  req.position = program_;
  req.incremental = state_.incremental;
  req.words = levelWords_;
  // X-type parameters follow the diameter setting; R of G166/G167 is always a radius
  if (state_.diameterAxes & 1u)
    for (char c : cycles::diameterWords(*levelCycle_))
      if (auto it = req.words.find(c); it != req.words.end()) it->second /= 2;
  req.rapidFlag = levelRapidFlag_;
  req.modalRapid = state_.motion == GAction::Rapid;
  req.feed = state_.feed;
  req.dwellSecondsPerUnit = profile_.machine.dwell.secondsPerUnit;
  req.profile = profile;
  req.spindleDirection = state_.spindleDirection;
  req.feedPerRevolution = state_.perRevolution;
  if (const auto missing = cycles::notImplemented(req))
    return fail(diag::code::NotImplemented, code, *missing);
  if (auto f = levelWords_.find('F'); f != levelWords_.end()) state_.feed = f->second;
  const auto ops = cycles::expandLevelTurning(req);
  if (const std::string* why = std::get_if<std::string>(&ops))
    return fail(diag::code::FmsCycleParameters, code, *why);
  from_.chain.push_back({code.begin, levelCode_});
  const bool ok = runCycleOps(std::get<std::vector<cycles::CycleOp>>(ops),
                              std::numeric_limits<std::size_t>::max(), BlockWords{},
                              motion::axesOf(state_.plane).normal);
  from_.chain.pop_back();
  return ok && !stopped_;
}

} // namespace gcx::machine
