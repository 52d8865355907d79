// Decimal text for traces and pictures: at most N decimals, trailing zeros dropped, never an
// exponent (so every reader, including line-oriented tools, sees plain numbers), "-0" as "0".
#pragma once
#include <cstddef>
#include <string>

namespace gcx::motion {

/// Appends v rounded to at most `decimals` (0..17) places. Non-finite values are written as
/// "null", which keeps JSON output valid; callers that cannot accept it must check first.
void appendDecimal(std::string& out, double v, int decimals = 6);
/// The same text by std::to_chars alone; appendDecimal takes an integer fast path where it can
/// prove the result equal (tests compare the two).
void appendDecimalExact(std::string& out, double v, int decimals = 6);
std::string formatDecimal(double v, int decimals = 6);
/// A word of a program line: a blank, the letter, then appendDecimal's text, in one append.
void appendWord(std::string& out, char letter, double v, int decimals = 6);
/// The room putWord may write.
inline constexpr std::size_t kWordRoom = 32;
/// appendWord's text written at `to`, which has kWordRoom bytes of room; returns its end. Null,
/// with nothing written, where the number needs std::to_chars: then appendWord writes it.
char* putWord(char* to, char letter, double v, int decimals = 6);

} // namespace gcx::motion
