#include "machine/cycle_state.h"

#include "machine/interpreter.h"

namespace gcx::machine {

CycleStateBox::CycleStateBox() : state_(std::make_unique<CycleState>()) {}
CycleStateBox::~CycleStateBox() = default;
CycleStateBox::CycleStateBox(const CycleStateBox& other)
    : state_(std::make_unique<CycleState>(*other.state_)) {}
CycleStateBox& CycleStateBox::operator=(const CycleStateBox& other) {
  *state_ = *other.state_;
  return *this;
}

} // namespace gcx::machine
