// The writer of flat motion every dialect shares: motion events as blocks of the target's codes,
// each chosen by its meaning from the target's profile (G codes by action, M codes by action, the
// dwell word and its unit, the arc-centre convention, the ranges of its addresses), printed by
// the dialect's own emitter. What the profile cannot say (program naming, comments, number
// resolution) the dialect gives in FlatSyntax. Coordinates are machine-frame, metric, absolute,
// as in canonical motion (emit/canonical.h): the result runs without a setup.
#pragma once
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dialect/profile.h"
#include "emit/emitter.h"
#include "emit/motion_writer.h"
#include "ir/block.h"
#include "translate/hole_lowering.h"

namespace gcx::emit {

struct FlatSyntax {
  const Profile* profile = nullptr;
  const char* label = "";  // the dialect as messages name it: "FMS-3000"
  int decimals = 3;        // of coordinates, centres and feeds: the control's resolution
  int codeDigits = 1;      // G and M numbers written with at least this many digits (G04)
  std::string programName; // as the target names its program (a unit, an O number)
  /// Blocks written before the notes (NCT's O number) and after the program end.
  std::vector<ir::Block> opening, closing;
  /// A comment line in the dialect's syntax.
  std::function<ir::Block(const std::string&)> comment;
  /// The target's drilling cycles (translate/hole_lowering.h), when cycles are kept.
  std::unique_ptr<xlate::HoleLowering> holes;
};

/// A comment line that runs to the end of the line (FMS-3000 `rem`, WL4 `$`).
ir::Block lineComment(const std::string& text);

class FlatWriter : public MotionWriter {
public:
  FlatWriter(std::unique_ptr<ProgramEmitter> emitter, FlatSyntax syntax,
             const MotionWriterOptions& opt, diag::Engine& diags);
  void event(const motion::Event& e) override;
  void finish() override;
  bool ok() const override { return ok_; }

private:
  class HoleOut;
  void write(const motion::Event& e);
  void drain(bool complete);
  bool lowerHole(const xlate::Hole& h, const motion::Event& first);
  void record(const xlate::Hole& h, const std::string& why);
  bool fail(const motion::Event& e, const char* code, const std::string& message);
  void begin();
  void flush();
  void word(const char* address, double v);
  void code(char letter, int code10);
  bool gcode(GAction a, const motion::Event& e, const char* meaning);
  bool mcode(MAction a, const motion::Event& e, const char* meaning);
  bool checkedWord(char letter, double v, const motion::Event& e, const char* meaning);
  double rounded(double v) const;
  void header(const motion::Event& e);
  bool feedMode(bool perRevolution, const motion::Event& e);
  bool position(const motion::Vec3& p, const motion::Extra& x, const motion::Event& e);
  bool straight(GAction a, const motion::Vec3& to, const motion::Extra& x, const motion::Event& e);
  bool arc(const motion::Event& e);
  bool arcPiece(const motion::Event& e, const motion::Vec3& to, const motion::Extra& x,
                double sweep, int turns);
  bool spindle(const motion::Event& e);
  bool coolant(const motion::Event& e);
  bool dwell(const motion::Event& e);
  bool end(const motion::Event& e);

  std::unique_ptr<ProgramEmitter> emitter_;
  FlatSyntax syntax_;
  MotionWriterOptions opt_;
  diag::Engine& diags_;
  ir::Block block_;
  bool ok_ = true;
  bool headerDone_ = false;
  bool ended_ = false;
  bool perRevolution_ = false;
  motion::Plane plane_ = motion::Plane::XY;
  motion::Vec3 at_ = motion::Vec3::Zero(); // where the written program has the tool
  bool extraWords_ = false;                // A B C on every move once one has moved
  // kept cycles: the events that may still be a hole, the one written before them, and
  // whether the target is in a cycle mode the next block must end
  std::deque<motion::Event> pending_;
  std::optional<motion::Event> last_;
  bool inCycle_ = false;
};

} // namespace gcx::emit
