#include "emit/emitter.h"

namespace gcx::emit {

std::string_view constructName(Construct c) {
  switch (c) {
  case Construct::CannedCycles:
    return "cycles";
  case Construct::Subprograms:
    return "subprograms";
  case Construct::Loops:
    return "loops";
  case Construct::Variables:
    return "variables";
  case Construct::ModalCalls:
    return "modal calls";
  }
  return "";
}

} // namespace gcx::emit
