#include "dialects/nct/profile.h"

#include "diag/diagnostic.h"
#include "dialects/nct/arguments.h"

namespace gcx::nct {

namespace {

Profile build() {
  Profile p;
  p.name = "nct";
  const double big = 99999999;
  auto coord = [](const char* a, const char* meaning) {
    return AddressSpec{a, true, true, true, -1e300, 1e300, false, meaning};
  };
  auto aux = [](const char* a, const char* meaning) {
    return AddressSpec{a, true, true, false, -1e300, 1e300, false, meaning};
  };
  auto integer = [](const char* a, double lo, double hi, const char* meaning) {
    return AddressSpec{a, false, false, false, lo, hi, false, meaning};
  };
  // nct.md §1.3, address table 000:33-85; ranges per nct-macro.md §1.2 and §2.6 (0 allowed
  // for M, H, D, L, T: M0, H0/D0, M99 L0 are documented codes).
  p.addresses = {
      integer("O", 0, big, "program number"),
      integer("N", 1, big, "block number"),
      AddressSpec{"G", true, false, false, 0, 9999.9, true, "preparatory function"},
      coord("X", "linear coordinate"),
      coord("Y", "linear coordinate"),
      coord("Z", "linear coordinate"),
      coord("U", "linear coordinate / incremental X"),
      coord("V", "linear coordinate / incremental Y"),
      coord("W", "linear coordinate / incremental Z"),
      coord("A", "angular coordinate"),
      coord("B", "angular coordinate"),
      coord("C", "angular coordinate"),
      coord("R", "arc radius, auxiliary data"),
      aux("I", "arc centre, auxiliary coordinate"),
      aux("J", "arc centre, auxiliary coordinate"),
      aux("K", "arc centre, auxiliary coordinate"),
      aux("E", "auxiliary coordinate"),
      AddressSpec{"F", true, false, false, 0, 1e300, false, "feed"},
      AddressSpec{"S", true, false, false, 0, big, false, "spindle speed"},
      AddressSpec{"M", false, false, false, 0, big, true, "miscellaneous function"},
      integer("T", 0, big, "tool number"),
      integer("H", 0, 999, "length offset number"),
      integer("D", 0, 999, "radius offset number"),
      integer("L", 0, big, "repetition count"),
      aux("P", "auxiliary data, dwell, program number"),
      aux("Q", "auxiliary data"),
      aux(",C", "chamfer"),
      aux(",R", "corner rounding radius"),
      aux(",A", "line direction angle"),
      AddressSpec{"AX", true, true, true, -1e300, 1e300, true, "axis given by its number"},
      AddressSpec{"<>", false, false, false, 0, 0, false, "program file of M98 / G65"},
  };
  // nct.md §2.1 (000:490-905) with the groups of nct-macro.md §2.9.4 (000:12690-12800).
  p.gcodes = {
      {0, 1, "rapid positioning"},
      {10, 1, "linear interpolation"},
      {20, 1, "circular interpolation CW"},
      {30, 1, "circular interpolation CCW"},
      {330, 1, "thread cutting"},
      {40, 0, "dwell"},
      {51, 0, "smoothing"},
      {71, 0, "cylindrical interpolation"},
      {90, 0, "exact stop"},
      {100, 0, "data input"},
      {109, 0, "radius/diameter switch"},
      {110, 0, "end of data input"},
      {121, 21, "polar interpolation on"},
      {131, 21, "polar interpolation off"},
      {150, 17, "polar coordinates off"},
      {160, 17, "polar coordinates on"},
      {170, 2, "plane XY"},
      {180, 2, "plane ZX"},
      {190, 2, "plane YZ"},
      {200, 6, "inch"},
      {210, 6, "metric"},
      {220, 4, "stroke limit on"},
      {230, 4, "stroke limit off"},
      {280, 0, "reference return"},
      {300, 0, "2nd/3rd/4th reference return"},
      {310, 0, "skip"},
      {370, 0, "tool length measurement"},
      {380, 0, "keep compensation vector"},
      {390, 0, "corner arc"},
      {400, 7, "radius compensation off"},
      {410, 7, "radius compensation left"},
      {420, 7, "radius compensation right"},
      {430, 8, "length compensation +"},
      {440, 8, "length compensation -"},
      {431, 8, "length compensation along tool axis"},
      {434, 8, "TCP type 1"},
      {435, 8, "TCP type 2"},
      {437, 8, "turning offsets"},
      {438, 8, "turning point control"},
      {439, 8, "turning point control"},
      {490, 8, "length compensation off"},
      {500, 11, "scaling off"},
      {510, 11, "scaling on"},
      {501, 22, "mirror off"},
      {511, 22, "mirror on"},
      {502, 31, "polygon turning off"},
      {512, 31, "polygon turning on"},
      {520, 0, "local coordinate system"},
      {530, 0, "machine coordinates"},
      {531, 0, "tool axis direction"},
      {536, 0, "tool axis direction"},
      {540, 14, "work offset 1"},
      {541, 14, "extended work offset"},
      {542, 14, "dynamic work offset"},
      {550, 14, "work offset 2"},
      {560, 14, "work offset 3"},
      {570, 14, "work offset 4"},
      {580, 14, "work offset 5"},
      {590, 14, "work offset 6"},
      {610, 15, "exact stop mode"},
      {620, 15, "inner corner override"},
      {630, 15, "tapping mode"},
      {640, 15, "continuous mode"},
      {650, 0, "macro call"},
      {660, 12, "modal macro call"},
      {661, 12, "modal macro call, every block"},
      {670, 12, "modal macro call off"},
      {680, 16, "rotation on"},
      {690, 16, "rotation off"},
      {681, 18, "3-D rotation"},
      {682, 18, "tilted working plane"},
      {691, 18, "3-D rotation off"},
      {707, 0, "finishing cycle"},
      {717, 0, "stock removal in turning"},
      {727, 0, "stock removal in facing"},
      {737, 0, "pattern repeating"},
      {747, 0, "end face peck drilling"},
      {757, 0, "outer/inner diameter drilling"},
      {767, 0, "multiple thread cutting"},
      {777, 1, "turning cycle"},
      {787, 1, "thread cutting cycle"},
      {797, 1, "facing cycle"},
      {730, 9, "peck drilling"},
      {740, 9, "counter tapping"},
      {760, 9, "fine boring"},
      {800, 9, "cycle cancel"},
      {810, 9, "drilling"},
      {820, 9, "counter boring"},
      {830, 9, "peck drilling"},
      {840, 9, "tapping"},
      {842, 9, "rigid tapping"},
      {843, 9, "rigid counter tapping"},
      {850, 9, "boring"},
      {860, 9, "boring"},
      {870, 9, "back boring"},
      {880, 9, "boring"},
      {890, 9, "boring"},
      {808, 34, "electronic gear box off"},
      {818, 34, "electronic gear box on"},
      {900, 3, "absolute"},
      {910, 3, "incremental"},
      {920, 0, "set work coordinates"},
      {940, 5, "feed per minute"},
      {950, 5, "feed per revolution"},
      {960, 13, "constant surface speed"},
      {970, 13, "constant surface speed off"},
      {980, 10, "return to initial level"},
      {990, 10, "return to R level"},
  };
  p.exclusiveMCodes = {3, 4, 5, 19};   // one spindle command per block (000:4278-4280)
  p.dataModeLCodes = {52, 75, 76, 77}; // G10 L52 parameters, L75-77 tool tables (nct.md §1.10)
  p.macroCallGCodes10 = {650, 660, 661};
  p.checkCallArguments = [](const ir::Block& b, diag::Engine& diags) {
    // statically only literal values are known; a variable may be vacant and skip its slot
    auto runtime = [](const ir::Word& w) { return !w.isLiteral(); };
    auto vacant = [](const ir::Word&) { return false; };
    ArgumentResult r = bindArguments(b, vacant, runtime);
    if (!r.ok()) diags.error(r.code, r.offending->range, r.message);
  };
  p.index();
  return p;
}

} // namespace

const Profile& profile() {
  static const Profile p = build();
  return p;
}

} // namespace gcx::nct
