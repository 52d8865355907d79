// Chamfers and roundings between two blocks (nct.md §4.1) as a stage of the motion stream, in
// front of radius compensation: the element of a block with a chamfer or rounding waits for
// the next element in the plane; then both are trimmed and the chamfer line or rounding arc is
// inserted between them, with the provenance of the first block. Dialect-neutral: the
// interpreter names the block's request (kind, size in the machine frame, plane).
#pragma once
#include <optional>
#include <vector>

#include "machine/compensation.h"

namespace gcx::machine {

class ContourCornerStage {
public:
  enum class Kind : unsigned char { Chamfer, Rounding };
  /// The next move of the current block ends in a chamfer or rounding of `size` (mm).
  void request(Kind kind, double size, motion::Plane plane);
  /// One event of the programmed stream. False after a failure (failure()).
  bool event(const motion::Event& e, motion::Sink& out);
  /// An intersection calculation moves the waiting element's end (CompensationStage's twin).
  bool endWaitingAt(const motion::Vec3& end);
  const std::optional<CompensationFailure>& failure() const { return failure_; }

private:
  struct Request {
    Kind kind;
    double size;
  };
  bool fail(const char* code, const motion::Provenance& at, std::string message);
  comp::Vec2 planar(const motion::Vec3& v) const;
  comp::Path2 pathOf(const motion::Event& e) const;

  motion::Plane plane_ = motion::Plane::XY;
  std::optional<Request> request_;    // for the current block's next plane move
  std::optional<motion::Event> held_; // that move, waiting for the next one
  Request heldRequest_{Kind::Chamfer, 0};
  std::vector<motion::Event> between_; // events without motion after it
  std::optional<CompensationFailure> failure_;
};

} // namespace gcx::machine
