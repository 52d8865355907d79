// The level cycles by meaning: drilling cycles whose levels follow the code (U the start of the
// feed, Z the bottom, I the exit) and the turning cycles that take their parameters the same
// way (fms3000.md §5). A dialect binds its codes to them in its G-code table (GCodeSpec::arg
// of a LevelDrillCycle action); messages name the code as the program wrote it.
#pragma once

namespace gcx::cycles {

enum class LevelCycle : unsigned char {
  // drilling, in the order of the bits that make them repeat modally (Setting::ModalLevelCycles)
  Drill,
  BoreFeedExit,
  DeepDrill,
  Tap,
  BoreSpindleStop,
  ChipBreakDrill,
  InterruptedDrill,
  BoreOrientedStop,
  // turning on the lathe axes
  LongitudinalPass,
  FacingPass,
  LongitudinalMultiPass,
  FacingMultiPass,
  DeepDrillZ,
  PeckGrooveX,
  DeepDrillZDecreasing,
  PeckGrooveXDecreasing,
  CylindricalGrooves,
  FaceGrooves,
  ChipBreakDrillZ,
  ChipBreakGrooveX,
  MultiPassThread,
  TapOrDie,
  LongitudinalRoughing, // to a profile that ends at `endcont`
  FacingRoughing,       // the same, across
  Chamfer,
  Fillet,
};

constexpr bool isLevelTurning(LevelCycle c) {
  return c >= LevelCycle::LongitudinalPass;
}
/// Runs after the blocks of its profile, at `endcont`.
constexpr bool takesProfile(LevelCycle c) {
  return c == LevelCycle::LongitudinalRoughing || c == LevelCycle::FacingRoughing;
}
/// Its parameters hold for one block only, nothing is remembered.
constexpr bool isOneBlock(LevelCycle c) {
  return c == LevelCycle::Chamfer || c == LevelCycle::Fillet;
}

} // namespace gcx::cycles
