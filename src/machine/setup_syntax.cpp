#include "machine/setup_syntax.h"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>

#include "dialect/control_flow.h"

namespace gcx::machine {

namespace {

bool allDigits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool allLetters(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalpha(static_cast<unsigned char>(c));
  });
}

std::string upper(std::string_view s) {
  std::string out;
  for (char c : s)
    out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

bool sameIgnoringCase(std::string_view a, std::string_view b) {
  return upper(a) == upper(b);
}

} // namespace

std::optional<std::string> SetupSyntax::parameterKey(std::string_view k) const {
  for (const std::string& name : namedParameters)
    if (sameIgnoringCase(k, name)) return name;
  const std::string_view prefix = parameterPrefix;
  if (parameterDigits <= 0 || k.size() <= prefix.size() ||
      !sameIgnoringCase(k.substr(0, prefix.size()), prefix))
    return std::nullopt;
  k.remove_prefix(prefix.size());
  const auto dot = k.find('.');
  const std::string_view number = k.substr(0, dot);
  if (number.size() > static_cast<std::size_t>(parameterDigits) || !allDigits(number))
    return std::nullopt;
  std::string out =
      parameterPrefix + std::string(parameterDigits - number.size(), '0') + std::string(number);
  if (dot == std::string_view::npos) return out;
  if (!parameterBits) return std::nullopt;
  const std::string_view bit = k.substr(dot + 1);
  if (bit.size() == 1 && bit[0] >= '0' && bit[0] <= '7') return out + "." + std::string(bit);
  if (!allLetters(bit)) return std::nullopt;
  return out + "." + upper(bit);
}

std::string SetupSyntax::parameterHelp() const {
  std::vector<std::string> ways;
  if (parameterDigits > 0) {
    std::string example = parameterPrefix + std::string(parameterDigits - 1, '0') + "1";
    ways.push_back(fmt::format("{} and 1-{} digits{} (\"{}\")", parameterPrefix, parameterDigits,
                               parameterBits ? ", optionally followed by .BIT with BIT 0-7 or a "
                                               "bit name"
                                             : "",
                               example));
  }
  for (const std::string& name : namedParameters)
    ways.push_back(fmt::format("\"{}\"", name));
  if (ways.empty()) return fmt::format("{} has no machine parameters", dialect);
  return fmt::format("{} parameters are {}", dialect, fmt::join(ways, ", "));
}

bool SetupSyntax::isWorkOffset(std::string_view k) const {
  if (k == "common") return true;
  if (std::find(workOffsetNames.begin(), workOffsetNames.end(), k) != workOffsetNames.end())
    return true;
  if (extendedWorkOffsets <= 0 || !k.starts_with(extendedWorkOffsetPrefix)) return false;
  const std::string_view n = k.substr(extendedWorkOffsetPrefix.size());
  if (!allDigits(n) || n[0] == '0' || n.size() > 9) return false;
  return std::stol(std::string(n)) <= extendedWorkOffsets;
}

std::optional<std::string> SetupSyntax::workOffsetSpelling(std::string_view k) const {
  auto squeeze = [](std::string_view s) {
    std::string out;
    for (char c : upper(s))
      if (c != ' ') out += c;
    return out;
  };
  const std::string s = squeeze(k);
  std::string fixed;
  if (s == "COMMON") fixed = "common";
  for (const std::string& name : workOffsetNames)
    if (s == squeeze(name)) fixed = name;
  const std::string prefix = squeeze(extendedWorkOffsetPrefix);
  if (fixed.empty() && extendedWorkOffsets > 0 && s.starts_with(prefix)) {
    std::string_view n = std::string_view(s).substr(prefix.size());
    while (n.size() > 1 && n[0] == '0')
      n.remove_prefix(1);
    fixed = extendedWorkOffsetPrefix + std::string(n);
  }
  if (fixed.empty() || fixed == k || !isWorkOffset(fixed)) return std::nullopt;
  return fixed;
}

std::string SetupSyntax::workOffsetHelp() const {
  std::string names;
  if (!workOffsetNames.empty())
    names = workOffsetNames.size() == 1
                ? workOffsetNames.front()
                : fmt::format("{}..{}", workOffsetNames.front(), workOffsetNames.back());
  if (extendedWorkOffsets > 0)
    names += fmt::format("{}\"{}1\"..\"{}{}\"", names.empty() ? "" : ", ", extendedWorkOffsetPrefix,
                         extendedWorkOffsetPrefix, extendedWorkOffsets);
  return names.empty() ? "\"common\"" : names + " and \"common\"";
}

bool SetupSyntax::presettable(long long n) const {
  return std::any_of(presetVariables.begin(), presetVariables.end(),
                     [n](const auto& r) { return n >= r.first && n <= r.second; });
}

std::string SetupSyntax::variableHelp() const {
  if (presetVariables.empty())
    return fmt::format("{} has no variables a setup may preset", dialect);
  std::vector<std::string> ranges;
  for (const auto& [first, last] : presetVariables)
    ranges.push_back(fmt::format("#{}-#{}", first, last));
  return fmt::format("the setup may set {}", fmt::join(ranges, " and "));
}

SetupSyntax setupSyntax(const std::string& dialect, const Profile& profile) {
  const MachineRules& r = profile.machine;
  SetupSyntax s;
  s.dialect = dialect;
  s.parameterPrefix = r.parameterKeyPrefix;
  s.parameterDigits = r.parameterKeyPrefix.empty() ? 0 : r.parameterKeyDigits;
  s.parameterBits = r.parameterBits;
  // every key the machine reads: the settings, and the chamfer-axis switch
  std::vector<const char*> keys;
  for (const SettingSpec& setting : r.settings)
    keys.insert(keys.end(), {setting.key, setting.alias});
  keys.push_back(r.contour.chamferAxisKey.c_str());
  for (const char* key : keys)
    if (key && *key && !s.parameterKey(key) &&
        std::find(s.namedParameters.begin(), s.namedParameters.end(), key) ==
            s.namedParameters.end())
      s.namedParameters.push_back(key);
  s.workOffsetNames = r.workOffsetNames;
  s.modelledValues = r.modelledValues;
  s.extendedWorkOffsetPrefix = r.extendedWorkOffsetPrefix;
  s.extendedWorkOffsets = r.extendedWorkOffsetPrefix.empty() ? 0 : r.extendedWorkOffsets;
  if (const ControlFlow* flow = profile.controlFlow; flow && flow->hasVariables) {
    const VariableSpace& v = flow->variables;
    s.presetVariables = {{v.localFirst, v.localLast}, {v.commonFirst, v.commonLast}};
  }
  return s;
}

const ModelledValues* SetupSyntax::modelled(std::string_view key) const {
  for (const ModelledValues& m : modelledValues)
    if (key == m.key) return &m;
  return nullptr;
}

const SetupSyntax* SetupDialects::find(std::string_view name) const {
  for (const SetupSyntax& s : all)
    if (s.dialect == name) return &s;
  return nullptr;
}

} // namespace gcx::machine
