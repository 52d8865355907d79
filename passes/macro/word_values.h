// NC words whose value is a variable or expression (`X#1`, `XI-#24`, `Y[#1+10]`, `G#102`): the
// vacant rule of nct-macro.md §2.5 rule 4, the rounding of §2.6 and the address range check.
#pragma once
#include <optional>
#include <string_view>

#include "ir/block.h"
#include "passes/macro/evaluator.h"

namespace gcx::macro {

/// How a value given to an address is rounded (nct-macro.md §2.6); ties away from zero.
enum class Rounding : unsigned char {
  Integer,    // M T H D L N, P as program / sequence number, S as call number
  Tenth,      // G: one decimal (G#1 with 84.2 -> G84.2, with 1.04 -> G1)
  Resolution, // coordinates: WordOptions::resolution
  None,       // F, S, P (dwell), Q
};

/// One row of the address table: rounding, then the inclusive range the rounded value must lie
/// in (§1.2, §2.6). min >= 0 means the address takes no sign. The table (word_values.cpp):
///
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
///
/// M0 H0 D0 L0 T0 pass (§2.6, §12 Q29). A multi-letter axis name starting with X Y Z U V W A B C
/// takes the coordinate row.
struct AddressRule {
  std::string_view address;
  bool callNumber; // the row of P / S used as a program, sequence or call number
  Rounding rounding;
  double min;
  double max;
};

const AddressRule& addressRule(std::string_view address, bool callNumber = false);

struct WordOptions {
  /// Coordinate resolution (profile setting nct.coord_resolution): 1e-6 mm and degree,
  /// 1e-7 inch (§2.6, §12 Q18).
  double resolution = 1e-6;
  /// P is a program or sequence number of a call or return (the remap row says so), S a
  /// configured call.
  bool callNumber = false;
};

enum class WordResult : unsigned char {
  Value,   // number holds the rounded, range-checked value
  Dropped, // a bare variable reference that is vacant: the word leaves the block (§2.5 rule 4)
  Error,   // reported
};

struct WordValue {
  WordResult result = WordResult::Error;
  double number = 0;
};

/// Resolves the value of w. A literal word is returned unchanged (the static checks own it).
/// `A#n`, `A-#n`, `AI#n`, `AI-#n`, `A#[e]`, `A#_NAME` drop the word when vacant; `A[e]`, `A-[e]`
/// are always a number (vacant = 0). w.incremental is left to the caller.
WordValue wordValue(const ir::Word& w, Evaluator& ev, const WordOptions& opt = {});

/// Rounds v for address per the table and checks its range: nullopt after reporting NCTX04 at
/// where. -0 comes back as 0.
std::optional<double> addressValue(double v, std::string_view address, const SourceRange& where,
                                   diag::Engine& diags, const WordOptions& opt = {});

} // namespace gcx::macro
