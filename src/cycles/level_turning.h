// The FMS-3000 turning cycles whose parameters follow the code (fms3000.md §5.3, cycles.md
// appendix A.5), on the lathe axes X (slot 0, as radius) and Z (slot 2): G150/G151 single-pass
// turning and facing, G152/G153 multi-pass turning and facing, G162 multi-pass thread,
// G154-G157/G160/G161 drilling along Z and grooving along X (the G83/G86
// sequences of the level drilling cycles, then the final position), G158/G159 grooves,
// G163 tapping, G164/G165 roughing to a profile, G166 chamfer and G167 fillet. A pure function of
// its inputs: the ops from the cycle's start point (И.Т.), in program coordinates.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "cycles/contour.h"
#include "cycles/level_cycle.h"
#include "cycles/ops.h"

namespace gcx::cycles {

struct LevelTurnRequest {
  LevelCycle cycle = LevelCycle::LongitudinalPass;
  std::string code = "the cycle"; // as the program wrote it, for messages: "G150"
  Vec3 position = Vec3::Zero();   // the start point И.Т.
  bool incremental = false;       // G91: positions are signed distances from И.Т.
  /// The cycle's parameters, remembered ones included; X-type values already as radius.
  std::map<char, double> words;
  bool rapidFlag = false;           // `G0` among the parameters: the first segment is a rapid
  bool modalRapid = false;          // G166/G167: the straight part under G0 (else G1)
  double feed = 0;                  // F when not among the words
  double dwellSecondsPerUnit = 0.1; // E
  int spindleDirection = 0;       // G162, G163: +1 M3, -1 M4, 0 stopped (the direction it reverses)
  bool feedPerRevolution = false; // G95
  /// G164/G165: the approach block and the profile up to `endcont`, traced (contour.h).
  const Profile* profile = nullptr;
};

/// A G164/G165 profile the manual refuses: the approach block moves the wrong axis, or the
/// profile is empty or not monotonic along the depth axis (001:3916, 001:3975).
struct ProfileFault {
  SourceRange where;
  std::string why;
};
std::optional<ProfileFault> checkRoughingProfile(LevelCycle cycle, std::string_view code,
                                                 const Profile& profile);

/// The parameters of `cycle` measured along X: diameters when X is programmed as a diameter.
std::string_view diameterWords(LevelCycle cycle);

/// The message of a part of the request gcx does not implement yet (a located GCX030, never a
/// guess): the cone of G152/G153, G162 under G95.
std::optional<std::string> notImplemented(const LevelTurnRequest& req);

/// The ops, or the message of a missing, extra or bad parameter. Zero-length moves are left out.
std::variant<std::vector<CycleOp>, std::string> expandLevelTurning(const LevelTurnRequest& req);

} // namespace gcx::cycles
