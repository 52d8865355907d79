// Runs a program through the interpreter into a motion sink: what expand, run and plot share.
#pragma once
#include <functional>
#include <memory>
#include <optional>

#include "cli/output_file.h"
#include "cli/session.h"
#include "front/encoding_output.h"
#include "machine/setup.h"
#include "motion/event.h"

namespace gcx::machine {
class Interpreter;
}
namespace gcx::macro {
struct Limits;
}

namespace gcx::cli {

/// Opens the program and loads --setup (defaults when empty) for a command that executes it.
/// Returns 0, or the exit code after reporting the problem.
int openWithSetup(Session& s, const std::string& file, const std::string& setupPath,
                  machine::Setup& setup);

/// The frame events reach the sink in: the interpreter's machine frame; the work frame of
/// motion/work_frame.h (points relative to the work origin in force at each event); or the
/// program frame, the work frame taken back through the programmable transformations
/// (motion/transform_frame.h) and into the program's units (motion/program_units.h).
enum class Frame { Machine, Work, Program };
/// The frame --frame names ("machine", "work", "program"; the CLI checks the name).
Frame frameNamed(const std::string& name);

/// Static checks and execution, block by block; stops at the first error. True if the whole
/// program ran without error.
/// Programs with macro statements or calls go through the expansion pass (loaded whole);
/// DPRNT output goes to printOut.
/// `onBlock` is told each block's provenance before it runs (machine::Interpreter).
bool executeProgram(Session& s, const CommonOptions& opt, const machine::Setup& setup,
                    motion::Sink& sink, std::ostream& printOut, Frame frame = Frame::Machine,
                    motion::Sink* machineSink = nullptr,
                    std::function<void(const motion::Provenance&)> onBlock = {});

/// The work origin (machine frame) a program starts with under this setup: the initial work
/// offset plus the common shift.
motion::Vec3 initialWorkOrigin(Session& s, const machine::Setup& setup);

/// The run limits of the options: --max-jumps, --max-blocks, --max-depth for the expansion pass;
/// --max-moves and --max-output for the machine, which stops at the block that crosses them.
macro::Limits expansionLimits(const CommonOptions& opt);
/// `programBytes` is the size of the main program file (for the automatic --max-output).
void limitMachine(machine::Interpreter& interp, const CommonOptions& opt,
                  std::uint64_t programBytes);
/// The --max-output budget in bytes for a main program of `programBytes` bytes.
std::uint64_t outputBudgetFor(const CommonOptions& opt, std::uint64_t programBytes);

/// Writes through a temporary file that replaces `path` only on success (never a partial file);
/// an empty path means standard output. Every write, the flush and the close are checked.
class AtomicOutput {
public:
  /// `encoding`: what the text written in UTF-8 is converted to (a dialect's program in its
  /// own encoding, front/encoding_output.h).
  explicit AtomicOutput(std::string path, front::Encoding encoding = front::Encoding::Utf8);
  ~AtomicOutput();
  std::ostream& stream() { return encoded_ ? *encodedStream_ : out_; }
  /// False (with a message) if the temporary file cannot be created.
  bool ok();
  /// Moves the result into place; false (with a message) on failure.
  bool commit();

private:
  void discard();

  std::string path_, tmp_;
  CheckedFile file_;
  std::ostream out_{&file_};
  std::unique_ptr<front::EncodingOutput> encoded_; // only for an encoding other than UTF-8
  std::unique_ptr<std::ostream> encodedStream_;
  bool direct_ = false; // a device or pipe: no temporary file
  bool done_ = false;
};

/// Where DPRNT output goes: --print FILE, else standard output, or standard error when the
/// command's own output is on standard output.
class PrintOutput {
public:
  PrintOutput(const CommonOptions& opt, bool outputOnStdout);
  /// False (with a message) if --print names a file that cannot be written.
  bool ok();
  std::ostream& stream() { return file_.isOpen() ? fileStream_ : *console_; }
  /// Flushes and closes --print; false (with a message) if a write failed.
  bool finish();

private:
  std::string path_;
  CheckedFile file_;
  std::ostream fileStream_{&file_};
  std::ostream* console_;
};

/// Writes a whole file to standard output; false (with a message) if the write fails.
bool copyToStdout(const std::string& path);

/// A sink that hands every event to several sinks.
class Tee : public motion::Sink {
public:
  void add(motion::Sink& s) { sinks_.push_back(&s); }
  bool empty() const { return sinks_.empty(); }
  void event(const motion::Event& e) override {
    for (motion::Sink* s : sinks_)
      s->event(e);
  }
  void finish() override {
    for (motion::Sink* s : sinks_)
      s->finish();
  }

private:
  std::vector<motion::Sink*> sinks_;
};

} // namespace gcx::cli
