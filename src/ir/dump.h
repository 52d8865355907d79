// The IR as JSON: `gcx dump --ir`, and (without locations) the structural identity the round-trip
// and fast-path tests compare.
#pragma once
#include <nlohmann/json.hpp>

#include "ir/block.h"

namespace gcx::ir {

nlohmann::json toJson(const Expr& e, bool withLocations);
nlohmann::json toJson(const Block& b, bool withLocations);

} // namespace gcx::ir
