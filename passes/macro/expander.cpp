#include "passes/macro/expander.h"

#include <array>
#include <charconv>

#include <fmt/format.h>
#include <fstream>

#include "diag/codes.h"
#include "emit/number.h"

namespace gcx::macro {

namespace {

const ControlFlow& controlFlowOf(const machine::Interpreter& machine) {
  static const ControlFlow none;
  const ControlFlow* flow = machine.profile().controlFlow;
  return flow ? *flow : none;
}

} // namespace

Expander::Expander(ProgramLibrary& library, machine::Interpreter& machine, diag::Engine& diags,
                   Limits limits)
    : library_(library), machine_(machine), flow_(controlFlowOf(machine)),
      system_(flow_.systemVariables ? flow_.systemVariables(machine, diags) : nullptr),
      diags_(diags), limits_(limits), eval_(*this, diags) {
  for (const auto& [n, v] : machine_.setup().variables)
    if (n >= flow_.variables.commonFirst) commons_[n] = Value::of(v);
}

Expander::~Expander() = default;

ParameterLookup Expander::parameters() const {
  return
      [this](const std::string& key, double fallback) { return machine_.parameter(key, fallback); };
}

bool Expander::fail(const char* code, const SourceRange& where, std::string message) {
  diag::Diagnostic d{diag::Severity::Error, code, std::move(message), where, {}};
  const motion::Provenance p = provenance(ir::Block{});
  for (auto it = p.chain.rbegin(); it != p.chain.rend(); ++it)
    d.notes.push_back({SourceRange{it->call, 1}, "in " + it->what});
  diags_.report(std::move(d));
  return false;
}

motion::Provenance Expander::provenance(const ir::Block& b) const {
  motion::Provenance p;
  fillProvenance(b, p);
  return p;
}

void Expander::fillProvenance(const ir::Block& b, motion::Provenance& p) const {
  p.at = b.range.begin;
  std::size_t n = 0;
  auto next = [&]() -> motion::Frame& {
    if (n == p.chain.size()) p.chain.emplace_back();
    return p.chain[n++];
  };
  for (std::size_t i = 0; i < stack_.size(); ++i) {
    const Frame& f = stack_[i];
    if (i > 0) {
      motion::Frame& call = next();
      call.call = f.callSite;
      call.what = f.what;
    }
    for (const Loop& l : f.loops) {
      const ir::Block& head = f.program->blocks[l.head];
      motion::Frame& loop = next();
      loop.call = head.range.begin;
      // "loop DO1 iteration 3", for every block of every iteration: to_chars, not fmt's parser
      std::array<char, 24> digits;
      loop.what.assign("loop DO");
      loop.what.append(digits.data(),
                       std::to_chars(digits.begin(), digits.end(), head.stmts.front().loopId).ptr);
      loop.what.append(" iteration ");
      loop.what.append(digits.data(), std::to_chars(digits.begin(), digits.end(), l.iteration).ptr);
    }
  }
  p.chain.resize(n);
}

bool Expander::run(const LoadedProgram& main) {
  Frame f;
  f.program = &main;
  stack_.push_back(std::move(f));
  if (system_) system_->startMain(main.path);
  frames_.reset(static_cast<std::size_t>(flow_.variables.frameSize()));
  done_ = false;
  machine_.setContourSource(
      [this](std::int64_t ns, std::int64_t nf, auto& out) { return contour(ns, nf, out); });
  while (!done_)
    if (!step()) {
      // errors reported below the pass (evaluator, machine) get the call chain as notes too
      if (diag::Diagnostic* d = diags_.lastError(); d && d->notes.empty()) {
        const motion::Provenance p = provenance(ir::Block{});
        for (auto it = p.chain.rbegin(); it != p.chain.rend(); ++it)
          d->notes.push_back({SourceRange{it->call, 1}, "in " + it->what});
      }
      return false;
    }
  return !diags_.hasErrors();
}

bool Expander::endOfProgram(const Frame& f) {
  if (stack_.size() == 1) { // end of the main file without a program end (nct.md Q31)
    done_ = true;
    const std::vector<ir::Block>& blocks = f.program->blocks;
    return machine_.endOfFile(blocks.empty() ? SourceRange{} : blocks.back().range);
  }
  // a called program must end with the dialect's return code (its Return row)
  std::string code = "a return", spec;
  for (const Remap& r : flow_.remaps.rows)
    if (r.action == FlowAction::Return && r.code) {
      code = r.address + emit::formatNumber(*r.code);
      spec = fmt::format(" ({})", r.spec);
      break;
    }
  return fail(diag::code::MissingReturn, SourceRange{f.callSite, 1},
              fmt::format("{} ended without {}{}", f.what, code, spec));
}

bool Expander::step() {
  Frame& f = stack_.back();
  if (f.pc >= f.program->blocks.size()) return endOfProgram(f);
  const ir::Block& b = f.program->blocks[f.pc];
  if (++blocks_ > limits_.maxBlocks)
    return fail(diag::code::TooManyBlocks, b.range,
                fmt::format("more than {} blocks executed: is this an endless loop? (exceeded "
                            "--max-blocks {}; raise it with --max-blocks N)",
                            limits_.maxBlocks, limits_.maxBlocks));
  if (machine_.skips(b.skipLevel)) { // the dialect's sense of the skip switch
    ++f.pc;
    return true;
  }
  if (runsInOrder(b)) return orderedBlock(f, b);
  if (!b.stmts.empty()) return statement(f, b);
  return ncBlock(f, b);
}

// One pass over the bytes, in bounded chunks: a table of the raw bytes that may start a marker
// (case folded in), then a bitmap of the folded byte pairs that start one, so a plain CAM program
// costs one table lookup per byte and a marker's full compare runs only where its first two
// letters stand (a `G1` is not the start of `G65`).
bool mayNeedExpansion(const std::string& path, const Profile& profile, std::uint64_t begin,
                      std::uint64_t end) {
  if (!profile.controlFlow) return false;
  const std::vector<std::string>& markers = profile.controlFlow->expansionMarkers;
  std::array<unsigned char, 256> fold{};
  for (unsigned c = 0; c < 256; ++c)
    fold[c] = static_cast<unsigned char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
  // per raw byte: 1 ends the scan ('#', '[': an expression only the expansion pass evaluates;
  // a one-letter marker), 2 may start a longer marker
  std::array<unsigned char, 256> interest{};
  interest['#'] = interest['['] = 1;
  std::array<std::uint64_t, 1024> pairs{}; // bit (first << 8 | second), both folded
  std::array<std::vector<const std::string*>, 256> byFirst;
  std::size_t longest = 1;
  for (const std::string& m : markers)
    if (!m.empty()) {
      const unsigned char first = fold[static_cast<unsigned char>(m[0])];
      byFirst[first].push_back(&m);
      longest = std::max(longest, m.size());
      if (m.size() > 1) {
        const unsigned pair = first << 8 | fold[static_cast<unsigned char>(m[1])];
        pairs[pair / 64] |= std::uint64_t{1} << (pair % 64);
      }
      for (unsigned c = 0; c < 256; ++c)
        if (fold[c] == first) interest[c] |= m.size() == 1 ? 1 : 2;
    }
  auto markerAt = [&](const std::string& text, std::size_t i) {
    if (i + 1 >= text.size()) return false; // a one-letter marker ended the scan already
    const unsigned pair = fold[static_cast<unsigned char>(text[i])] << 8 |
                          fold[static_cast<unsigned char>(text[i + 1])];
    if (!((pairs[pair / 64] >> (pair % 64)) & 1)) return false;
    for (const std::string* m : byFirst[fold[static_cast<unsigned char>(text[i])]]) {
      if (i + m->size() > text.size()) continue;
      std::size_t k = 1;
      while (k < m->size() && fold[static_cast<unsigned char>(text[i + k])] ==
                                  fold[static_cast<unsigned char>((*m)[k])])
        ++k;
      if (k == m->size()) return true;
    }
    return false;
  };
  std::ifstream in(path, std::ios::binary);
  if (begin > 0) in.seekg(static_cast<std::streamoff>(begin));
  std::string text;         // the unscanned tail of the last chunk, then the next chunk
  std::uint64_t at = begin; // the file offset of text[0]
  std::size_t kept = 0;
  constexpr std::size_t kChunk = 1 << 16;
  for (;;) {
    text.resize(kept + kChunk);
    in.read(text.data() + kept, static_cast<std::streamsize>(kChunk));
    const auto got = static_cast<std::size_t>(in.gcount());
    text.resize(kept + got);
    const bool endOfFile = got < kChunk;
    // a marker that may run past the chunk waits for the next one; with the bytes read, the
    // markers that begin before `end` are all in view
    std::size_t scanEnd = endOfFile ? text.size() : text.size() - (longest - 1);
    const bool reachesEnd = at + scanEnd >= end;
    if (reachesEnd) scanEnd = static_cast<std::size_t>(end - at);
    const bool last = endOfFile || reachesEnd;
    const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
    for (std::size_t i = 0; i < scanEnd;) {
      // eight bytes of no interest (most of a CAM program's) pass with one test
      if (i + 8 <= scanEnd &&
          (interest[bytes[i]] | interest[bytes[i + 1]] | interest[bytes[i + 2]] |
           interest[bytes[i + 3]] | interest[bytes[i + 4]] | interest[bytes[i + 5]] |
           interest[bytes[i + 6]] | interest[bytes[i + 7]]) == 0) {
        i += 8;
        continue;
      }
      for (const std::size_t stop = std::min(i + 8, scanEnd); i < stop; ++i) {
        const unsigned char k = interest[bytes[i]];
        if (k == 0) continue;
        if (k & 1) return true;
        if (markerAt(text, i)) return true;
      }
    }
    if (last) return false;
    text.erase(0, scanEnd);
    at += scanEnd;
    kept = text.size();
  }
}

} // namespace gcx::macro
