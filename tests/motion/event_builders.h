// Short constructors for motion events in tests.
#pragma once
#include <vector>

#include "motion/event.h"

namespace gcx::motion::test {

inline Event move(Kind kind, Vec3 from, Vec3 to, double feed = 0) {
  Event e;
  e.kind = kind;
  e.start = from;
  e.end = to;
  e.feed = feed;
  return e;
}
inline Event rapid(Vec3 from, Vec3 to) {
  return move(Kind::Rapid, from, to);
}
inline Event feed(Vec3 from, Vec3 to, double f = 100) {
  return move(Kind::Feed, from, to, f);
}

inline Event arc(Plane plane, Vec3 from, Vec3 to, Vec3 centre, bool cw, int turns = 0,
                 double f = 100) {
  Event e = move(Kind::Arc, from, to, f);
  e.plane = plane;
  e.center = centre;
  e.clockwise = cw;
  e.turns = turns;
  return e;
}

/// A B C (degrees) and U V W (mm).
inline Extra extra(double a, double b, double c, double u = 0, double v = 0, double w = 0) {
  Extra x;
  x << a, b, c, u, v, w;
  return x;
}
inline Event withExtra(Event e, const Extra& from, const Extra& to) {
  e.extraStart = from;
  e.extraEnd = to;
  return e;
}

inline Event valueEvent(Kind kind, double value, bool perRevolution = false) {
  Event e;
  e.kind = kind;
  e.value = value;
  e.perRevolution = perRevolution;
  return e;
}

/// A sink that keeps every event and whether finish() came.
struct Collect : Sink {
  std::vector<Event> events;
  bool finished = false;
  void event(const Event& e) override { events.push_back(e); }
  void finish() override { finished = true; }
};

} // namespace gcx::motion::test
