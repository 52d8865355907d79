// gcx: transpiler and toolchain between CNC G-code dialects.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fmt/format.h>
#include <iostream>

#include "cli/block_pipeline.h"
#include "cli/commands.h"
#include "cli/translate_target.h"
#include "dialect/dialect.h"

int main(int argc, char** argv) {
  using namespace gcx::cli;
  CLI::App app{"gcx: parse, check, translate and execute CNC G-code dialects (NCT, ...)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "gcx 0.1.0");

  CommonOptions common;
  common.jobs = gcx::cli::defaultJobs();
  // a whole number of 1 or more: no sign, no fraction (CLI11 would wrap -1 around)
  const CLI::Validator atLeastOne(
      [](std::string& v) -> std::string {
        const bool digits = !v.empty() && v.find_first_not_of("0123456789") == std::string::npos;
        if (!digits || v.find_first_not_of('0') == std::string::npos)
          return "must be a whole number of 1 or more, not '" + v + "'";
        return "";
      },
      "N>=1");
  auto addCommon = [&](CLI::App* cmd) {
    cmd->add_option("--dialect", common.dialect,
                    "dialect of the input (default: from the extension)")
        ->check(CLI::IsMember(gcx::dialectNames()));
    cmd->add_option("--encoding", common.encoding,
                    "encoding of the program files (default: the dialect's)")
        ->check(CLI::IsMember(gcx::front::encodingNames()));
    cmd->add_flag("--json", common.json, "diagnostics as JSON");
    cmd->add_option("--max-errors", common.maxErrors, "stop after this many errors (1 or more)")
        ->check(atLeastOne);
  };
  auto addExecution = [&](CLI::App* cmd) {
    cmd->add_option("--lib", common.libraryDirs, "folders searched for M98/G65 programs");
    cmd->add_option("--max-jumps", common.maxJumps,
                    "backward jumps and L repeats of calls before a runaway-loop error")
        ->check(atLeastOne);
    cmd->add_option("--max-blocks", common.maxBlocks, "blocks executed before an error")
        ->check(atLeastOne);
    cmd->add_option("--max-moves", common.maxMoves,
                    "moves (rapids, feeds, arc turns) before an error")
        ->check(atLeastOne);
    cmd->add_option("--max-output", common.maxOutput,
                    "bytes written (all outputs together) before an error; 100M, 2G ... (default: "
                    "256M, or 32 bytes per byte of the program when more)")
        ->check(atLeastOne)
        ->transform(CLI::AsSizeValue(false));
    cmd->add_option("--max-depth", common.maxDepth, "nested subprogram and macro calls")
        ->check(CLI::Range(1, 1000));
    cmd->add_option("--print", common.printFile, "file for DPRNT/BPRNT output");
    cmd->add_option("--jobs", common.jobs,
                    "threads for a program without macros: 2 reads and checks ahead of the "
                    "interpreter, 1 runs both in one (default: 2 on a machine with 2+ cores)")
        ->check(CLI::Range(1, 2));
    cmd->add_option_function<std::string>(
           "--vacant-order", [&](const std::string& v) { common.fanucVacantOrder = v == "fanuc"; },
           "how a vacant variable compares in GT/GE/LT/LE: nct (the manual, default) or fanuc")
        ->check(CLI::IsMember({"nct", "fanuc"}));
  };

  std::vector<std::string> checkFiles;
  CLI::App* check = app.add_subcommand("check", "syntax and static checks");
  check->add_option("FILE", checkFiles, "program files")->required();
  addCommon(check);
  check
      ->add_option("--jobs", common.jobs,
                   "threads: 2 reads the two halves of a large file at once, 1 reads it in one "
                   "(default: 2 on a machine with 2+ cores)")
      ->check(CLI::Range(1, 2));

  std::string fmtFile, fmtOut;
  CLI::App* fmt = app.add_subcommand("fmt", "print a program back as normalised text");
  fmt->add_option("FILE", fmtFile, "program file")->required();
  fmt->add_option("-o,--output", fmtOut, "output file (default: standard output)");
  addCommon(fmt);

  std::string dumpFile;
  bool dumpIr = false;
  CLI::App* dump = app.add_subcommand("dump", "print internal representations");
  dump->add_option("FILE", dumpFile, "program file")->required();
  dump->add_flag("--ir", dumpIr, "the IR, one JSON object per block")->required();
  addCommon(dump);

  ExpandOptions expandOpt;
  expandOpt.expand.clear(); // flatten what the target cannot keep, unless --expand says
  std::string expandFile;
  CLI::App* expand = app.add_subcommand("expand", "expand to flat motion in a target dialect");
  expand->add_option("FILE", expandFile, "program file")->required();
  expand
      ->add_option("--to", expandOpt.to,
                   "target: canonical (RS274/NGC that LinuxCNC runs) or a dialect (" +
                       fmt::format("{}", fmt::join(gcx::dialectNames(), ", ")) + ")")
      ->required();
  expand->add_option("-o,--output", expandOpt.output, "output file (default: standard output)");
  expand->add_option("--setup", expandOpt.setup, "machine setup (JSON): offsets, tools, ...");
  expand->add_flag("--provenance", expandOpt.provenance, "a source comment on each line");
  expand->add_option("--expand", expandOpt.expand,
                     "with --to <dialect>: macros,subprograms flattens macros, calls and repeats "
                     "(cycles stay cycles); default: what the target cannot keep (a dialect "
                     "without variables keeps its calls and repeats as written)");
  expand->add_option("--keep", expandOpt.keep,
                     "structure to keep where the target expresses it: cycles (--to nct; the "
                     "default there; --to canonical expands every cycle), comp (--to canonical: "
                     "G41.1/G42.1 for a controller that compensates itself)");
  addCommon(expand);
  addExecution(expand);

  RunOptions runOpt;
  std::string runFile;
  CLI::App* run = app.add_subcommand("run", "execute a program on gcx's interpreter");
  run->add_option("FILE", runFile, "program file")->required();
  run->add_option("--setup", runOpt.setup, "machine setup (JSON): offsets, tools, ...");
  run->add_option("--trace", runOpt.trace, "write the motion trace (JSON lines) to this file");
  run->add_flag("--stats", runOpt.stats, "print path length, time and bounds");
  run->add_option(
         "--frame", runOpt.frame,
         "frame of the trace: machine (default), work (relative to the work origin in force "
         "at each move) or program (the work frame taken back through rotation, scaling "
         "and mirror, in the program's units); --stats always measures the machine's "
         "path in mm")
      ->check(CLI::IsMember({"machine", "work", "program"}));
  addCommon(run);
  addExecution(run);

  PlotOptions plotOpt;
  std::string plotFile;
  CLI::App* plot = app.add_subcommand("plot", "draw the tool path as SVG");
  plot->add_option("FILE", plotFile, "program file")->required();
  plot->add_option("-o,--output", plotOpt.output, "SVG file")->required();
  plot->add_option("--setup", plotOpt.setup, "machine setup (JSON): offsets, tools, ...");
  plot->add_option("--view", plotOpt.view,
                   "xy, xz (lathe convention: Z right, X up, X as a radius), yz or iso")
      ->check(CLI::IsMember({"xy", "xz", "yz", "iso"}));
  plot->add_option("--frame", plotOpt.frame,
                   "work (default): coordinates relative to the work origin in force at each "
                   "move (work offset, G92/G52 shifts, tool length and turning offsets); program: "
                   "the work frame taken back through rotation, scaling and mirror, in the "
                   "program's units; machine: the machine frame, with the program's starting "
                   "work zero marked")
      ->check(CLI::IsMember({"work", "program", "machine"}));
  addCommon(plot);
  addExecution(plot);

  EquivCommandOptions equivOpt;
  std::string equivA, equivB;
  CLI::App* equiv = app.add_subcommand("equiv", "whether two programs move the tool the same");
  equiv->add_option("A", equivA, "first program (any dialect gcx reads, or RS274/NGC)")->required();
  equiv->add_option("B", equivB, "second program")->required();
  equiv->add_option("--setup", equivOpt.setup, "machine setup (JSON) of both programs");
  equiv->add_option("--setup-b", equivOpt.setupB, "B's own machine setup (JSON), or none");
  equiv->add_option("--tol", equivOpt.tolerance, "how far the paths may be apart (mm)")
      ->check(CLI::PositiveNumber);
  equiv->add_option("--report", equivOpt.report,
                    "also write an HTML page: both paths overlaid, the divergence marked, the "
                    "source around it on both sides");
  equiv->add_flag("--strict-rapids", equivOpt.strictRapids,
                  "compare the path of rapids, not only where each run of rapids ends");
  equiv->add_option("--rs274", equivOpt.rs274,
                    "LinuxCNC's rs274 for .ngc programs (default: PATH)");
  addCommon(equiv);
  addExecution(equiv);

  TranslateOptions translateOpt;
  std::string translateInput;
  CLI::App* translate = app.add_subcommand(
      "translate", "write a program for another target, proven to move the tool the same");
  translate->add_option("IN", translateInput, "program file, or a folder of programs")->required();
  translate
      ->add_option("--to", translateOpt.to,
                   "target: " + gcx::cli::translateTargetNames() +
                       " (canonical and ngc: RS274/NGC that LinuxCNC runs)")
      ->required();
  translate
      ->add_option("--from", common.dialect, "dialect of the input (default: from the extension)")
      ->check(CLI::IsMember(gcx::dialectNames()));
  translate->add_option("-o,--output", translateOpt.output,
                        "output file (default: standard output), or the folder of a batch");
  translate->add_option("--setup", translateOpt.setup,
                        "machine setup (JSON); in a batch, a program's NAME.setup.json wins");
  translate->add_flag("--verify,!--no-verify", translateOpt.verify,
                      "prove the result moves the tool like the source before it is written "
                      "(gcx equiv; the default), or write without the proof");
  translate
      ->add_option("--expand", translateOpt.expand,
                   "what the translation may not keep: cycles,subprograms,loops,variables or "
                   "all (flat motion)")
      ->check([](const std::string& list) {
        std::string why;
        return gcx::cli::parseExpand(list, why) ? std::string() : why;
      });
  translate->add_flag("--write-offsets", translateOpt.writeOffsets,
                      "ngc: set the setup's work offsets by G10 L2 at the start of the program");
  translate->add_option("--tol", translateOpt.tolerance, "how far the paths may be apart (mm)")
      ->check(CLI::PositiveNumber);
  translate->add_option("--rs274", translateOpt.rs274,
                        "LinuxCNC's rs274 that reads the RS274/NGC result (default: PATH)");
  translate->add_option("--jobs", translateOpt.batchJobs, "translations at once in a batch")
      ->check(CLI::Range(1, 64));
  translate
      ->add_option("--encoding", common.encoding,
                   "encoding of the program files (default: the dialect's)")
      ->check(CLI::IsMember(gcx::front::encodingNames()));
  translate->add_option("--lib", common.libraryDirs, "folders searched for called programs");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return UsageError;
  }

  auto runCommand = [&]() -> int {
    if (check->parsed()) return runCheck(checkFiles, common);
    if (fmt->parsed()) return runFmt(fmtFile, fmtOut, common);
    if (dump->parsed()) return runDumpIr(dumpFile, common);
    if (expand->parsed()) {
      expandOpt.common = common;
      return runExpand(expandFile, expandOpt);
    }
    if (run->parsed()) {
      runOpt.common = common;
      return runRun(runFile, runOpt);
    }
    if (plot->parsed()) {
      plotOpt.common = common;
      return runPlot(plotFile, plotOpt);
    }
    if (translate->parsed()) {
      translateOpt.common = common;
      translateOpt.common.jobs = 1; // a batch runs translations side by side instead
      return runTranslate(translateInput, translateOpt);
    }
    if (equiv->parsed()) {
      equivOpt.common = common;
      return runEquiv(equivA, equivB, equivOpt);
    }
    return UsageError;
  };
  const int rc = runCommand();
  // standard output is checked like any output: a full device or closed pipe is exit 2
  std::cout.flush();
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::cerr << "gcx: error: standard output: cannot write: " << std::strerror(errno) << '\n';
    return rc == Ok ? UsageError : rc;
  }
  return rc;
}
