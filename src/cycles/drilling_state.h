// NCT drilling cycles (cycles.md §2): the cycle codes, the machine parameters the cycles read
// (§2.8), and the cycle variables a control keeps while cycle mode is on (§2.3-§2.5). The
// interpreter owns one DrillModal per channel and calls updateModal() for every block executed
// in cycle mode; expandHole() (drilling.h) then turns each hole into operations.
#pragma once
#include <optional>
#include <string>

#include "diag/diagnostic.h"
#include "ir/source.h"

namespace gcx::cycles {

/// The drilling cycles of group 09 (cycles.md §2.1). G83.1/G84.1/G86.1 (the CSM setting) are the
/// same cycles as G73/G74/G76: a dialect binds its codes to these (GCodeSpec::arg).
enum class DrillCycle : unsigned char {
  HighSpeedPeck,    // high-speed peck drilling (000:9670)
  LeftTapFloating,  // left-hand tapping, floating holder (000:9702)
  FineBoring,       // fine boring with oriented retract (000:9744)
  Drill,            // drilling, rapid retract (000:9798)
  DrillDwell,       // drilling with dwell (000:9829)
  PeckDrill,        // peck drilling, retract to R (000:9851)
  RightTapFloating, // right-hand tapping, floating holder (000:9884)
  RigidTapRight,    // rigid tapping, right hand (000:9925)
  RigidTapLeft,     // rigid tapping, left hand (000:9925)
  BoreFeedOut,      // boring, feed retract (000:10107)
  BoreSpindleStop,  // boring, spindle stop, rapid retract (000:10138)
  BackBore,         // A: manual intervention (ORI=0); B: back boring (ORI=1) (000:10161)
  BoreDwellManual,  // dwell, manual intervention (000:10253)
  BoreDwellFeedOut, // boring with dwell, feed retract (000:10291)
};

/// Group 10: where the tool returns after a hole (§2.3). G98 is the default and is set again at
/// power-on, reset and when cycle mode is cancelled (000:9456-9459).
enum class DrillReturn : unsigned char { Initial /* G98 */, RLevel /* G99 */ };

/// One cycle address as programmed, in mm (inch already converted by the caller).
struct DrillWord {
  double value = 0;
  /// Z and R only: the value is incremental (G91, the I operator `RI-5`, or U/V/W used as
  /// incremental addresses). Incremental R counts from the initial level, incremental Z from
  /// the R level (000:9566-9567, 9577); expandHole() applies the rule at every hole.
  bool incremental = false;
  SourceRange range; // where it was programmed: errors about a modal value point here
};

/// The modal cycle variables (§2.4). Z and R are kept as programmed (value + incremental flag):
/// after G80 "Z and R become incremental 0" (000:9792-9793), so the control resolves them at
/// each hole, not when they are programmed [D].
struct DrillVariables {
  std::optional<DrillWord> z, r; // bottom, R level
  std::optional<DrillWord> q;    // peck depth (G73, G83, G84.2/.3), positive, not scaled
  std::optional<DrillWord> e;    // G73 retract, G83 clearance, G84.2/.3 retract or clearance
  std::optional<DrillWord> p;    // dwell at the bottom, G04 units
  /// One I J K register (§9 Q-3): the orientation shift of G76/G87-B (I J in G17, K I in G18,
  /// J K in G19; always incremental, 000:9550-9556), and I as the retract override in % of
  /// G85, G89, G84.2, G84.3.
  std::optional<DrillWord> i, j, k;
  /// I as written, for its percent meaning (never converted from inch); stored with i.
  std::optional<DrillWord> overridePercent;
};

/// What a control remembers between blocks while cycle mode is on. cancel() at G80, at any
/// group-1 code (G00 G01 G02 G03 G33) and at reset (000:9479-9481, 9792-9793).
struct DrillModal {
  std::optional<DrillCycle> cycle; // nullopt: G80
  std::string label;               // its code as the program wrote it ("G81"), for messages
  /// The drilling axis the initial level belongs to, in the caller's numbering (suggested:
  /// 0-2 X Y Z, 3-5 U V W as parallel axes). A change of drilling axis registers a new
  /// initial level and needs R in the same block (000:9494-9505).
  int axis = -1;
  std::optional<double> initial; // the initial level `ini` (§2.3), mm
  DrillVariables vars;
};

/// The cycle words of one block executed in cycle mode (or of the block that enters it).
struct DrillWords {
  std::optional<DrillCycle> code; // a drilling-cycle G code in this block
  std::string label;              // that code as written ("G84.2")
  /// §2.5: the block programs a plane axis, the drilling axis or another non-drilling axis q
  /// (000:10327-10332). A Z word (vars.z) counts as one by itself. The caller decides what
  /// counts (a G04 block never does: its P is the dwell's, 000:10334-10336).
  bool holeWord = false;
  int axis = 2;               // the drilling axis of this block (DrillModal::axis numbering)
  double axisPosition = 0;    // its programmed position before the block: ini when registered
  DrillVariables vars;        // the block's Z R Q E P I J K words (Z and R resolved at the hole)
  std::optional<DrillWord> l; // repetitions; not modal (000:9615-9618)
  SourceRange range;          // the block
};

/// Stores a block's cycle words in m by the NCT rules, registers the initial level and checks
/// the data. Returns the number of holes the block drills: 0 when it drills none (no hole word,
/// or L0: "data stored, not executed", 000:9617), else L (default 1); nullopt after reporting
/// an error. Rules:
///  * a cycle code while G80 is in force enters cycle mode: ini = axisPosition (000:9485-9493);
///  * another drilling axis: new ini, the stored R is dropped, so R must be in this block or
///    error 2053 follows (000:9494-9505); Z stays stored [D];
///  * Z and R are stored from any block; Q E P I J K only from a block with a hole word
///    (000:10338-10358), F and S are the caller's (they survive G80);
///  * a hole needs Z and R: error 2053 (000:9503-9505, 9624);
///  * Q or E < 0: CYC-Q-NEGATIVE (000:9584, 9590); L outside 0..99999999: CYC-L-RANGE (000:9616).
std::optional<long> updateModal(DrillModal& m, const DrillWords& w, diag::Engine& diags);

/// G80, a group-1 code, reset: cycle mode ends and every cycle variable is cleared
/// (000:9792-9793). The caller also sets G98 again (000:9456-9459); F and S are not touched.
inline void cancel(DrillModal& m) {
  m = DrillModal{};
}

/// Machine settings of the cycles (§2.8), as values; the machine reads them from the setup
/// under the dialect's keys (machine/settings.h). The seed gives no factory values: the
/// defaults are the spec's test values.
struct DrillConfig {
  double returnG73 = 0.5;         // high-speed peck retract d
  double clearanceG83 = 1.0;      // peck drilling clearance
  double extractionG85G89 = 100;  // retract override in G85, G89 (%)
  double tapReturn = 0.5;         // peck rigid tapping retract (tapNormalPeck off)
  double tapClearance = 1.0;      // peck rigid tapping clearance (tapNormalPeck on)
  double tapExtraction = 100;     // rigid tapping retract override (%)
  double tapReturnOverride = 100; // rigid tapping return override (%)
  bool tapOrient = false;         // op 4 orients the spindle instead of closeLoopMCode
  bool tapNormalPeck = false;     // peck rigid tap retracts to R (as G83)
  bool extractionEnabled = false; // the rigid-tap retract override applies
  bool returnEnabled = false;     // tapReturnOverride applies to peck retracts to R
  bool orient = true;             // the spindle can be oriented (G76, G87 variant B)
  bool indexable = true;          // the spindle has a position loop (G84.2, G84.3)
  int closeLoopMCode = 24;        // the M code that closes the spindle position loop
  const char* orientLabel = "";   // how messages name the orient and index settings
  const char* indexLabel = "";
};

} // namespace gcx::cycles
