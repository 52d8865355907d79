// The interpreter's side of FMS-3000 G164/G165 (fms3000.md §5.3.1, 001:3245-3389): the blocks
// after the cycle block up to `endcont` are its approach block and profile, kept unexecuted and
// checked; at `endcont` they are traced on a scratch copy of the engine (as the contour cycles
// do, machine/turning_cycles.cpp) and the cycle runs from И.Т. with them.
#include <fmt/format.h>

#include <algorithm>

#include "cycles/level_turning.h"
#include "diag/codes.h"
#include "emit/number.h"
#include "machine/code_names.h"
#include "machine/interpreter.h"

namespace gcx::machine {

namespace {

// What a profile block may hold is the dialect's (MachineRules::profileBlock, 001:3287-3291).
bool allowedInProfile(const Profile& profile, const ir::Word& w, bool approach) {
  const ProfileBlockWords& rules = profile.machine.profileBlock;
  auto among = [](const std::vector<GAction>& codes, GAction a) {
    return std::find(codes.begin(), codes.end(), a) != codes.end();
  };
  if (w.is('G')) {
    const GCodeSpec* g = profile.gcode(w.number);
    return g &&
           (among(rules.codes, g->action) || (approach && among(rules.approachCodes, g->action)));
  }
  return w.address.size() == 1 && rules.letters.find(w.address[0]) != std::string::npos;
}

} // namespace

bool Interpreter::profileBlock(const ir::Block& block, const motion::Provenance& from) {
  if (block.kind == ir::BlockKind::ContourEnd) return profileCycle();
  if (!block.stmts.empty())
    return fail(diag::code::FmsProfile, block.stmts.front().range,
                "a statement inside the profile of G164/G165 (001:3287-3291)");
  const bool approach = pendingProfile_->blocks.empty();
  for (const ir::Word& w : block.words)
    if (!allowedInProfile(profile_, w, approach))
      return fail(diag::code::FmsProfile, w.range,
                  fmt::format("{} is not allowed in the profile of {}: only {}",
                              w.is('G') ? "G" + emit::formatNumber(w.number) : w.address,
                              levelCode_, profile_.machine.profileBlock.list));
  if (block.kind == ir::BlockKind::Normal && !block.words.empty())
    pendingProfile_->blocks.push_back({block, from});
  return true;
}

bool Interpreter::profileCycle() {
  const PendingProfile pending = std::move(*pendingProfile_);
  pendingProfile_.reset();
  if (state_.plane != motion::Plane::ZX)
    return fail(diag::code::FmsCycleParameters, pending.code,
                fmt::format("{} turns in the lathe plane: {} first (fms3000.md §5.3)", levelCode_,
                            codeName(profile_, GAction::PlaneZX)));
  if (pending.blocks.empty())
    return fail(diag::code::FmsProfile, pending.code,
                fmt::format("{} needs an approach block and a profile before endcont "
                            "(001:3255-3259)",
                            levelCode_));
  // the cycle's F is the profile's feed unless a profile block sets its own (001:3283)
  if (auto f = levelWords_.find('F'); f != levelWords_.end()) state_.feed = f->second;
  std::vector<cycles::ContourSegment> moves;
  if (!traceContour(pending.blocks, moves)) return false;
  if (moves.empty())
    return fail(diag::code::FmsProfile, pending.code,
                fmt::format("the profile of {} does not move", levelCode_));
  moves.front().modeProgrammed = true; // the approach may keep the modal G0/G1
  const auto profile =
      cycles::makeProfile(moves, motion::Plane::ZX, pending.blocks.front().block.range, diags_);
  if (!profile) return false;
  if (const auto fault = cycles::checkRoughingProfile(*levelCycle_, levelCode_, *profile))
    return fail(diag::code::FmsProfile, fault->where, fault->why);
  from_ = pending.from;
  return levelTurning(pending.code, &*profile);
}

} // namespace gcx::machine
