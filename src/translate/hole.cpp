#include "translate/hole.h"

#include <cmath>
#include <vector>

namespace gcx::xlate {

using motion::Event;
using motion::Kind;

namespace {

constexpr double kEps = 1e-6; // mm: the events of one cycle share their coordinates exactly

bool same(double a, double b) {
  return std::fabs(a - b) < kEps;
}

bool extraStill(const Event& e) {
  return e.extraStart == e.extraEnd;
}

bool alongZ(const Event& e) {
  return same(e.start.x(), e.end.x()) && same(e.start.y(), e.end.y()) && extraStill(e) &&
         !same(e.start.z(), e.end.z());
}

bool inPlane(const Event& e) {
  return same(e.start.z(), e.end.z()) && extraStill(e) &&
         (!same(e.start.x(), e.end.x()) || !same(e.start.y(), e.end.y()));
}

bool plainFeed(const Event& e) {
  return e.kind == Kind::Feed && e.lead == 0 && !e.perRevolution && alongZ(e);
}

bool sameLoc(const SourceLoc& a, const SourceLoc& b) {
  return a.file == b.file && a.offset == b.offset && a.line == b.line;
}

bool sameChain(const motion::Provenance& a, const motion::Provenance& b) {
  if (a.chain.size() != b.chain.size()) return false;
  for (std::size_t i = 0; i < a.chain.size(); ++i)
    if (!sameLoc(a.chain[i].call, b.chain[i].call) || a.chain[i].what != b.chain[i].what)
      return false;
  return true;
}

bool sameBlock(const motion::Provenance& a, const motion::Provenance& b) {
  return sameLoc(a.at, b.at) && sameChain(a, b);
}

} // namespace

std::string_view holeKindName(HoleKind k) {
  switch (k) {
  case HoleKind::Drill:
    return "drilling";
  case HoleKind::DrillDwell:
    return "drilling with dwell";
  case HoleKind::BoreFeedOut:
    return "boring with feed out";
  case HoleKind::Peck:
    return "peck drilling";
  case HoleKind::ChipBreak:
    return "chip-breaking drilling";
  }
  return "drilling";
}

HoleMatch matchHole(std::span<const Event> events, bool complete, const Event* before) {
  HoleMatch m;
  const HoleMatch::Status incomplete = complete ? HoleMatch::NoHole : HoleMatch::NeedMore;
  const std::size_t n = events.size();
  Hole& h = m.hole;
  std::size_t i = 0;
  if (n > 0 && events[0].kind == Kind::Rapid && inPlane(events[0])) {
    h.positioned = true;
    i = 1;
  }
  if (i == n) {
    m.status = h.positioned ? incomplete : HoleMatch::NoHole;
    return m;
  }
  const std::size_t core = i;
  const Event& first = events[i];
  h.x = first.start.x();
  h.y = first.start.y();
  h.start = h.r = first.start.z();
  if (first.kind == Kind::Rapid && alongZ(first) && first.end.z() < first.start.z()) {
    h.r = first.end.z();
    if (++i == n) return m.status = incomplete, m;
  }
  if (!plainFeed(events[i]) || events[i].end.z() > h.r - kEps) return m; // not one feed down
  h.bottom = events[i].end.z();
  h.feed = events[i].feed;
  if (++i == n) return m.status = incomplete, m;
  // pecks (NCT G83, FMS-3000 G83, WL4 %83): back to R, a rapid down to the last depth plus a
  // clearance, the next feed down
  std::vector<double> depths{h.bottom};
  while (events[i].kind == Kind::Rapid && alongZ(events[i]) && same(events[i].end.z(), h.r)) {
    if (i + 1 == n && !complete) return m.status = HoleMatch::NeedMore, m;
    if (i + 1 == n) break;
    const Event& down = events[i + 1];
    if (down.kind != Kind::Rapid || !alongZ(down) || down.end.z() > h.r - kEps ||
        down.end.z() < h.bottom + kEps)
      break; // the way out
    if (i + 2 == n && !complete) return m.status = HoleMatch::NeedMore, m;
    if (i + 2 == n) break;
    const Event& feed = events[i + 2];
    const double clearance = down.end.z() - h.bottom;
    if (!plainFeed(feed) || feed.end.z() > h.bottom - kEps || !same(feed.feed, h.feed) ||
        (h.clearance > 0 && !same(clearance, h.clearance)))
      break;
    h.clearance = clearance;
    h.bottom = feed.end.z();
    depths.push_back(h.bottom);
    if ((i += 3) == n) return m.status = incomplete, m;
  }
  // chip breaking (NCT G73, FMS-3000 G86): a rapid back by a little, the next feed down
  while (depths.size() == 1 || h.backOff > 0) {
    const Event& back = events[i];
    if (back.kind != Kind::Rapid || !alongZ(back) || back.end.z() < h.bottom + kEps ||
        back.end.z() > h.r - kEps)
      break;
    if (i + 1 == n && !complete) return m.status = HoleMatch::NeedMore, m;
    if (i + 1 == n) return m;
    const Event& feed = events[i + 1];
    const double backOff = back.end.z() - h.bottom;
    if (!plainFeed(feed) || feed.end.z() > h.bottom - kEps || !same(feed.feed, h.feed) ||
        (h.backOff > 0 && !same(backOff, h.backOff)))
      return m;
    h.backOff = backOff;
    h.bottom = feed.end.z();
    depths.push_back(h.bottom);
    if ((i += 2) == n) return m.status = incomplete, m;
  }
  if (depths.size() > 1) { // equal pecks from R, the last one to the bottom
    h.peck = h.r - depths.front();
    for (std::size_t k = 0; k + 1 < depths.size(); ++k)
      if (!same(depths[k], h.r - h.peck * static_cast<double>(k + 1))) return m;
    if (depths.back() < h.r - h.peck * static_cast<double>(depths.size()) - kEps) return m;
  }
  if (events[i].kind == Kind::Dwell && !events[i].perRevolution) {
    h.dwell = events[i].value;
    if (++i == n) return m.status = incomplete, m;
  }
  const Event& out = events[i];
  if (!alongZ(out) || out.end.z() < h.r - kEps) return m;
  if (depths.size() > 1) {
    if (out.kind != Kind::Rapid || h.dwell > 0) return m;
    h.kind = h.backOff > 0 ? HoleKind::ChipBreak : HoleKind::Peck;
  } else if (out.kind == Kind::Rapid) {
    h.kind = h.dwell > 0 ? HoleKind::DrillDwell : HoleKind::Drill;
  } else if (plainFeed(out) && same(out.end.z(), h.r) && h.dwell == 0) {
    h.kind = HoleKind::BoreFeedOut;
    h.retractFeed = out.feed;
  } else {
    return m;
  }
  h.exit = out.end.z();
  ++i;
  // one cycle made it: one block (NCT, FMS-3000), or one call of a cycle program (WL4 %81)
  const motion::Provenance& from = events[core].from;
  bool oneBlock = true, oneCall = !from.chain.empty();
  for (std::size_t k = core; k < i; ++k) {
    oneBlock = oneBlock && sameBlock(events[k].from, from);
    oneCall = oneCall && sameChain(events[k].from, from);
  }
  if (h.positioned && !oneBlock && sameChain(events[0].from, from)) oneCall = false;
  if (!oneBlock && !oneCall) return m;
  auto ofTheCycle = [&](const Event& e) {
    return oneBlock ? sameBlock(e.from, from) : sameChain(e.from, from);
  };
  // from R the cycle's rapid on to the exit level (FMS-3000 I, NCT G98 after a feed out)
  if (same(h.exit, h.r)) {
    if (i == n && !complete) return m.status = HoleMatch::NeedMore, m;
    if (i < n && events[i].kind == Kind::Rapid && alongZ(events[i]) &&
        events[i].end.z() > h.r + kEps && ofTheCycle(events[i])) {
      h.exit = events[i].end.z();
      ++i;
    }
  }
  if (i == n && !complete) return m.status = HoleMatch::NeedMore, m;
  // the whole cycle or nothing: no move of it before or after the hole
  if ((i < n && ofTheCycle(events[i])) || (before && ofTheCycle(*before))) return m;
  h.at = oneBlock ? from.at : from.chain.back().call;
  m.status = HoleMatch::Found;
  m.length = i;
  return m;
}

cycles::DrillCycle drillCycleOf(HoleKind k) {
  switch (k) {
  case HoleKind::Drill:
    return cycles::DrillCycle::Drill;
  case HoleKind::DrillDwell:
    return cycles::DrillCycle::DrillDwell;
  case HoleKind::BoreFeedOut:
    return cycles::DrillCycle::BoreFeedOut;
  case HoleKind::Peck:
    return cycles::DrillCycle::PeckDrill;
  case HoleKind::ChipBreak:
    return cycles::DrillCycle::HighSpeedPeck;
  }
  return cycles::DrillCycle::Drill;
}

} // namespace gcx::xlate
