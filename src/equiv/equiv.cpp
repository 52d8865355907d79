#include "equiv/equiv.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include "diag/codes.h"
#include "equiv/event_queue.h"
#include "equiv/ngc_subset.h"
#include "machine/setup.h"
#include "oracle/canon.h"
#include "oracle/rs274.h"
#include "oracle/setup.h"

namespace gcx::equiv {

namespace {

namespace fs = std::filesystem;

bool isNgc(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".ngc";
}

bool readText(const std::string& path, std::string& text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  text = s.str();
  return static_cast<bool>(in) || in.eof();
}

/// The program line rs274 stopped at: it echoes the failing block, which starts with the
/// N<line> number every line was given (oracle/rs274.h); 1 when it cannot tell.
std::uint32_t failingLine(const oracle::Rs274Result& r) {
  const std::string& t = r.stderrText;
  for (std::size_t at = t.rfind("\nN"); at != std::string::npos; at = t.rfind("\nN", at - 1)) {
    std::uint32_t line = 0;
    std::size_t i = at + 2;
    while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])))
      line = line * 10 + static_cast<std::uint32_t>(t[i++] - '0');
    if (i > at + 2 && line > 0) return line;
    if (at == 0) break;
  }
  return 1;
}

std::string oneLine(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' '))
    s.pop_back();
  for (char& c : s)
    if (c == '\n') c = ' ';
  return s;
}

/// One program being read: by gcx's interpreter (the caller's GcxProgram) or by rs274 (its
/// text).
class Side : public ProgramSide {
public:
  Side(const ProgramInput& in, const EquivOptions& o, motion::Sink* tap,
       std::function<std::unique_ptr<GcxProgram>()> maker)
      : in_(in), o_(o), maker_(std::move(maker)), sink_(queue_, tap) {}

  const std::string& name() const override { return in_.path; }
  const SourceManager& sources() const override { return gcx_ ? gcx_->sources() : sources_; }
  const std::vector<diag::Diagnostic>& diagnostics() const override {
    return gcx_ ? gcx_->diags().all() : diags_.all();
  }
  EventQueue& queue() { return queue_; }
  double rapidRate() const { return gcx_ ? gcx_->setup().rapidRate : setup_.rapidRate; }
  bool ok() const { return ok_; }
  bool readByRs274() const { return rs274_; }

  /// Opens the program and its setup (on the calling thread, so usage messages come out in
  /// order); false when it cannot be read.
  bool prepare() {
    const bool ngc = isNgc(in_.path);
    rs274_ = in_.reader == ProgramInput::Reader::Rs274 ||
             (in_.reader == ProgramInput::Reader::Auto && ngc &&
              oracle::findRs274(o_.rs274).has_value());
    if (rs274_) return prepareRs274();
    gcx_ = maker_();
    if (!gcx_->open(in_.path, in_.setup, ngc)) return false;
    if (ngc) {
      std::string text;
      if (!readText(in_.path, text)) return false;
      if (!checkCanonicalSubset(text, gcx_->file(), gcx_->diags())) {
        ok_ = false;
        return true; // reported with the other diagnostics
      }
    }
    return true;
  }

  /// The producer: runs the program into the queue; the queue is closed at the end.
  void produce() {
    try {
      if (!ok_) {
      } else if (rs274_) {
        ok_ = produceRs274();
      } else {
        ok_ = gcx_->run(sink_);
        if (!ok_) sink_.flush(); // the motion before the error still counts
      }
    } catch (const Cancelled&) {
      // the comparison has its answer
    }
    queue_.close();
  }

private:
  bool prepareRs274() {
    if (!readText(in_.path, text_)) {
      diag::reportUsage(fmt::format("{}: cannot open [{}]", in_.path, diag::code::CannotRead));
      return false;
    }
    file_ = sources_.addBuffer(in_.path, text_);
    if (!oracle::findRs274(o_.rs274)) {
      diags_.error(diag::code::NeedsRs274, SourceRange{SourceLoc{file_, 1, 1}, 0},
                   "reading this program needs LinuxCNC's interpreter rs274, which is not "
                   "installed; install it with `apt-get install linuxcnc-uspace`");
      ok_ = false;
      return true;
    }
    options_.executable = o_.rs274;
    options_.timeoutSeconds = o_.rs274TimeoutSeconds;
    if (!in_.setup.empty()) {
      std::string setupText, error;
      if (!readText(in_.setup, setupText)) {
        diag::reportUsage(
            fmt::format("{}: cannot open [{}]", in_.setup, diag::code::SetupCannotRead));
        return false;
      }
      oracle::OracleSetup s;
      if (!oracle::parseSetupJson(setupText, s, error)) {
        diag::reportUsage(
            fmt::format("{}: {} (rs274 takes work offsets G54-G59 and tools)", in_.setup, error));
        return false;
      }
      oracle::applySetup(s, options_);
      setup_.rapidRate = s.rapidRate; // for the times, as gcx's reader takes it
    }
    // T M6 needs the tool in rs274's table: the tools the setup does not give have length 0,
    // as in gcx's default setup
    for (int t = 1; t <= 99; ++t) {
      bool given = false;
      for (const oracle::OracleTool& tool : options_.tools)
        given = given || tool.number == t;
      if (!given) options_.tools.push_back(oracle::OracleTool{t, 0, 0});
    }
    return true;
  }

