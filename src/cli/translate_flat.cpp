#include "cli/translate_flat.h"

#include <filesystem>

#include "cli/execute.h"

namespace gcx::cli {

int writeFlatMotion(const std::string& input, const TranslateTarget& target,
                    const TranslateOptions& opt, const std::string& output) {
  Session s(opt.common);
  machine::Setup setup;
  if (int rc = openWithSetup(s, input, opt.setup, setup)) return rc;
  AtomicOutput out(output);
  PrintOutput print(opt.common, true); // DPRNT never mixes with the program written
  if (!out.ok() || !print.ok()) return UsageError;
  emit::MotionWriterOptions wo;
  wo.programName = std::filesystem::path(input).stem().string();
  wo.notes = {"translated from " + std::filesystem::path(input).filename().string() + " (" +
                  s.dialect().name + ") by gcx",
              target.note};
  wo.source = &s.dialect().profile();
  std::unique_ptr<emit::MotionWriter> writer = target.motionWriter(out.stream(), wo, s.diags());
  const bool ok = executeProgram(s, opt.common, setup, *writer, print.stream()) && writer->ok();
  s.flushDiagnostics();
  if (!ok) return ProgramErrors;
  return print.finish() && out.commit() ? Ok : UsageError;
}

} // namespace gcx::cli
