#include "cli/check_in_parts.h"

#include <algorithm>
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
constexpr std::size_t kChunk = 1 << 18;

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

// The line number at `offset`: one more than the LFs before it.
std::uint32_t lineAt(std::ifstream& in, std::uint64_t offset) {
  std::vector<char> buf(kChunk);
  in.clear();
  in.seekg(0);
  std::uint64_t lines = 1;
  for (std::uint64_t left = offset; left > 0;) {
    in.read(buf.data(), static_cast<std::streamsize>(std::min<std::uint64_t>(left, buf.size())));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (got == 0) break;
    std::size_t n = 0;
    for (std::size_t i = 0; i < got; ++i) // a loop the compiler vectorises
      n += buf[i] == '\n';
    lines += n;
    left -= got;
  }
  return static_cast<std::uint32_t>(lines);
}

// A part after the first: [begin, end) of the file, read on a thread of its own into a private
// diagnostics engine, its source stopped at the first block boundary at or after end.
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
  std::thread thread;
};

void readPart(Session& s, Part& p, bool last) {
  const diag::Engine::Divert divert(s.diags(), p.diags);
  p.in.open(s.path(), std::ios::binary);
  const std::uint32_t line = lineAt(p.in, p.begin);
  p.in.clear();
  p.in.seekg(static_cast<std::streamoff>(p.begin));
  p.source = s.dialect().open(p.in, s.file(), s.diags());
  p.source->startAt(p.begin, line);
  if (!last) p.source->stopAt(p.end);
  p.checker = std::make_unique<check::StaticChecker>(s.dialect().profile(), s.diags());
  ir::Block block;
  p.blocks = readAll(*p.source, *p.checker, block);
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

void replay(diag::Engine& to, const diag::Engine& from) {
  for (const diag::Diagnostic& d : from.all())
    if (d.code != diag::code::TooManyErrors) to.report(d); // the session's engine counts itself
}

} // namespace

CheckedBlocks checkBlocks(Session& s, check::StaticChecker& checker, unsigned jobs) {
  ir::Block block;
  BlockSource& first = s.source();
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(s.path(), ec);
  if (jobs < 2 || ec || size < 2 * kMinPartBytes || !first.canReadInParts())
    return {readAll(first, checker, block), first.failedBlocks()};
  jobs = static_cast<unsigned>(std::min<std::uint64_t>(jobs, size / kMinPartBytes));
  const std::vector<std::uint64_t> cuts = cutsOf(s.path(), size, jobs);
  if (cuts.empty()) return {readAll(first, checker, block), first.failedBlocks()};

  std::vector<std::unique_ptr<Part>> parts;
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const std::uint64_t end = i + 1 < cuts.size() ? cuts[i + 1] : size;
    parts.push_back(std::make_unique<Part>(cuts[i], end, s.diags().errorLimit()));
  }
  for (std::size_t i = 0; i < parts.size(); ++i) {
    Part& p = *parts[i];
    const bool last = i + 1 == parts.size();
    p.thread = std::thread([&s, &p, last] {
      try {
        readPart(s, p, last);
      } catch (...) {
        p.failure = std::current_exception();
      }
    });
  }
  // This thread reads the first part straight into the session, then joins the others in order.
  struct JoinAll {
    std::vector<std::unique_ptr<Part>>& parts;
    ~JoinAll() {
      for (auto& p : parts)
        if (p->thread.joinable()) p->thread.join();
    }
  } joinAll{parts};

  std::vector<BlockSource*> used{&first}; // the sources whose blocks count
  BlockSource* reading = &first;
  reading->stopAt(cuts[0]);
  CheckedBlocks total;
  total.blocks = readAll(*reading, checker, block);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    Part& p = *parts[i];
    p.thread.join();
    if (p.failure) std::rethrow_exception(p.failure);
    const std::optional<std::uint64_t> stopped = reading->stoppedAt();
    if (!stopped) break; // the input ended or failed before the part: nothing more to read
    if (*stopped == p.begin && reading->stateless() && checker.join(std::move(*p.checker))) {
      replay(s.diags(), p.diags);
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
