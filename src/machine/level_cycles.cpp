// The interpreter's side of the level drilling cycles (FMS-3000 G81-G88, fms3000.md §5.1): the
// words before the cycle code are an ordinary block that runs first; the words after it are the
// cycle's parameters, remembered while the same cycle is programmed again and cleared by G80
// or another cycle; the hole's ops come from cycles/level_drilling.h.
#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <string_view>

#include "cycles/level_drilling.h"
#include "diag/codes.h"
#include "emit/number.h"
#include "machine/interpreter.h"
#include "machine/settings.h"
#include "motion/geometry.h"

namespace gcx::machine {

bool Interpreter::levelCycleBlock(const ir::Block& block, const ir::Word& code,
                                  const GCodeSpec& spec) {
  ir::Block before = block;
  std::erase_if(before.words, [&](const ir::Word& w) { return w.order >= code.order; });
  if (!before.words.empty() && !executeBlock(before)) return false;
  const auto cycle = static_cast<cycles::LevelCycle>(spec.arg); // the profile's binding
  if (levelCycle_ != cycle) levelWords_.clear();
  if (cycles::isOneBlock(cycle)) levelWords_.clear(); // one block each (§8 T26, T27)
  levelRapidFlag_ = false;
  levelCycle_ = cycle;
  levelCode_ = "G" + emit::formatNumber(code.number);
  if (spec.group > 0 && spec.group < static_cast<int>(modalCodes_.size()))
    modalCodes_[spec.group] = spec.code10;
  for (const ir::Word& w : block.words) {
    if (w.order <= code.order) continue;
    if (w.is('G') && w.number == 0 && cycles::isLevelTurning(cycle)) { // their rapid flag
      levelRapidFlag_ = true;
      continue;
    }
    if (w.address.size() != 1 || w.is('G'))
      return fail(diag::code::ForbiddenAddress, w.range,
                  fmt::format("{} is no parameter of {}", w.address, levelCode_));
    levelWords_[w.address[0]] = w.number;
  }
  if (cycles::takesProfile(cycle)) { // runs at `endcont`, after its profile blocks
    pendingProfile_ = PendingProfile{code.range, from_, {}};
    return true;
  }
  return levelHole(code.range);
}

bool Interpreter::levelHole(const SourceRange& code) {
  if (cycles::isLevelTurning(*levelCycle_)) return levelTurning(code);
  const motion::PlaneAxes ax = motion::axesOf(state_.plane);
  cycles::LevelDrillRequest req;
  req.cycle = *levelCycle_;
  req.code = levelCode_;
  req.axis = ax.normal;
  req.firstAxis = ax.first;
  req.secondAxis = ax.second;
  req.position = program_;
  req.incremental = state_.incremental;
  req.words = levelWords_;
  req.feed = state_.feed;
  req.spindleDirection = state_.spindleDirection;
  req.dwellSecondsPerUnit = profile_.machine.dwell.secondsPerUnit;
  if (auto f = levelWords_.find('F'); f != levelWords_.end()) state_.feed = f->second;
  const auto ops = cycles::expandLevelHole(req);
  if (const std::string* why = std::get_if<std::string>(&ops))
    return fail(diag::code::MissingData, code, *why);
  from_.chain.push_back({code.begin, levelCode_});
  const bool ok = runCycleOps(std::get<std::vector<cycles::CycleOp>>(ops),
                              std::numeric_limits<std::size_t>::max(), BlockWords{}, ax.normal);
  from_.chain.pop_back();
  return ok && !stopped_;
}

std::optional<bool> Interpreter::levelCycleRepeat(const ir::Block& block) {
  if (!levelCycle_ || cycles::isLevelTurning(*levelCycle_) || repeatingLevelCycle_)
    return std::nullopt;
  // one bit per drilling cycle, in the order of cycles::LevelCycle
  const auto modal = static_cast<unsigned>(setting(profile_, setup_, Setting::ModalLevelCycles));
  if (!(modal & (1u << static_cast<unsigned>(*levelCycle_)))) return std::nullopt;
  // fms3000.md §5.1: only a block with an axis word repeats the cycle (§10 leaves the others open)
  const bool axisWord = std::any_of(block.words.begin(), block.words.end(), [](const ir::Word& w) {
    return w.address.size() == 1 &&
           std::string_view("XYZUVWABC").find(w.address[0]) != std::string_view::npos;
  });
  if (!axisWord) return std::nullopt;
  repeatingLevelCycle_ = true;
  const bool ok = executeBlock(block);
  repeatingLevelCycle_ = false;
  if (!ok || stopped_) return false;
  if (!levelCycle_) return true; // the block cancelled the cycle (G80)
  return levelHole(block.range);
}

} // namespace gcx::machine
