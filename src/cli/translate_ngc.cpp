#include "cli/translate_ngc.h"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "cli/translate_structured.h"
#include "dialects/ngc/printer.h"
#include "dialects/ngc/structured.h"
#include "dialects/ngc/structured_spelling.h"
#include "emit/number.h"
#include "oracle/setup.h"
#include "passes/macro/program_library.h"

namespace gcx::cli {

namespace {

namespace fs = std::filesystem;

// "G10 L2 P1 X.. Y.. Z..\n" for each work offset of the setup; false with why when the setup is
// not one rs274 takes.
bool setupOffsets(const std::string& setupPath, std::string& out, std::string& why) {
  std::ifstream in(setupPath, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  oracle::OracleSetup setup;
  if (!in || !oracle::parseSetupJson(text.str(), setup, why)) {
    why = setupPath + ": " + (why.empty() ? "cannot be read" : why);
    return false;
  }
  for (const oracle::OracleWorkOffset& w : setup.workOffsets) {
    if (w.rotationDeg != 0) {
      why = setupPath + ": a rotated work offset has no G10 L2 X Y Z form";
      return false;
    }
    out += fmt::format("G10 L2 P{} X{} Y{} Z{}\n", w.index, emit::formatNumber(w.offsetMm.x()),
                       emit::formatNumber(w.offsetMm.y()), emit::formatNumber(w.offsetMm.z()));
  }
  return true;
}

// FMS-3000 and WL4: the structured translation every dialect shares (cli/translate_structured.h)
// with LinuxCNC's spelling; a program without structure to keep is written flat.
NgcStructure writeNeutralNgc(const Dialect& source, const std::string& input,
                             const std::string& file, const TranslateOptions& opt) {
  NgcStructure result;
  const fs::path out(file);
  const fs::path stage = (out.has_parent_path() ? out.parent_path() : fs::path(".")) /
                         fmt::format(".gcx-ngc-{}.d", getpid());
  struct DiscardFolder {
    fs::path path;
    ~DiscardFolder() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  } discard{stage};
  const StructuredTarget target{&ngc::structuredSpelling(), &ngc::makeEmitter, "ngc", true,
                                front::Encoding::Utf8};
  StructuredAttempt st = writeStructuredDialect(source, target, input, stage, "main.ngc", opt);
  if (!st.written) {
    result.unkept = st.tried ? st.unkept : "the program has no structure to keep";
    return result;
  }
  std::error_code ec;
  fs::copy_file(st.staged.front(), out, fs::copy_options::overwrite_existing, ec);
  result.written = !ec;
  result.kept = std::move(st.kept);
  return result;
}

} // namespace

NgcStructure writeStructuredNgc(const Dialect& source, const std::string& input,
                                const std::string& file, const TranslateOptions& opt) {
  const CommonOptions& common = opt.common;
  NgcStructure result;
  const ngc::StructuredWriter writer = ngc::structuredWriter(source);
  if (!writer) return writeNeutralNgc(source, input, file, opt);
  SourceManager sources;
  diag::Engine diags(common.maxErrors);
  macro::ProgramLibrary library(source, sources, diags, common.libraryDirs);
  const macro::LoadedProgram* main = library.load(input);
  if (!main || diags.errorCount() > 0) return result;
  const ngc::FindProgram find = [&](const std::string& unit, const SourceRange& where) {
    const macro::LoadedProgram* p = library.byUnit(unit, *main, where);
    return p && diags.errorCount() == 0 ? &p->blocks : nullptr;
  };
  ngc::Structured structured;
  ngc::Unkept unkept;
  if (!writer(main->blocks, find, structured, unkept)) {
    const SourceLoc& at = unkept.where.begin;
    result.unkept = fmt::format("{}:{}: {}: {}", at.valid() ? sources.name(at.file) : input,
                                at.line, unkept.what, unkept.why);
    return result;
  }
  std::string offsets;
  if (opt.writeOffsets && !opt.setup.empty() && !setupOffsets(opt.setup, offsets, result.unkept))
    return result;
  if (!offsets.empty()) structured.kept.push_back("the setup's work offsets as G10 L2");
  // after the heading line
  const std::size_t body = structured.text.find('\n') + 1;
  std::ofstream out(file, std::ios::binary);
  out << structured.text.substr(0, body) << offsets << structured.text.substr(body);
  result.written = static_cast<bool>(out);
  result.kept = std::move(structured.kept);
  return result;
}

std::string ngcNote(const NgcStructure& ngc, bool kept, const std::string& flat,
                    const std::string& proof) {
  if (kept) {
    if (ngc.kept.empty()) return {};
    std::string list;
    for (const std::string& k : ngc.kept)
      list += (list.empty() ? "" : ", ") + k;
    return "kept as LinuxCNC's own: " + list;
  }
  if (!ngc.unkept.empty()) return flat + ": " + ngc.unkept;
  if (!ngc.written) return flat;
  return flat + ": the structured program did not move the tool like the source" +
         divergence(proof);
}

std::string divergence(const std::string& proof) {
  // the proof names the first divergence: "first difference at A:1:1 vs B:2:1: what"
  const std::string head = "first difference at ";
  if (const std::size_t at = proof.find(head); at != std::string::npos) {
    const std::string line =
        proof.substr(at + head.size(), proof.find('\n', at) - at - head.size());
    const std::size_t vs = line.find(" vs "), what = line.find(": ", vs);
    if (vs != std::string::npos && what != std::string::npos)
      return ": " + line.substr(what + 2) + " at " + line.substr(0, vs);
  }
  return {};
}

bool prependComment(const std::string& file, const std::string& note) {
  std::stringstream text;
  {
    std::ifstream in(file, std::ios::binary);
    text << in.rdbuf();
  }
  std::string comment;
  for (char c : note)
    if (c != '(' && c != ')') comment += c;
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << '(' << comment << ")\n" << text.str();
  return static_cast<bool>(out);
}

} // namespace gcx::cli
