#include "dialect/machine_rules.h"

namespace gcx {

const SettingSpec* MachineRules::setting(Setting s) const {
  for (const SettingSpec& spec : settings)
    if (spec.setting == s) return &spec;
  return nullptr;
}

const MCodeSpec* MachineRules::mcode(int code) const {
  for (const MCodeSpec& spec : mcodes)
    if (spec.code == code) return &spec;
  return nullptr;
}

} // namespace gcx
