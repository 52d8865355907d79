#include "cli/check_in_parts.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <thread>
#include <vector>

#include "cli/session.h"
#include "diag/codes.h"
#include "passes/check/static_checks.h"

namespace gcx::cli {

namespace {

// Below this a part does not pay for its thread and for counting the lines before it.
constexpr std::uint64_t kMinPartBytes = 1 << 20;
constexpr std::size_t kChunk = 1 << 12; // lines are short: the LF after a cut is near

std::size_t readAll(BlockSource& source, check::StaticChecker& checker, ir::Block& block) {
  std::size_t n = 0;
  while (source.next(block)) {
    checker.block(block);
    ++n;
  }
  return n;
}

// The offset just after the first LF at or after `from` (before `size`), or 0 if there is none.
std::uint64_t lineStartFrom(std::ifstream& in, std::uint64_t from, std::uint64_t size) {
  std::vector<char> buf(kChunk);
  in.clear();
  in.seekg(static_cast<std::streamoff>(from));
  for (std::uint64_t at = from; at < size;) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (got == 0) break;
    const auto lf = std::find(buf.data(), buf.data() + got, '\n');
    if (lf != buf.data() + got) {
      const std::uint64_t next = at + static_cast<std::uint64_t>(lf - buf.data()) + 1;
      return next < size ? next : 0;
    }
    at += got;
  }
  return 0;
}

// A part after the first: [begin, end) of the file, read into a private diagnostics engine by
// whichever thread takes it, its source stopped at the first block boundary at or after end. Its
// lines are numbered from 1: the lines before it are known only when the part before it is read.
struct Part {
  Part(std::uint64_t b, std::uint64_t e, std::size_t errorLimit)
      : begin(b), end(e), diags(errorLimit) {}

  std::uint64_t begin, end;
  diag::Engine diags;
  std::ifstream in;
  std::unique_ptr<BlockSource> source;
  std::unique_ptr<check::StaticChecker> checker;
  std::size_t blocks = 0;
  std::exception_ptr failure;
};

void readPart(Session& s, Part& p, bool last) {
  const diag::Engine::Divert divert(s.diags(), p.diags);
  p.in.open(s.path(), std::ios::binary);
  p.in.seekg(static_cast<std::streamoff>(p.begin));
  p.source = s.dialect().open(p.in, s.file(), s.diags());
  p.source->startAt(p.begin, 1);
  if (!last) p.source->stopAt(p.end);
  p.checker = std::make_unique<check::StaticChecker>(s.dialect().profile(), s.diags());
  ir::Block block;
  p.blocks = readAll(*p.source, *p.checker, block);
}

// Reads the parts not yet taken, one after another, until none is left.
void takeParts(Session& s, std::vector<std::unique_ptr<Part>>& parts,
               std::atomic<std::size_t>& next) {
  for (std::size_t i; (i = next++) < parts.size();) {
    Part& p = *parts[i];
    try {
      readPart(s, p, i + 1 == parts.size());
    } catch (...) {
      p.failure = std::current_exception();
    }
  }
}

// The cuts between parts: line starts near equal shares of the file, in increasing order.
std::vector<std::uint64_t> cutsOf(const std::string& path, std::uint64_t size, unsigned jobs) {
  std::vector<std::uint64_t> cuts;
  std::ifstream in(path, std::ios::binary);
  for (unsigned k = 1; k < jobs && in; ++k) {
    const std::uint64_t at = lineStartFrom(in, size / jobs * k, size);
    if (at == 0 || (!cuts.empty() && at <= cuts.back())) continue;
    cuts.push_back(at);
  }
  return cuts;
}

// The part's diagnostics, moved from its provisional line numbers to the lines they stand at.
void replay(diag::Engine& to, const diag::Engine& from, std::int64_t lineShift) {
  auto shift = [lineShift](SourceRange& r) {
    if (r.begin.valid()) r.begin.line = static_cast<std::uint32_t>(r.begin.line + lineShift);
  };
  for (diag::Diagnostic d : from.all()) {
    if (d.code == diag::code::TooManyErrors) continue; // the session's engine counts itself
    shift(d.range);
    for (diag::Note& n : d.notes)
      shift(n.range);
    to.report(std::move(d));
  }
}

} // namespace

CheckedBlocks checkBlocks(Session& s, check::StaticChecker& checker, unsigned jobs,
                          unsigned partsPerJob) {
  ir::Block block;
  BlockSource& first = s.source();
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(s.path(), ec);
  if (jobs < 2 || ec || size < 2 * kMinPartBytes || !first.canReadInParts())
    return {readAll(first, checker, block), first.failedBlocks()};
  jobs = static_cast<unsigned>(std::min<std::uint64_t>(jobs, size / kMinPartBytes));
  const auto count = static_cast<unsigned>(std::min<std::uint64_t>(
      std::uint64_t{jobs} * std::max(partsPerJob, 1u), size / kMinPartBytes));
  const std::vector<std::uint64_t> cuts = cutsOf(s.path(), size, count);
  if (cuts.empty()) return {readAll(first, checker, block), first.failedBlocks()};

  std::vector<std::unique_ptr<Part>> parts;
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const std::uint64_t end = i + 1 < cuts.size() ? cuts[i + 1] : size;
    parts.push_back(std::make_unique<Part>(cuts[i], end, s.diags().errorLimit()));
  }
  // The parts after the first go to whichever thread is free: a thread on a slower core (a VM's
  // cores need not be equal) takes fewer of them.
  std::atomic<std::size_t> next = 0;
  std::vector<std::thread> helpers;
  struct JoinAll {
    std::vector<std::thread>& threads;
    ~JoinAll() {
      for (std::thread& t : threads)
        if (t.joinable()) t.join();
    }
  } joinAll{helpers};
  for (unsigned k = 1; k < jobs; ++k)
    helpers.emplace_back([&] { takeParts(s, parts, next); });

  // This thread reads the first part straight into the session, then takes parts too; the
  // parts are joined in file order once all are read.
  std::vector<BlockSource*> used{&first}; // the sources whose blocks count
  BlockSource* reading = &first;
  reading->stopAt(cuts[0]);
  CheckedBlocks total;
  total.blocks = readAll(*reading, checker, block);
  takeParts(s, parts, next);
  for (std::thread& t : helpers)
    t.join();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    Part& p = *parts[i];
    if (p.failure) std::rethrow_exception(p.failure);
    const std::optional<SourceLoc> stopped = reading->stoppedAt();
    if (!stopped) break; // the input ended or failed before the part: nothing more to read
    // the part numbered its first line 1; it is the line the reading before it stopped at
    const std::int64_t lineShift = std::int64_t{stopped->line} - 1;
    if (stopped->offset == p.begin && reading->stateless() &&
        checker.join(std::move(*p.checker), lineShift)) {
      replay(s.diags(), p.diags, lineShift);
      p.source->shiftLines(lineShift);
      total.blocks += p.blocks;
      ++total.partsTaken;
      reading = p.source.get();
      used.push_back(reading);
      continue;
    }
    // the part's findings may differ from reading on: read it in sequence instead
    reading->stopAt(i + 1 < parts.size() ? parts[i + 1]->begin : 0);
    total.blocks += readAll(*reading, checker, block);
  }
  for (BlockSource* source : used)
    total.failed += source->failedBlocks();
  return total;
}

} // namespace gcx::cli
