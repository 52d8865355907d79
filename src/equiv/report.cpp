#include "equiv/report.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace gcx::equiv {

namespace {

std::string locText(const SourceLoc& at, const SourceManager& sm) {
  std::string s = sm.name(at.file);
  if (at.line != 0) s += fmt::format(":{}", at.line);
  if (at.col != 0) s += fmt::format(":{}", at.col);
  return s;
}

std::string sourceLine(const SourceLoc& at, const SourceManager& sm) {
  if (at.line == 0) return {};
  std::string text = sm.lineText(at, 200);
  while (!text.empty() && (text.back() == '\r' || text.back() == ' '))
    text.pop_back();
  return text;
}

double round6(double v) {
  const double r = std::round(v * 1e6) / 1e6;
  return r == 0 ? 0.0 : r; // no -0
}

std::string sideLine(const char* label, const SideAt& s, const SourceManager& sm) {
  if (!s.present) return fmt::format("  {}: (nothing: the program had not moved yet)\n", label);
  const SourceLoc& at = s.event.from.at;
  std::string out =
      fmt::format("{}: {}: {}\n", provenanceText(s.event.from, sm), label, s.description);
  const std::string text = sourceLine(at, sm);
  if (!text.empty()) {
    out += "  " + text + "\n";
    if (at.col > 0 && at.col <= text.size() + 1) out += "  " + std::string(at.col - 1, ' ') + "^\n";
  }
  return out;
}

std::string summaryLine(const char* label, const ProgramSide& p, const SideSummary& s) {
  return fmt::format("  {} {}: {} segments, {} events, path {:.3f} mm ({:.3f} mm feed), {:.1f} s\n",
                     label, p.name(), s.segments, s.events, s.stats.totalLength(),
                     s.stats.feedLength, s.stats.totalSeconds());
}

nlohmann::json sideJson(const SideAt& s, const SourceManager& sm) {
  if (!s.present) return nullptr;
  const SourceLoc& at = s.event.from.at;
  nlohmann::json chain = nlohmann::json::array();
  for (const motion::Frame& f : s.event.from.chain)
    chain.push_back({{"what", f.what}, {"file", sm.name(f.call.file)}, {"line", f.call.line}});
  return {{"file", sm.name(at.file)},
          {"line", at.line},
          {"col", at.col},
          {"chain", chain},
          {"provenance", provenanceText(s.event.from, sm)},
          {"source", sourceLine(at, sm)},
          {"event", s.description}};
}

nlohmann::json summaryJson(const ProgramSide& p, const SideSummary& s) {
  return {{"file", p.name()},
          {"segments", s.segments},
          {"events", s.events},
          {"stats", motion::toJson(s.stats)}};
}

} // namespace

std::string provenanceText(const motion::Provenance& p, const SourceManager& sm) {
  std::string s = locText(p.at, sm);
  bool first = true;
  for (auto it = p.chain.rbegin(); it != p.chain.rend(); ++it) {
    s += fmt::format("{}in {} from {}", first ? " (" : ", ", it->what, locText(it->call, sm));
    first = false;
  }
  if (!first) s += ")";
  return s;
}

std::string headline(const EquivOutcome& o, double tolerance) {
  const EquivResult& r = o.result;
  if (r.equivalent)
    return fmt::format("equivalent: {} and {} move the tool the same (tolerance {} mm, largest "
                       "deviation {:.6f} mm)",
                       o.a->name(), o.b->name(), tolerance, r.maxDeviation);
  const Divergence& d = *r.divergence;
  auto where = [](const SideAt& s, const ProgramSide& p) {
    return s.present ? provenanceText(s.event.from, p.sources()) : p.name() + " (start)";
  };
  return fmt::format("first difference at {} vs {}: {}", where(d.a, *o.a), where(d.b, *o.b),
                     d.summary);
}

std::string renderText(const EquivOutcome& o, double tolerance) {
  const EquivResult& r = o.result;
  std::string out = headline(o, tolerance) + "\n";
  if (!r.equivalent) {
    const Divergence& d = *r.divergence;
    out += sideLine("A", d.a, o.a->sources());
    out += sideLine("B", d.b, o.b->sources());
    if (d.stateSetA.line != 0 || d.stateSetB.line != 0)
      out += fmt::format("  the state was set at {} (A) and {} (B)\n",
                         d.stateSetA.line ? locText(d.stateSetA, o.a->sources()) : "the start",
                         d.stateSetB.line ? locText(d.stateSetB, o.b->sources()) : "the start");
    out += fmt::format("  {} difference at ({:.4f}, {:.4f}, {:.4f}) in the machine frame; "
                       "largest deviation before it {:.6f} mm (tolerance {} mm)\n",
                       kindName(d.kind), round6(d.where.x()), round6(d.where.y()),
                       round6(d.where.z()), r.maxDeviation, tolerance);
    out += "  up to the difference:\n";
  }
  out += summaryLine("A", *o.a, r.a);
  out += summaryLine("B", *o.b, r.b);
  return out;
}

nlohmann::json toJson(const EquivOutcome& o, double tolerance) {
  const EquivResult& r = o.result;
  nlohmann::json j;
  j["equivalent"] = r.equivalent;
  j["tolerance_mm"] = tolerance;
  j["headline"] = headline(o, tolerance);
  if (r.divergence) {
    const Divergence& d = *r.divergence;
    j["divergence"] = {{"kind", kindName(d.kind)},
                       {"summary", d.summary},
                       {"amount", round6(d.amount)},
                       {"at", {round6(d.where.x()), round6(d.where.y()), round6(d.where.z())}},
                       {"a", sideJson(d.a, o.a->sources())},
                       {"b", sideJson(d.b, o.b->sources())}};
    auto setAt = [](const SourceLoc& at, const SourceManager& sm) -> nlohmann::json {
      if (at.line == 0) return nullptr;
      return {{"file", sm.name(at.file)}, {"line", at.line}, {"col", at.col}};
    };
    j["divergence"]["state_set_a"] = setAt(d.stateSetA, o.a->sources());
    j["divergence"]["state_set_b"] = setAt(d.stateSetB, o.b->sources());
  } else {
    j["divergence"] = nullptr;
  }
  j["max_deviation_mm"] = round6(r.maxDeviation);
  j["a"] = summaryJson(*o.a, r.a);
  j["b"] = summaryJson(*o.b, r.b);
  return j;
}

} // namespace gcx::equiv
