// Cutter radius compensation as a stage of the motion stream (docs/compensation.md): the
// interpreter emits the programmed path, the stage turns it into the tool-centre path with a
// bounded look-ahead (one element waiting for its successor, plus the events between them) and
// passes everything else through in order. It works in the machine frame, which differs from
// the transformed program frame only by a translation (offsets and lengths change only at
// look-ahead breakers), so the offset path is computed after the programmable transforms.
// Dialect-neutral: the interpreter tells it the side, the radius and the block boundaries.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "machine/offset_geometry.h"
#include "motion/event.h"

namespace gcx::machine {

struct CompensationFailure {
  const char* code = "";
  motion::Provenance at;
  std::string message;
};

class CompensationStage {
public:
  struct Options {
    int lookAheadBlocks = 2; // blocks read beyond a plane element for its successor
    bool interferenceCheck = true;
    comp::OuterCorner outer = comp::OuterCorner::TypeC;
    double arcGapLimit = 0;            // an arc corner with a smaller gap: the intersection
    bool startUpPerpendicular = false; // start-up ends on the next element's start perpendicular
    bool cancelPerpendicular = false;  // the cancel's element ends on its end perpendicular
    double mergeDistance = 0;          // corner vectors closer than this on both axes are merged
  };
  CompensationStage() = default;
  explicit CompensationStage(Options o) : options_(o) {}

  /// A block begins (blocks without words are not counted). False on a look-ahead alarm.
  bool beginBlock(motion::Sink& out);
  /// The block's compensation: side +1 left, -1 right, 0 off; radius >= 0 (mm); the plane;
  /// `direction`: in-plane I J K of a start-up or cancel block (machine frame).
  void setMode(motion::Plane plane, int side, double radius,
               const std::optional<comp::Vec2>& direction = std::nullopt);
  /// The block has in-plane axis words but no in-plane displacement (nct.md §3.17.1).
  void zeroPlaneMove() { zeroMove_ = true; }
  /// G39: the next outer corner is passed on an arc of the radius about the corner point.
  void cornerArc() { cornerArc_ = true; }
  /// G39 I J K: the waiting element ends on an arc of the radius about its end point, from its
  /// end perpendicular to the perpendicular of `direction`. False when no element waits.
  bool cornerArcTowards(const comp::Vec2& direction, motion::Sink& out);
  /// G38: this block's plane element ends with the vector it starts with.
  void holdVector() { holdBlock_ = blockIndex_; }
  /// A look-ahead breaker (nct.md §3.17.7): the waiting element ends on its programmed point,
  /// this block's moves pass uncompensated, the vector is rebuilt by the next plane element.
  void breakLookAhead(motion::Sink& out);
  /// One event of the programmed stream. False after a failure (failure()).
  bool event(const motion::Event& e, motion::Sink& out);
  /// An intersection calculation (nct.md §4.3) moves the waiting element's programmed end to
  /// `end` (in the plane; on its line or circle). False when no element waits.
  bool endWaitingAt(const motion::Vec3& end);
  const std::optional<CompensationFailure>& failure() const { return failure_; }
  /// Compensation is on, or the tool is not yet back on the programmed path.
  bool engaged() const { return side_ != 0 || pending_ || displaced_; }

private:
  struct Element {
    motion::Event e;
    comp::Path2 path;
    double d = 0;                          // signed offset at its end (left positive)
    bool startUp = false;                  // starts at the uncompensated point
    std::optional<comp::Vec2> virtualDir;  // the start-up block's I J K
    bool hold = false;                     // G38: ends with its start vector
    comp::Vec2 start = comp::Vec2::Zero(); // its compensated start
  };

  bool inPlane(const motion::Event& e) const;
  comp::Path2 pathOf(const motion::Event& e) const;
  comp::Vec2 planar(const motion::Vec3& v) const;
  motion::Vec3 spatial(const comp::Vec2& p, double normal) const;
  bool fail(const char* code, const motion::Provenance& at, std::string message);
  /// A plane element arrives.
  bool element(const motion::Event& e, motion::Sink& out);
  /// Emits the waiting element to the corner points, the corner's lines, then the held events.
  /// `centre`: the waiting arc runs about this centre instead of its own (a shifted arc).
  bool release(const std::vector<comp::Vec2>& points, bool arcAbout, motion::Sink& out,
               const std::optional<comp::Vec2>& centre = {});
  /// The waiting element ends on its end perpendicular (or its programmed end point).
  bool releaseAlone(bool onProgrammedPoint, motion::Sink& out);
  void emitHeld(motion::Sink& out);
  /// An event moved to start (and, without motion, stay) at the tool position.
  void passAtTool(motion::Event e, motion::Sink& out);
  /// A straight move from the tool position to `to` at the tool's height, as `like` moves.
  void emitLine(const motion::Event& like, const comp::Vec2& to, motion::Sink& out);
  void send(const motion::Event& e, motion::Sink& out);

  Options options_;
  motion::Plane plane_ = motion::Plane::XY;
  int side_ = 0;
  double radius_ = 0;
  std::optional<comp::Vec2> direction_;
  std::optional<Element> pending_;
  std::vector<motion::Event> held_; // events between the waiting element and its successor
  int blockIndex_ = 0, waiting_ = 0;
  int startBlock_ = -1;  // the block that switched compensation on (a start-up follows)
  int cancelBlock_ = -1; // the block that switched it off while an element waits
  bool startPending_ = false, restart_ = false, cancelPending_ = false;
  int suspendedBlock_ = -1; // a breaker's block: its moves pass uncompensated
  bool zeroMove_ = false;
  bool cornerArc_ = false; // G39 before the next corner
  int holdBlock_ = -1;     // the G38 block
  bool displaced_ = false; // the tool stands off the programmed path after a cancel
  motion::Vec3 tool_ = motion::Vec3::Zero();
  motion::Extra toolExtra_ = motion::Extra::Zero();
  bool toolKnown_ = false;
  std::optional<CompensationFailure> failure_;
};

} // namespace gcx::machine
