// Numbers as G-code text: the shortest form that reads back to the same double, never with an
// exponent (no dialect accepts one), "-0" written as "0".
#pragma once
#include <string>

namespace gcx::emit {

std::string formatNumber(double v);
void appendNumber(std::string& out, double v);

} // namespace gcx::emit
