// gcx run FILE: execute on the interpreter; optional motion trace and statistics.
#include <fmt/format.h>
#include <iostream>

#include "cli/commands.h"
#include "cli/execute.h"
#include "motion/stats.h"
#include "motion/trace_writer.h"

namespace gcx::cli {

int runRun(const std::string& file, const RunOptions& opt) {
  Session s(opt.common);
  machine::Setup setup;
  if (int rc = openWithSetup(s, file, opt.setup, setup)) return rc;
  std::optional<AtomicOutput> traceFile;
  std::optional<motion::TraceWriter> trace;
  if (!opt.trace.empty()) {
    traceFile.emplace(opt.trace);
    if (!traceFile->ok()) return UsageError;
    trace.emplace(traceFile->stream(), [&](FileId id) { return s.sources().name(id); });
  }
  motion::StatsOptions sopt;
  sopt.rapidRate = setup.rapidRate;
  motion::StatsCollector stats(sopt);
  PrintOutput print(opt.common, false);
  if (!print.ok()) return UsageError;
  // the trace in the frame asked for; the statistics always measure the machine's path in mm
  struct Discard : motion::Sink {
    void event(const motion::Event&) override {}
  } noTrace;
  const bool ok =
      executeProgram(s, opt.common, setup, trace ? static_cast<motion::Sink&>(*trace) : noTrace,
                     print.stream(), frameNamed(opt.frame), &stats);
  s.flushDiagnostics();
  if (!ok) return ProgramErrors;
  if (!print.finish() || (traceFile && !traceFile->commit())) return UsageError;
  const motion::Stats& st = stats.stats();
  if (opt.stats) {
    std::cout << fmt::format("moves: {} rapid, {} linear, {} arc\n", st.rapidMoves, st.feedMoves,
                             st.arcMoves)
              << fmt::format("path: {:.3f} mm rapid, {:.3f} mm feed ({:.3f} mm on arcs)\n",
                             st.rapidLength, st.feedLength, st.arcLength)
              << fmt::format("time: {:.1f} s ({:.1f} s rapid at {:g} mm/min, {:.1f} s feed, "
                             "{:.1f} s dwell)\n",
                             st.totalSeconds(), st.rapidSeconds, setup.rapidRate, st.feedSeconds,
                             st.dwellSeconds)
              << fmt::format("tool changes: {}, dwells: {}\n", st.toolChanges, st.dwells);
    if (!st.bounds.isEmpty())
      std::cout << fmt::format(
          "bounds: X {:.3f} .. {:.3f}, Y {:.3f} .. {:.3f}, Z {:.3f} .. {:.3f}\n",
          st.bounds.min().x(), st.bounds.max().x(), st.bounds.min().y(), st.bounds.max().y(),
          st.bounds.min().z(), st.bounds.max().z());
  } else if (!opt.common.json) {
    std::cout << fmt::format("{}: ran to the end, {} moves\n", file,
                             st.rapidMoves + st.feedMoves + st.arcMoves);
  }
  return Ok;
}

} // namespace gcx::cli
