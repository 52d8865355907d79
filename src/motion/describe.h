// Motion events as one line of text for reports and test messages: "Feed (0.0000, 0.0000,
// 0.0000) -> (10.0000, 0.0000, 0.0000) F300". Shared by the comparers (gcx equiv and the
// oracle's event-list comparison) so both describe an event alike.
#pragma once
#include <string>

#include "motion/event.h"

namespace gcx::motion {

/// One event as text, coordinates to 4 decimals (rs274's precision).
std::string describeEvent(const Event& e);
/// The kind's name as describeEvent() prints it ("Rapid", "FeedModeChange").
const char* kindLabel(Kind k);

} // namespace gcx::motion
