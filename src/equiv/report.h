// The equivalence report for people (text, clang-like locations with the source line and a
// caret) and for tools (one JSON object with the same content).
#pragma once
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "equiv/equiv.h"

namespace gcx::equiv {

/// "a.nct:12:1 (in O9010 from a.nct:40, in WHILE iteration 3 from a.nct:38)"
std::string provenanceText(const motion::Provenance& p, const SourceManager& sm);
/// The first line of the report: "equivalent: ..." or "first difference at ... vs ...: why".
std::string headline(const EquivOutcome& o, double tolerance);
std::string renderText(const EquivOutcome& o, double tolerance);
nlohmann::json toJson(const EquivOutcome& o, double tolerance);

} // namespace gcx::equiv
