// What a dialect's setup file may say: the names of its machine parameters, its work offsets
// and the variables a setup may preset. Built from the dialect's profile, so the setup reader
// spells none of them (docs/setup.md).
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "dialect/profile.h"

namespace gcx::machine {

struct SetupSyntax {
  std::string dialect; // the name of its section in a shared setup file ("nct")
  /// Numbered parameters: prefix and up to `parameterDigits` digits, written canonically with
  /// exactly that many (NCT: "N" and 4 digits); 0 digits: none.
  std::string parameterPrefix;
  int parameterDigits = 0;
  bool parameterBits = false;               // ".0"-".7" or a bit's name after the number
  std::vector<std::string> namedParameters; // settings keyed by a name ("arc_tolerance")
  std::vector<std::string> workOffsetNames; // "G54".."G59"
  std::string extendedWorkOffsetPrefix;     // + 1..extendedWorkOffsets ("G54.1 P7")
  int extendedWorkOffsets = 0;
  std::vector<std::pair<int, int>> presetVariables; // #first..#last ranges a setup may set
  std::vector<ModelledValues> modelledValues;       // parameters gcx models in part

  /// The rule of a parameter gcx models only in part, or null.
  const ModelledValues* modelled(std::string_view key) const;

  /// The canonical key of a parameter as a file may write it (NCT: lower case, fewer digits), or
  /// nullopt when it is not one of this dialect's parameters.
  std::optional<std::string> parameterKey(std::string_view written) const;
  /// How a message tells the parameter keys ("N and 1-4 digits, ...").
  std::string parameterHelp() const;
  bool isWorkOffset(std::string_view key) const;
  /// The intended work-offset key of a near miss ("g55", "G54.1P7", "COMMON"), if any.
  std::optional<std::string> workOffsetSpelling(std::string_view key) const;
  std::string workOffsetHelp() const;
  bool presettable(long long variable) const;
  std::string variableHelp() const;
};

/// The setup syntax of a dialect, from its profile (machine rules and variable space).
SetupSyntax setupSyntax(const std::string& dialect, const Profile& profile);

/// The dialects a setup file is read for: `own`'s top-level parameters and section apply; the
/// sections of the others are checked by their syntax and left for their programs. Without
/// `own` (readers that want only the machine: offsets, tools, positions), parameters,
/// variables and sections are skipped unchecked.
struct SetupDialects {
  std::optional<SetupSyntax> own;
  std::vector<SetupSyntax> all; // every known dialect, `own` included

  const SetupSyntax* find(std::string_view name) const;
};

} // namespace gcx::machine
