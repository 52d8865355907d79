// How messages name G and M codes: by the dialect's own numbers, from its profile or from the
// word as written, so the machine never spells a dialect's code in a message.
#pragma once
#include <string>
#include <vector>

#include "dialect/profile.h"
#include "ir/block.h"

namespace gcx::machine {

/// A G word as written, by its value: "G10.9" (G010.90 too).
std::string gName(const ir::Word& w);
/// The dialect's first G code with this action ("G50"); "" when it has none.
std::string codeName(const Profile& profile, GAction action);
/// M codes as a list: "M3, M4 and M5".
std::string mCodeList(const std::vector<int>& codes);

} // namespace gcx::machine
