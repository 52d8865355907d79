// gcx equiv A B: whether two programs move the tool the same (docs/equivalence.md).
// Exit 0 equivalent, 1 different, 2 a program could not be read or run.
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli/commands.h"
#include "cli/equiv_program.h"
#include "cli/execute.h"
#include "cli/session.h"
#include "equiv/equiv.h"
#include "equiv/html_page.h"
#include "equiv/report.h"
#include "report/equiv_html.h"

namespace gcx::cli {

int runEquiv(const std::string& a, const std::string& b, const EquivCommandOptions& opt) {
  equiv::ProgramInput ia{a, opt.setup, equiv::ProgramInput::Reader::Auto};
  // `--setup-b none`: B runs without a setup (gcx's canonical output has its offsets baked in)
  const std::string setupB =
      opt.setupB == "none" ? std::string() : (opt.setupB.empty() ? opt.setup : opt.setupB);
  equiv::ProgramInput ib{b, setupB, equiv::ProgramInput::Reader::Auto};
  equiv::EquivOptions o;
  o.gcxProgram = gcxProgramMaker(opt.common);
  o.walk.tolerance = opt.tolerance;
  o.walk.strictRapids = opt.strictRapids;
  o.rs274 = opt.rs274;
  // --report: each side's path recorded on its own thread; the page replaces the file only
  // when complete
  std::optional<AtomicOutput> page;
  report::PathRecorder pathA, pathB;
  if (!opt.report.empty()) {
    page.emplace(opt.report);
    if (!page->ok()) {
      reportUsage("cannot write " + opt.report);
      return UsageError;
    }
    o.tapA = &pathA;
    o.tapB = &pathB;
  }
  const equiv::EquivOutcome out = equiv::checkEquivalence(ia, ib, o);
  if (!out.a || !out.b) return UsageError;
  // diagnostics in a stable order: A's, then B's
  for (const equiv::ProgramSide* side : {out.a.get(), out.b.get()}) {
    if (opt.common.json) continue;
    for (const diag::Diagnostic& d : side->diagnostics())
      std::cerr << diag::renderText(d, side->sources());
  }
  if (!out.ok) {
    if (opt.common.json) {
      nlohmann::json j;
      j["error"] = true;
      j["diagnostics"] = nlohmann::json::array();
      for (const equiv::ProgramSide* side : {out.a.get(), out.b.get()})
        for (auto& d :
             nlohmann::json::parse(diag::renderJson(side->diagnostics(), side->sources())))
          j["diagnostics"].push_back(d);
      std::cout << j.dump() << '\n';
    }
    return UsageError;
  }
  if (opt.common.json)
    std::cout << equiv::toJson(out, opt.tolerance).dump() << '\n';
  else
    std::cout << equiv::renderText(out, opt.tolerance);
  if (page) {
    report::writeEquivHtml(page->stream(), equiv::htmlPage(out, opt.tolerance), pathA, pathB,
                           report::defaultView(pathA, pathB));
    if (!page->commit()) return UsageError;
  }
  return out.result.equivalent ? Ok : ProgramErrors;
}

} // namespace gcx::cli
