// Shared by the compensation tests: a setup with the tool radius in register 1, and the motion
// without the end-of-file event.
#pragma once
#include <string>
#include <vector>

#include "machine/setup.h"

namespace gcx::test {

inline machine::Setup compSetup(double radius, double x = 0, double y = 0, double z = 0) {
  machine::Setup s;
  s.initialPosition = {x, y, z};
  s.tools[1].radius = radius;
  return s;
}

inline std::vector<std::string> compMotion(std::vector<std::string> v) {
  if (!v.empty() && v.back().rfind("END", 0) == 0) v.pop_back();
  return v;
}

} // namespace gcx::test
