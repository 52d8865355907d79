// gcx translate IN --to T: a program written for another controller, proven to move the tool
// like the original before it is written (docs/translation.md). The output is staged beside its
// destination, checked with the equivalence engine (`gcx equiv`), and only then moved into
// place; a translation that does not hold leaves no file.
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

#include "cli/commands.h"
#include "cli/equiv_program.h"
#include "cli/translate_batch.h"
#include "cli/translate_flat.h"
#include "cli/translate_ngc.h"
#include "cli/translate_structured.h"
#include "cli/translate_target.h"
#include "diag/diagnostic.h"
#include "dialect/dialect.h"
#include "equiv/equiv.h"
#include "equiv/report.h"

namespace gcx::cli {

namespace fs = std::filesystem;

namespace {

// A name beside the destination (same file system: the final rename is atomic), or in the
// temporary folder when the result goes to standard output.
fs::path stagingPath(const std::string& output, const std::string& extension) {
  const std::string name = fmt::format(".gcx-translate-{}{}", getpid(), extension);
  if (output.empty()) return fs::temp_directory_path() / name;
  const fs::path out(output);
  return (out.has_parent_path() ? out.parent_path() : fs::path(".")) / name;
}

bool copyToStdout(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::cout << in.rdbuf();
  return static_cast<bool>(std::cout);
}

// Runs source and translation through the equivalence engine; prints why they differ on err.
bool verified(const std::string& source, const fs::path& result, bool resultReadsSetup,
              const TranslateOptions& opt, std::ostream& err = std::cerr) {
  equiv::ProgramInput a{source, opt.setup, equiv::ProgramInput::Reader::Auto};
  // canonical motion has the offsets of the setup written into it; a dialect's program (and
  // structured ngc) reads them from the same setup as its source
  equiv::ProgramInput b{result.string(), resultReadsSetup ? opt.setup : std::string(),
                        equiv::ProgramInput::Reader::Auto};
  equiv::EquivOptions o;
  o.gcxProgram = gcxProgramMaker(opt.common);
  // --from names the source's dialect; the result is read in the target's, by its extension
  CommonOptions target = opt.common;
  target.dialect.clear();
  target.encoding.clear();
  o.gcxProgramB = gcxProgramMaker(target);
  o.walk.tolerance = opt.tolerance;
  o.rs274 = opt.rs274;
  const equiv::EquivOutcome out = equiv::checkEquivalence(a, b, o);
  if (!out.a || !out.b) return false;
  for (const equiv::ProgramSide* side : {out.a.get(), out.b.get()})
    for (const diag::Diagnostic& d : side->diagnostics())
      err << diag::renderText(d, side->sources());
  if (!out.ok) return false;
  if (out.result.equivalent) return true;
  err << "gcx: error: the translation does not move the tool like " << source
      << "; nothing was written:\n"
      << equiv::renderText(out, opt.tolerance);
  return false;
}

// The note of a translation written, and that it was proven.
void reportWritten(const std::string& input, const std::string& note, const TranslateOptions& opt) {
  if (!note.empty()) std::cerr << "gcx: note: " << input << ": " << note << '\n';
  if (opt.verify)
    std::cerr << fmt::format("gcx: {} -> {}: verified, moves the tool like the source within {} "
                             "mm\n",
                             input, opt.output.empty() ? "standard output" : opt.output,
                             opt.tolerance);
}

struct StructuredOutcome {
  int rc = -1;        // the exit code when the structured translation decided it; -1: fall back
  std::string unkept; // why the structure was not kept, when the program has one
};

// The structured translation to another dialect (cli/translate_structured.h): staged in a folder
// beside the output, proven, then moved into place file by file.
StructuredOutcome translateStructured(const Dialect& source, const TranslateTarget& target,
                                      const std::string& input, const TranslateOptions& opt) {
  StructuredOutcome o;
  const fs::path out(opt.output);
  const fs::path folder = opt.output.empty()      ? fs::temp_directory_path()
                          : out.has_parent_path() ? out.parent_path()
                                                  : fs::path(".");
  const fs::path stage = folder / fmt::format(".gcx-translate-{}.d", getpid());
  struct DiscardFolder {
    fs::path path;
    ~DiscardFolder() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  } discard{stage};
  const std::string mainName = ".gcx-main" + target.extension;
  StructuredAttempt st = writeStructuredDialect(source, structuredTarget(*target.dialect), input,
                                                stage, mainName, opt);
  if (!st.tried) return o;
  if (st.written && opt.output.empty() && st.staged.size() > 1) {
    st.written = false;
    st.unkept = "its subprograms go to files of their own beside the output: give -o";
  }
  std::ostringstream proof;
  if (st.written && opt.verify && !verified(input, st.staged.front(), true, opt, proof)) {
    st.written = false;
    st.unkept = "the program with its structure kept did not move the tool like the source" +
                divergence(proof.str());
  }
  if (!st.written) {
    o.unkept = st.unkept;
    return o;
  }
  if (opt.output.empty()) {
    o.rc = copyToStdout(st.staged.front()) ? Ok : UsageError;
  } else {
    for (std::size_t i = 0; i < st.staged.size(); ++i) {
      const fs::path to = i == 0 ? out : folder / st.names[i];
      std::error_code ec;
      fs::rename(st.staged[i], to, ec);
      if (ec) {
        diag::reportUsage(fmt::format("cannot write {}: {}", to.string(), ec.message()));
        o.rc = UsageError;
        return o;
      }
    }
    o.rc = Ok;
  }
  std::string files;
  for (std::size_t i = 1; i < st.names.size(); ++i)
    files += (files.empty() ? "; subprograms written as " : ", ") + st.names[i];
  reportWritten(input, st.note + files, opt);
  return o;
}

} // namespace

int runTranslate(const std::string& input, const TranslateOptions& opt) {
  if (fs::is_directory(input)) return runTranslateBatch(input, opt);
  const Dialect* source =
      opt.common.dialect.empty() ? dialectForPath(input) : findDialect(opt.common.dialect);
  if (!source) {
    diag::reportUsage(
        fmt::format("{}: cannot tell the dialect from the file name; name it with --from", input));
    return UsageError;
  }
  std::string why;
  const std::optional<ExpandSet> expandSet = parseExpand(opt.expand, why);
  if (!expandSet) why = "--expand " + opt.expand + ": " + why;
  const std::optional<TranslateTarget> target =
      expandSet ? translateTarget(*source, opt.to, *expandSet, why) : std::nullopt;
  if (!target) {
    diag::reportUsage(why);
    return UsageError;
  }
  const fs::path staged = stagingPath(opt.output, target->extension);
  ExpandOptions expand;
  expand.common = opt.common;
  expand.common.dialect = source->name;
  expand.to = target->expandTo;
  expand.output = staged.string();
  expand.setup = opt.setup;
  struct Discard {
    fs::path path;
    ~Discard() {
      std::error_code ec;
      fs::remove(path, ec);
    }
  } discard{staged};
  std::string note = target->note;
  bool kept = false;
  if (target->name == "ngc" && !expandSet->any()) {
    // LinuxCNC's own structure where it means the same, proven like the flat motion
    const NgcStructure ngc = writeStructuredNgc(*source, input, staged.string(), opt);
    std::ostringstream proof;
    kept = ngc.written && (!opt.verify || verified(input, staged, true, opt, proof));
    note = ngcNote(ngc, kept, target->note, proof.str());
  }
  // another dialect: the program's structure in the target's own forms, proven; else the flat
  // motion below, with why in its note
  std::string structureNote;
  if (target->motionWriter && !expandSet->subprograms && !expandSet->loops &&
      !expandSet->variables) {
    const StructuredOutcome st = translateStructured(*source, *target, input, opt);
    if (st.rc >= 0) return st.rc;
    structureNote = st.unkept;
  }
  const auto withStructureNote = [&](FlatAttempt& a) {
    if (!structureNote.empty()) a.note = "structure not kept: " + structureNote + "; " + a.note;
  };
  if (target->motionWriter) {
    // cycles kept where the target has them, proven; else everything run out, proven
    FlatAttempt attempt = planFlatMotion(input, *target, opt, target->keepCycles);
    withStructureNote(attempt);
    if (const int rc = writeFlatMotion(input, *target, opt, staged.string(), attempt)) return rc;
    std::ostringstream proof;
    bool proven = !opt.verify || verified(input, staged, false, opt, proof);
    if (!proven && attempt.keepCycles) { // again with every cycle run out, the note says why
      attempt = planFlatMotion(input, *target, opt, false, divergence(proof.str()));
      withStructureNote(attempt);
      if (const int rc = writeFlatMotion(input, *target, opt, staged.string(), attempt)) return rc;
      proven = verified(input, staged, false, opt);
    } else if (!proven) {
      std::cerr << proof.str();
    }
    if (!proven) return ProgramErrors;
    note = attempt.note;
    kept = true; // written and proven: nothing below runs
  }
  if (!kept) {
    if (const int rc = target->printSource ? runFmt(input, expand.output, expand.common)
                                           : runExpand(input, expand))
      return rc;
    if (target->name == "ngc" && !prependComment(staged.string(), note)) return UsageError;
    // printed as written, the result calls the source's programs: beside it, else in --lib,
    // else where the source found them
    TranslateOptions proof = opt;
    if (target->printSource)
      proof.common.libraryDirs.push_back(fs::absolute(input).parent_path().string());
    if (opt.verify && !verified(input, staged, target->dialect != nullptr, proof))
      return ProgramErrors;
  }
  if (opt.output.empty()) {
    if (!copyToStdout(staged)) return UsageError;
  } else {
    std::error_code ec;
    fs::rename(staged, opt.output, ec);
    if (ec) {
      diag::reportUsage(fmt::format("cannot write {}: {}", opt.output, ec.message()));
      return UsageError;
    }
  }
  reportWritten(input, note, opt);
  return Ok;
}

} // namespace gcx::cli
