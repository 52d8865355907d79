// The libFuzzer driver of every target (entry_points.h): the environment variable
// GCX_FUZZ_TARGET names the target; GCX_FUZZ_TARGET=list prints each target's name and the
// extension of the files that seed it, and exits.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz/entry_points.h"

namespace {
std::string target;
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* name = std::getenv("GCX_FUZZ_TARGET");
  if (!name || !*name) {
    std::fprintf(stderr, "set GCX_FUZZ_TARGET to a target, or to list\n");
    std::exit(2);
  }
  target = name;
  const auto& names = gcx::fuzz::targetNames();
  if (target == "list") {
    for (const std::string& n : names)
      std::printf("%s %s\n", n.c_str(), gcx::fuzz::seedExtension(n).c_str());
    std::exit(0);
  }
  for (const std::string& n : names)
    if (n == target) return 0;
  std::fprintf(stderr, "GCX_FUZZ_TARGET=%s: no such target (GCX_FUZZ_TARGET=list names them)\n",
               name);
  std::exit(2);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const gcx::fuzz::Outcome out =
      gcx::fuzz::runTarget(target, std::string_view(reinterpret_cast<const char*>(data), size));
  if (!out.violation.empty()) {
    std::fprintf(stderr, "property violated: %s\n", out.violation.c_str());
    std::abort();
  }
  return 0;
}
