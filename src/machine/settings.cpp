#include "machine/settings.h"

namespace gcx::machine {

double setting(const Profile& profile, const Setup& setup, Setting which, double absent) {
  const SettingSpec* s = profile.machine.setting(which);
  if (!s) return absent;
  const double fallback = s->alias ? setup.parameter(s->alias, s->fallback) : s->fallback;
  return setup.parameter(s->key, fallback);
}

const char* settingLabel(const Profile& profile, Setting which) {
  const SettingSpec* s = profile.machine.setting(which);
  return s ? s->label : "";
}

const char* settingKey(const Profile& profile, Setting which) {
  const SettingSpec* s = profile.machine.setting(which);
  return s ? s->key : nullptr;
}

cycles::DrillConfig drillConfig(const Profile& profile, const Setup& setup) {
  const cycles::DrillConfig d;
  auto value = [&](Setting s, double fallback) { return setting(profile, setup, s, fallback); };
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
  c.orientLabel = settingLabel(profile, Setting::SpindleOrientable);
  c.indexLabel = settingLabel(profile, Setting::SpindleIndexable);
  return c;
}

} // namespace gcx::machine
