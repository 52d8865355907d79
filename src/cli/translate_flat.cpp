#include "cli/translate_flat.h"

#include <filesystem>
#include <fmt/format.h>
#include <map>
#include <streambuf>

#include "cli/execute.h"
#include "translate/structure_scan.h"

namespace gcx::cli {

namespace {

namespace fs = std::filesystem;

// Writes nothing: the run that only learns which holes the target's cycles take.
class NullBuffer : public std::streambuf {
protected:
  int_type overflow(int_type c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

// Runs `input` into the target's writer on `out`; 0 or the exit code after reporting why not.
int run(const std::string& input, const TranslateTarget& target, const TranslateOptions& opt,
        std::ostream* out, const std::string& note, bool keepCycles,
        std::vector<emit::StructureNote>* met, SourceManager** sources, Session& s) {
  machine::Setup setup;
  if (int rc = openWithSetup(s, input, opt.setup, setup)) return rc;
  *sources = &s.sources();
  NullBuffer nothing;
  std::ostream discard(&nothing);
  PrintOutput print(opt.common, true); // DPRNT never mixes with the program written
  if (out && !print.ok()) return UsageError;
  std::ostream& written = out ? *out : discard;
  emit::MotionWriterOptions wo;
  wo.programName = fs::path(input).stem().string();
  wo.notes = {"translated from " + fs::path(input).filename().string() + " (" + s.dialect().name +
                  ") by gcx",
              note};
  wo.source = &s.dialect().profile();
  wo.keepCycles = keepCycles;
  wo.structures = met;
  std::unique_ptr<emit::MotionWriter> writer = target.motionWriter(written, wo, s.diags());
  const bool ok =
      executeProgram(s, opt.common, setup, *writer, out ? print.stream() : discard) && writer->ok();
  if (out) s.flushDiagnostics();
  if (!ok) return ProgramErrors;
  return !out || print.finish() ? Ok : UsageError;
}

// "A.nct:2, 3, 9": the blocks, the file named once per run of the same file
std::string places(const std::vector<SourceLoc>& at, SourceManager& sources) {
  constexpr std::size_t kShown = 6;
  std::string out;
  FileId file = static_cast<FileId>(-1);
  for (std::size_t i = 0; i < at.size() && i < kShown; ++i) {
    if (i > 0) out += ", ";
    if (at[i].file != file) out += fs::path(sources.name(at[i].file)).filename().string() + ":";
    file = at[i].file;
    out += std::to_string(at[i].line);
  }
  if (at.size() > kShown) out += fmt::format(" and {} more", at.size() - kShown);
  return out;
}

std::string joined(const std::vector<std::string>& parts, const char* separator) {
  std::string out;
  for (const std::string& p : parts)
    out += (out.empty() ? "" : separator) + p;
  return out;
}

bool sameLine(const SourceLoc& a, const SourceLoc& b) {
  return a.file == b.file && a.line == b.line;
}

} // namespace

FlatAttempt planFlatMotion(const std::string& input, const TranslateTarget& target,
                           const TranslateOptions& opt, bool keepCycles,
                           const std::string& refusal) {
  FlatAttempt plan;
  const std::string frame =
      "machine frame, offsets and tool lengths in the coordinates, run without a setup";
  Session scan(opt.common);
  if (!scan.open(input)) return plan; // the writing run reports it
  std::vector<ir::Block> blocks;
  for (ir::Block b; scan.source().next(b); b = ir::Block{})
    blocks.push_back(std::move(b));
  std::map<xlate::Structure, std::vector<SourceLoc>> found;
  for (const xlate::StructureAt& s : xlate::scanStructures(blocks, scan.dialect().profile()))
    found[s.kind].push_back(s.at);
  const std::vector<SourceLoc> cycles = found[xlate::Structure::Cycle];
  plan.keepCycles = keepCycles && !cycles.empty();

  std::vector<emit::StructureNote> met;
  SourceManager* sources = &scan.sources();
  Session dry(opt.common);
  if (plan.keepCycles && run(input, target, opt, nullptr, {}, true, &met, &sources, dry) != Ok)
    plan.keepCycles = false; // the writing run reports the error
  if (!plan.keepCycles) met.clear();

  std::vector<std::string> kept, runOut;
  std::map<std::string, std::vector<SourceLoc>> keptByKind;
  std::vector<std::string> keptOrder;
  for (const emit::StructureNote& m : met) {
    if (!m.why.empty()) continue;
    if (!keptByKind.count(m.what)) keptOrder.push_back(m.what);
    auto& lines = keptByKind[m.what];
    if (lines.empty() || !sameLine(lines.back(), m.at)) lines.push_back(m.at);
  }
  for (const std::string& what : keptOrder)
    kept.push_back(fmt::format("{} ({})", what, places(keptByKind[what], *sources)));
  // the holes the target could not write, one entry per kind and reason
  std::vector<std::pair<std::string, std::string>> refusedOrder;
  std::map<std::pair<std::string, std::string>, std::vector<SourceLoc>> refused;
  for (const emit::StructureNote& m : met) {
    if (m.why.empty()) continue;
    const std::pair<std::string, std::string> key{m.what, m.why};
    if (!refused.count(key)) refusedOrder.push_back(key);
    auto& lines = refused[key];
    if (lines.empty() || !sameLine(lines.back(), m.at)) lines.push_back(m.at);
  }
  for (const auto& key : refusedOrder)
    runOut.push_back(fmt::format("the {} cycle at {}: {}", key.first,
                                 places(refused[key], *sources), key.second));
  // cycle blocks no hole came from (the runs may number the files apart: by name)
  std::vector<SourceLoc> other;
  for (std::size_t i = 0; i < cycles.size(); ++i) {
    const std::uint32_t from = cycles[i].line;
    const std::uint32_t to = i + 1 < cycles.size() ? cycles[i + 1].line : UINT32_MAX;
    const std::string file = scan.sources().name(cycles[i].file);
    bool covered = false;
    for (const emit::StructureNote& m : met)
      covered =
          covered || (m.at.line >= from && m.at.line < to && sources->name(m.at.file) == file);
    if (!covered) other.push_back(cycles[i]);
  }
  if (!other.empty())
    runOut.push_back(fmt::format(
        "cycles ({}){}", places(other, scan.sources()),
        !refusal.empty()
            ? ": the program with its cycles kept did not move the tool like the source" + refusal
        : !keepCycles ? " (--expand cycles)"
                      : ": no single drilled hole that the target's cycles take"));
  for (xlate::Structure k :
       {xlate::Structure::Subprogram, xlate::Structure::Loop, xlate::Structure::Variable})
    if (!found[k].empty())
      runOut.push_back(
          fmt::format("{} ({})", xlate::structureName(k), places(found[k], scan.sources())));
  std::vector<std::string> parts;
  if (!kept.empty())
    parts.push_back(fmt::format("kept as {} cycles: {}", target.name, joined(kept, ", ")));
  if (!runOut.empty()) parts.push_back("run out into motion: " + joined(runOut, ", "));
  parts.push_back(frame);
  plan.note = joined(parts, "; ");
  return plan;
}

int writeFlatMotion(const std::string& input, const TranslateTarget& target,
                    const TranslateOptions& opt, const std::string& output,
                    const FlatAttempt& attempt) {
  Session s(opt.common);
  // the target's program in the target's encoding (WL4: KOI8-R), as its proof reads it back
  AtomicOutput out(output, target.dialect ? target.dialect->textEncoding() : front::Encoding::Utf8);
  if (!out.ok()) return UsageError;
  SourceManager* sources = nullptr;
  if (const int rc = run(input, target, opt, &out.stream(), attempt.note, attempt.keepCycles,
                         nullptr, &sources, s))
    return rc;
  return out.commit() ? Ok : UsageError;
}

} // namespace gcx::cli
