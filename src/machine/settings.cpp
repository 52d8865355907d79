#include "machine/settings.h"

#include <array>

namespace gcx::machine {

namespace {
double valueOf(const SettingSpec* s, const Setup& setup, double absent) {
  if (!s) return absent;
  if (setup.parameters.empty()) return s->fallback; // the usual case: no key strings to build
  const double fallback = s->alias ? setup.parameter(s->alias, s->fallback) : s->fallback;
  return setup.parameter(s->key, fallback);
}
} // namespace

double setting(const Profile& profile, const Setup& setup, Setting which, double absent) {
  return valueOf(profile.machine.setting(which), setup, absent);
}

const char* settingLabel(const Profile& profile, Setting which) {
  const SettingSpec* s = profile.machine.setting(which);
  return s ? s->label : "";
}

const char* settingKey(const Profile& profile, Setting which) {
  const SettingSpec* s = profile.machine.setting(which);
  return s ? s->key : nullptr;
}

const GCodeSpec* codeOf(const Profile& profile, GAction action) {
  for (const GCodeSpec& g : profile.gcodes)
    if (g.action == action) return &g;
  return nullptr;
}

cycles::DrillConfig drillConfig(const Profile& profile, const Setup& setup) {
  const cycles::DrillConfig d;
  // asked for every drilled block: one walk over the dialect's settings finds all fourteen (the
  // first row of each, as MachineRules::setting answers)
  std::array<const SettingSpec*, 256> spec{};
  for (const SettingSpec& s : profile.machine.settings)
    if (!spec[static_cast<unsigned char>(s.setting)])
      spec[static_cast<unsigned char>(s.setting)] = &s;
  auto specOf = [&](Setting s) { return spec[static_cast<unsigned char>(s)]; };
  auto value = [&](Setting s, double fallback) { return valueOf(specOf(s), setup, fallback); };
  auto on = [&](Setting s, bool fallback) { return value(s, fallback ? 1 : 0) != 0; };
  cycles::DrillConfig c;
  c.returnG73 = value(Setting::PeckReturn, d.returnG73);
  c.clearanceG83 = value(Setting::PeckClearance, d.clearanceG83);
  c.extractionG85G89 = value(Setting::BoreExtractionPct, d.extractionG85G89);
  c.tapReturn = value(Setting::TapReturn, d.tapReturn);
  c.tapClearance = value(Setting::TapClearance, d.tapClearance);
  c.tapExtraction = value(Setting::TapExtractionPct, d.tapExtraction);
  c.tapReturnOverride = value(Setting::TapReturnPct, d.tapReturnOverride);
  c.tapOrient = on(Setting::TapOrients, d.tapOrient);
  c.tapNormalPeck = on(Setting::TapPeckToR, d.tapNormalPeck);
  c.extractionEnabled = on(Setting::TapExtractionEnabled, d.extractionEnabled);
  c.returnEnabled = on(Setting::TapReturnEnabled, d.returnEnabled);
  c.orient = on(Setting::SpindleOrientable, d.orient);
  c.indexable = on(Setting::SpindleIndexable, d.indexable);
  c.closeLoopMCode = static_cast<int>(value(Setting::CloseLoopMCode, d.closeLoopMCode));
  auto label = [&](Setting s) { return specOf(s) ? specOf(s)->label : ""; };
  c.orientLabel = label(Setting::SpindleOrientable);
  c.indexLabel = label(Setting::SpindleIndexable);
  return c;
}

} // namespace gcx::machine
