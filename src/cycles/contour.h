// The finished-part contour ns..nf of G71.7/G72.7/G73.7 (cycles.md §4.7) in lathe coordinates,
// its checks (CYC-NS-MODE, type I and monotonicity of §4.8/§4.9) and the geometry the roughing
// cycles need: shifting by the allowance, the first crossing of a level line, following it.
#pragma once
#include <optional>
#include <vector>

#include "cycles/turning_path.h"
#include "diag/diagnostic.h"

namespace gcx::cycles {

/// One resolved move of blocks ns..nf as the interpreter executed it (chamfers and rounds
/// already inserted, §4.7), program coordinates in mm with diameter axes as radius. The first
/// is the ns block's move from A to A'.
struct ContourSegment {
  OpKind kind = OpKind::Feed; // Rapid, Feed, ArcCW, ArcCCW
  Vec3 from = Vec3::Zero(), to = Vec3::Zero(), center = Vec3::Zero();
  double feed = 0; // F of the block: ignored in roughing (§4.7)
  SourceRange range;
  /// The block wrote its G0/G1/G2/G3 itself (not modal from an earlier block): the ns block
  /// must (§4.7).
  bool modeProgrammed = true;
};

struct ProfileSegment {
  OpKind kind = OpKind::Feed; // Feed (Rapid inside the contour is cut at F), ArcCW, ArcCCW
  Vec2 from = Vec2::Zero(), to = Vec2::Zero(), center = Vec2::Zero();
  SourceRange range;
};

/// The contour in lathe coordinates (z, x): the ns move A -> A' and the profile A' -> B.
struct Profile {
  OpKind approach = OpKind::Rapid; // the ns mode: G0 or G1
  Vec2 a = Vec2::Zero(), aPrime = Vec2::Zero();
  SourceRange ns;
  std::vector<ProfileSegment> segments; // A' -> B, zero-length moves dropped
};

/// Converts and checks the contour: not empty (CYC-CONTOUR-DEGENERATE at `block`), the ns block
/// a G0/G1 that programs its mode (CYC-NS-MODE), arcs with a radius (GCX037).
std::optional<Profile> makeProfile(const std::vector<ContourSegment>& contour, motion::Plane plane,
                                   const SourceRange& block, diag::Engine& diags);

/// The profile moved by `offset` (z, x): C' of §4.8 step 1; A stays.
Profile shifted(const Profile& p, const Vec2& offset);

/// The roughing frame of a type-I contour: `level` is the axis the depth steps along (x for
/// G71.7, z for G72.7), `cut` the other one; signs point from A toward the part.
struct RoughFrame {
  int level = 1, cut = 0;
  double levelSign = -1, cutSign = -1;
};

/// §4.8/§4.9 type I: the ns move runs along the level axis only (else CYC-TYPE2-UNSUPPORTED),
/// and A' -> B is monotonic in both axes, running back toward A's level (else
/// CYC-NONMONOTONIC at the first block that turns). Gives the frame.
std::optional<RoughFrame> checkTypeOne(const Profile& p, int levelAxis, const char* cycle,
                                       diag::Engine& diags);

/// The first point where the line {level axis = v}, run from cut coordinate `from` along
/// f.cutSign, meets the profile; nullopt when it does not.
std::optional<double> firstCrossing(const Profile& p, const RoughFrame& f, double v, double from);

/// Whether an arc passes, strictly inside its sweep, a point where its coordinate on lathe
/// axis `axis` (0 z, 1 x) turns back; a line never does.
bool turnsBackAlong(const ProfileSegment& s, int axis);

/// Runs A' -> B at feed f: lines as G1, arcs as G2/G3 with their centres.
void followProfile(const Profile& p, TurningPath& path, double f);

/// Runs the profile at feed f from `from` (a point on it: from the first segment holding it)
/// in its direction until lathe coordinate `axis` reaches `until` (the segment is cut there),
/// or to its end B.
void followProfileUntil(const Profile& p, const Vec2& from, int axis, double until,
                        TurningPath& path, double f);
/// A roughing pass's way out of a level along the profile (WL4 G77/G78): as
/// followProfileUntil, and it also stops where the profile goes deeper (toward `s` along
/// `axis`) than `level`, the level being cut (a zone that level cuts apart). Returns the
/// shallowest coordinate the way reached: a retract along the other axis there is clear.
double followOut(const Profile& p, const Vec2& from, int axis, double s, double level, double until,
                 TurningPath& path, double f);

/// Every point where the line {lathe coordinate `level` = v} meets the profile: their other
/// coordinate, sorted, without repeats.
std::vector<double> crossingsAt(const Profile& p, int level, double v);
/// The extreme of the profile along `axis` toward s: vertices, and arcs where they turn.
double extremeAlong(const Profile& p, int axis, double s);

} // namespace gcx::cycles
