// NCT turning cycles G70.7-G79.7 (cycles.md §4): the cycle codes, the words of a cycle block,
// the plane mapping of §4.2 and the values the two-block formats store between blocks. The
// interpreter owns one TurningModal per channel and calls updateModal() for every block with a
// turning-cycle code; when it says Run, expandTurning() (turning.h) makes the operations.
#pragma once
#include <array>
#include <optional>
#include <string>

#include "diag/diagnostic.h"
#include "ir/source.h"
#include "motion/event.h"

namespace gcx::cycles {

/// The turning cycles (§4.1). G70.7-G76.7 are one-shot (group 0), G77.7-G79.7 modal (group 1).
enum class TurningCycle : unsigned char {
  Finishing,      // finishing: the interpreter re-executes ns..nf (§4.11)
  RoughTurning,   // stock removal in turning (§4.8)
  RoughFacing,    // stock removal in facing (§4.9)
  PatternRepeat,  // pattern repeating (§4.10)
  FaceGrooving,   // face grooving / peck drilling (§4.12)
  Grooving,       // grooving (§4.12)
  MultipleThread, // multiple threading (§4.13)
  TurningPass,    // turning cycle (§4.4)
  ThreadPass,     // simple thread cycle (§4.5)
  FacingPass,     // facing cycle (§4.6)
};

/// One address of a cycle block as programmed: mm, a diameter axis NOT halved.
struct TurningWord {
  double value = 0;
  bool incremental = false; // G91 or the I operator (only axis words use it)
  SourceRange range;
};

/// The words of one turning-cycle block, raw, by address letter.
struct TurningWords {
  TurningCycle cycle = TurningCycle::RoughTurning;
  std::string label; // the code as written ("G71.7"), for messages
  motion::Plane plane = motion::Plane::ZX;
  unsigned diameter = 0; // bit a: axis a (0 X, 1 Y, 2 Z) is diameter-programmed
  std::array<std::optional<TurningWord>, 26> letters;
  SourceRange range; // the block

  const std::optional<TurningWord>& operator[](char c) const { return letters[index(c)]; }
  void set(char c, double v, SourceRange r = {}, bool incremental = false) {
    letters[index(c)] = TurningWord{v, incremental, r};
  }
  /// The range of word c when given, else the block's: where an error about c points.
  SourceRange at(char c) const {
    const auto& w = (*this)[c];
    return w && w->range.begin.valid() ? w->range : range;
  }

private:
  static std::size_t index(char c) { return static_cast<std::size_t>((c | 0x20) - 'a') % 26; }
};

/// §4.2: P1 (lathe Z) is the plane's first axis, P2 (lathe X) its second. The letters a block
/// uses for them: absolute X/Y/Z and the incremental U/V/W (lathe W' = P1, lathe U' = P2).
struct LatheAxes {
  int p1, p2, normal; // indices into Vec3
  char z, x;          // absolute letters of P1 and P2
  char w, u;          // incremental letters of P1 and P2: lathe W' and U'
};
LatheAxes latheAxes(motion::Plane plane);

/// The values the first block of a two-block format stores (§4.8-§4.13), in radius mm. Fanuc
/// keeps them as parameters shared by G71/G72 (Δd, e) and by G74/G75 (e) [F]; so does this.
struct TurningModal {
  std::optional<double> roughDepth;  // Δd of G71.7/G72.7
  double roughRetract = 0;           // e of G71.7/G72.7 (Fanuc parameter; 0 until programmed)
  double reliefP2 = 0, reliefP1 = 0; // Δi, Δk of G73.7
  std::optional<int> repeatCount;    // d of G73.7
  double grooveRetract = 0;          // e of G74.7/G75.7
  int threadFinishPasses = 1;        // m of G76.7
  int threadChamfer = 0;             // r of G76.7, in 0.1 leads
  int threadAngle = 60;              // a of G76.7, degrees
  double threadMinCut = 0;           // Δdmin of G76.7
  double threadAllowance = 0;        // d of G76.7
};

enum class TurningBlock : unsigned char {
  Error,  // reported; nothing runs
  Stored, // a first block: values stored, no motion
  Run,    // the block runs the cycle: call expandTurning()
};

/// Reads the block: a first block (G71.7/G72.7/G73.7 without P and Q, G74.7/G75.7/G76.7
/// without a P1/P2 axis word) stores its values in m; the other blocks and G70.7/G77.7-G79.7
/// run. Values are checked (CYC-PARAM at the word, §7): Δd <= 0, e < 0, d not an integer >= 1,
/// m not an integer 1..99, a not in {0, 29, 30, 55, 60, 80}, Δdmin or d < 0.
TurningBlock updateModal(TurningModal& m, const TurningWords& w, diag::Engine& diags);

} // namespace gcx::cycles