  /// The location of the start of a line of the program text (so the source line can be shown).
  SourceLoc lineStart(std::uint32_t line) const {
    std::uint64_t offset = 0;
    for (std::uint32_t l = 1; l < line && offset < text_.size(); ++l) {
      const std::size_t eol = text_.find('\n', offset);
      if (eol == std::string::npos) break;
      offset = eol + 1;
    }
    return SourceLoc{file_, line, 1, offset};
  }

  bool produceRs274() {
    const oracle::Rs274Result r = oracle::Rs274(options_).run(text_);
    if (!r.ok()) {
      diags_.error(diag::code::Rs274Failed, SourceRange{lineStart(failingLine(r)), 0},
                   fmt::format("rs274 could not run the program: {}", oneLine(r.summary())));
      return false;
    }
    oracle::CanonOptions copt;
    copt.file = file_;
    copt.programText = text_;
    oracle::CanonReader reader(copt);
    for (const std::string& line : r.canonLines) {
      reader.line(line);
      for (const motion::Event& e : reader.take())
        sink_.event(e);
    }
    if (!reader.unsupported().empty()) {
      diags_.error(diag::code::Rs274Failed, SourceRange{SourceLoc{file_, 1, 1}, 0},
                   fmt::format("rs274's output has calls gcx cannot read back: {}",
                               reader.unsupported().front()));
      return false;
    }
    sink_.finish();
    return true;
  }

  const ProgramInput& in_;
  const EquivOptions& o_;
  std::function<std::unique_ptr<GcxProgram>()> maker_; // this side's gcx program
  EventQueue queue_;
  QueueSink sink_;
  bool rs274_ = false;
  bool ok_ = true;
  // gcx's reading
  std::unique_ptr<GcxProgram> gcx_;
  // rs274's reading
  machine::Setup setup_; // the rapid rate of the setup, as gcx reads it
  SourceManager sources_;
  diag::Engine diags_;
  std::string text_;
  FileId file_ = 0;
  oracle::Rs274Options options_;
};

} // namespace

EquivOutcome checkEquivalence(const ProgramInput& a, const ProgramInput& b,
                              const EquivOptions& options) {
  EquivOutcome out;
  auto sa = std::make_shared<Side>(a, options, options.tapA, options.gcxProgram);
  auto sb = std::make_shared<Side>(b, options, options.tapB,
                                   options.gcxProgramB ? options.gcxProgramB : options.gcxProgram);
  out.a = sa;
  out.b = sb;
  if (!sa->prepare() || !sb->prepare()) return out;
  WalkOptions walkOptions = options.walk;
  walkOptions.rapidRate = sa->rapidRate();
  walkOptions.rapidRateB = sb->rapidRate();
  if (sa->readByRs274() || sb->readByRs274())
    walkOptions.resolution = std::max(walkOptions.resolution, 1e-4);
  std::thread ta([&] { sa->produce(); });
  std::thread tb([&] { sb->produce(); });
  QueueSource qa(sa->queue()), qb(sb->queue());
  out.result = walk(qa, qb, walkOptions);
  sa->queue().cancel();
  sb->queue().cancel();
  ta.join();
  tb.join();
  // A program error counts where the comparison reached it: a divergence found before it
  // stands (the producer may or may not have run on to the error by then).
  out.ok = (sa->ok() || !qa.ended()) && (sb->ok() || !qb.ended());
  return out;
}

} // namespace gcx::equiv
