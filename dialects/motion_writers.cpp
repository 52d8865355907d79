// The writers of flat motion, by dialect (emit/motion_writer.h).
#include "dialects/fms3000/motion_writer.h"
#include "dialects/nct/motion_writer.h"
#include "dialects/wl4/motion_writer.h"

namespace gcx::emit {

MotionWriterMaker motionWriterFor(std::string_view dialect) {
  if (dialect == "nct") return &nct::makeMotionWriter;
  if (dialect == "fms3000") return &fms3000::makeMotionWriter;
  if (dialect == "wl4") return &wl4::makeMotionWriter;
  return nullptr;
}

} // namespace gcx::emit
