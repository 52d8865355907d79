#include "dialects/nct/word_value_rules.h"

namespace gcx::nct {

/// | address                                    | rounding   | range           |
/// |--------------------------------------------|------------|-----------------|
/// | G                                          | Tenth      | 0 .. 9999.9     |
/// | M T L                                      | Integer    | 0 .. 99999999   |
/// | H D                                        | Integer    | 0 .. 999        |
/// | N                                          | Integer    | 1 .. 99999999   |
/// | P (call number)                            | Integer    | 1 .. 99999999   |
/// | S (call number)                            | Integer    | 0 .. 99999999   |
/// | X Y Z U V W A B C I J K R E ,C ,R ,A AX    | Resolution | any finite      |
/// | F                                          | None       | 0 .. any finite |
/// | S                                          | None       | 0 .. 99999999   |
/// | P Q, any other address                     | None       | any finite      |
/// M0 H0 D0 L0 T0 pass (§2.6, §12 Q29). A multi-letter axis name starting with X Y Z U V W A B C
/// takes the coordinate row. Coordinates round to 1e-6 mm and degree (§2.6, §12 Q18).
WordValueRules wordValueRules() {
  constexpr double big = 99999999, any = anyValue;
  constexpr Rounding integer = Rounding::Integer, coordinate = Rounding::Resolution;
  WordValueRules r;
  r.rows = {
      {"G", false, Rounding::Tenth, 0, 9999.9},
      {"M", false, integer, 0, big},
      {"T", false, integer, 0, big},
      {"L", false, integer, 0, big},
      {"H", false, integer, 0, 999},
      {"D", false, integer, 0, 999},
      {"N", false, integer, 1, big},
      {"P", true, integer, 1, big},
      {"S", true, integer, 0, big},
      {"F", false, Rounding::None, 0, any},
      {"S", false, Rounding::None, 0, big},
  };
  for (std::string_view a : {"X", "Y", "Z", "U", "V", "W", "A", "B", "C", "I", "J", "K", "R", "E",
                             ",C", ",R", ",A", "AX"})
    r.rows.push_back({a, false, coordinate, -any, any});
  r.coordinateLetters = "XYZUVWABC";
  r.coordinateRow = "X";
  r.resolution = 1e-6;
  r.reference = "nct-macro.md §2.6";
  return r;
}

} // namespace gcx::nct
