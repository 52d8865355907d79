// WL4 as the target of a translation from another dialect: the executed motion in its syntax
// (translate/flat_writer.h).
#pragma once
#include "emit/motion_writer.h"

namespace gcx::wl4 {

std::unique_ptr<emit::MotionWriter>
makeMotionWriter(std::ostream& out, const emit::MotionWriterOptions& opt, diag::Engine& diags);

} // namespace gcx::wl4
