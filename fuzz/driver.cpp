// The libFuzzer driver of every target: GCX_FUZZ_TARGET names the entry point (entry_points.h).
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz/entry_points.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const gcx::fuzz::Outcome out = gcx::fuzz::runTarget(
      GCX_FUZZ_TARGET, std::string_view(reinterpret_cast<const char*>(data), size));
  if (!out.violation.empty()) {
    std::fprintf(stderr, "property violated: %s\n", out.violation.c_str());
    std::abort();
  }
  return 0;
}
