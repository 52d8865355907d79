// rs274 on a program text, read back as motion events; `failure` says why when it stops.
#pragma once
#include <string>
#include <vector>

#include "motion/event.h"
#include "oracle/canon.h"
#include "oracle/rs274.h"

namespace gcx::test {

inline std::vector<motion::Event> runOracle(const std::string& text,
                                            const oracle::Rs274Options& opt, std::string& failure) {
  const oracle::Rs274Result r = oracle::Rs274(opt).run(text);
  if (!r.ok()) {
    failure = r.summary();
    return {};
  }
  oracle::CanonOptions copt;
  copt.programText = text;
  return oracle::parseCanon(r.canonLines, copt);
}

} // namespace gcx::test
