#include "oracle/compare.h"

#include "motion/describe.h"
#include "motion/geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace gcx::oracle {

using motion::Event;
using motion::Extra;
using motion::Kind;
using motion::Vec3;

namespace {

/// A point in axis space: X Y Z, then A B C U V W (degrees and mm mixed, as rs274 and nct.md
/// §3.4 interpolate them).
using Axes = Eigen::Matrix<double, 9, 1>;

Axes axes(const Vec3& p, const Extra& x) {
  Axes a;
  a << p, x;
  return a;
}

/// A normalised event: possibly several collinear input pieces merged.
struct Item {
  Event e;
  std::size_t first = 0; // index range in the input list
  std::size_t last = 0;
  std::vector<Axes> interior; // joints of merged pieces
};

template <typename V> double maxDiff(const V& a, const V& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

double distanceToSegment(const Axes& p, const Axes& a, const Axes& b) {
  const Axes ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 == 0) return (p - a).norm();
  const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

/// Whether a straight move moves no axis by more than the tolerance.
bool zeroLength(const Event& e, double tol) {
  return maxDiff(e.start, e.end) <= tol && maxDiff(e.extraStart, e.extraEnd) <= tol;
}

bool sameFeed(const Event& a, const Event& b, const CompareOptions& o) {
  if (!o.compareFeed) return true;
  return a.perRevolution == b.perRevolution && std::abs(a.feed - b.feed) <= o.feedTolerance &&
         std::abs(a.lead - b.lead) <= o.feedTolerance;
}

bool tryMerge(Item& it, const Event& e, const CompareOptions& o) {
  if (e.kind != it.e.kind) return false;
  if (e.kind == Kind::Feed ? !o.mergeCollinearFeeds
                           : (e.kind != Kind::Rapid || !o.mergeCollinearRapids))
    return false;
  if (!sameFeed(it.e, e, o)) return false;
  // Collinear in axis space, so pieces that turn a rotary axis merge only when it turns
  // linearly along the whole line.
  const Axes s = axes(it.e.start, it.e.extraStart), joint = axes(it.e.end, it.e.extraEnd);
  const Axes from = axes(e.start, e.extraStart), f = axes(e.end, e.extraEnd);
  if (maxDiff(joint, from) > o.tolerance) return false;
  const Axes dir = f - s;
  if (dir.dot(joint - s) <= 0 || dir.dot(f - from) <= 0) return false;
  if (distanceToSegment(joint, s, f) > o.tolerance) return false;
  for (const Axes& p : it.interior)
    if (distanceToSegment(p, s, f) > o.tolerance) return false;
  it.interior.push_back(joint);
  it.e.end = e.end;
  it.e.extraEnd = e.extraEnd;
  return true;
}

std::vector<Item> normalise(const std::vector<Event>& in, const CompareOptions& o) {
  std::vector<Item> out;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Event& e = in[i];
    if (std::find(o.kinds.begin(), o.kinds.end(), e.kind) == o.kinds.end()) continue;
    if (o.dropZeroLength && (e.kind == Kind::Rapid || e.kind == Kind::Feed) &&
        zeroLength(e, o.tolerance))
      continue;
    if (!out.empty() && tryMerge(out.back(), e, o)) {
      out.back().last = i;
      continue;
    }
    out.push_back(Item{e, i, i, {}});
  }
  return out;
}

std::string where(const Event& e, const SourceManager* sm) {
  std::string s;
  const SourceLoc& at = e.from.at;
  if (sm != nullptr) {
    s = sm->name(at.file);
    if (at.valid()) {
      s += fmt::format(":{}", at.line);
      if (at.col != 0) s += fmt::format(":{}", at.col);
      std::string text = sm->lineText(at, 200);
      while (!text.empty() && (text.back() == '\r' || text.back() == ' '))
        text.pop_back();
      if (!text.empty()) s += fmt::format(" \"{}\"", text);
    }
  } else {
    s = at.valid() ? fmt::format("line {}", at.line) : std::string("line ?");
  }
  for (auto it = e.from.chain.rbegin(); it != e.from.chain.rend(); ++it)
    s += fmt::format(" (in {} from line {})", it->what, it->call.line);
  return s;
}

std::string describeItem(const Item& it, const char* side, const SourceManager* sm) {
  std::string pieces;
  if (it.last > it.first)
    pieces = fmt::format(" [{} collinear pieces, events #{}..#{}]", it.last - it.first + 1,
                         it.first, it.last);
  return fmt::format("  {:<6} #{} {}:\n           {}{}", side, it.first, where(it.e, sm),
                     motion::describeEvent(it.e), pieces);
}

/// Empty if a and b match, else why not.
std::string mismatch(const Event& a, const Event& b, const CompareOptions& o) {
  if (a.kind != b.kind)
    return fmt::format("different kinds: {} vs {}", motion::kindLabel(a.kind),
                       motion::kindLabel(b.kind));
  const double tol = o.tolerance;
  switch (a.kind) {
  case Kind::Rapid:
  case Kind::Feed:
  case Kind::Arc: {
    if (double d = maxDiff(a.start, b.start); d > tol)
      return fmt::format("start points differ by {:.6f} mm (tolerance {})", d, tol);
    if (double d = maxDiff(a.end, b.end); d > tol)
      return fmt::format("end points differ by {:.6f} mm (tolerance {})", d, tol);
    for (int i = 0; i < 6; ++i) {
      const char* unit = i < 3 ? "deg" : "mm";
      const char name = motion::kExtraAxisNames[i];
      if (double d = std::abs(a.extraStart[i] - b.extraStart[i]); d > tol)
        return fmt::format("{} at the start differs by {:.6f} {} (tolerance {})", name, d, unit,
                           tol);
      if (double d = std::abs(a.extraEnd[i] - b.extraEnd[i]); d > tol)
        return fmt::format("{} at the end differs by {:.6f} {} (tolerance {})", name, d, unit, tol);
    }
    if (a.kind == Kind::Arc) {
      if (a.plane != b.plane)
        return fmt::format("arc planes differ: {} vs {}", motion::planeCode(a.plane),
                           motion::planeCode(b.plane));
      if (a.clockwise != b.clockwise)
        return fmt::format("arc directions differ: {} vs {}", a.clockwise ? "CW" : "CCW",
                           b.clockwise ? "CW" : "CCW");
      if (a.turns != b.turns)
        return fmt::format("extra full turns differ: {} vs {}", a.turns, b.turns);
      if (double d = maxDiff(a.center, b.center); d > tol)
        return fmt::format("arc centres differ by {:.6f} mm (tolerance {})", d, tol);
    }
    if (a.kind != Kind::Rapid && o.compareFeed) {
      if (a.perRevolution != b.perRevolution)
        return fmt::format("feed modes differ: {} vs {}", a.perRevolution ? "per rev" : "per min",
                           b.perRevolution ? "per rev" : "per min");
      if (std::abs(a.feed - b.feed) > o.feedTolerance)
        return fmt::format("feeds differ: {} vs {}", a.feed, b.feed);
      if (std::abs(a.lead - b.lead) > o.feedTolerance)
        return fmt::format("spindle-synchronised leads differ: {} vs {} mm/rev", a.lead, b.lead);
    }
    return {};
  }
  case Kind::Dwell:
    if (a.perRevolution != b.perRevolution) return "dwell units differ (seconds vs revolutions)";
    if (std::abs(a.value - b.value) > o.dwellTolerance)
      return fmt::format("dwell times differ: {} vs {}", a.value, b.value);
    return {};
  case Kind::Spindle:
    if (a.direction != b.direction || std::abs(a.value - b.value) > 1e-6)
      return "spindle states differ";
    return {};
  case Kind::ToolChange:
  case Kind::Coolant:
  case Kind::SpindleOrient:
  case Kind::OverrideLock:
  case Kind::RadiusComp:
    if (std::abs(a.value - b.value) > 1e-6) return "values differ";
    return {};
  case Kind::Stop:
    if (a.optional != b.optional) return "optional flags differ";
    return {};
  case Kind::End:
    return {};
  case Kind::Message:
    if (a.text != b.text) return "message texts differ";
    return {};
  case Kind::PlaneChange:
    if (a.plane != b.plane || a.text != b.text) return "planes differ";
    return {};
  case Kind::UnitsChange:
  case Kind::FeedModeChange:
    if (a.value != b.value) return "codes differ";
    return {};
  }
  return {};
}

} // namespace

CompareResult compareEvents(const std::vector<Event>& left, const std::vector<Event>& right,
                            const CompareOptions& o) {
  const std::vector<Item> l = normalise(left, o), r = normalise(right, o);
  CompareResult res;
  const std::size_t n = std::min(l.size(), r.size());
  for (std::size_t i = 0; i < n; ++i) {
    const std::string why = mismatch(l[i].e, r[i].e, o);
    if (why.empty()) {
      ++res.matched;
      continue;
    }
    res.leftIndex = l[i].first;
    res.rightIndex = r[i].first;
    res.report = fmt::format("first divergence after {} matching events: {}\n{}\n{}", i, why,
                             describeItem(l[i], o.leftName.c_str(), o.leftSources),
                             describeItem(r[i], o.rightName.c_str(), o.rightSources));
    return res;
  }
  if (l.size() == r.size()) {
    res.equivalent = true;
    return res;
  }
  const bool leftLonger = l.size() > r.size();
  const Item& extra = leftLonger ? l[n] : r[n];
  (leftLonger ? res.leftIndex : res.rightIndex) = extra.first;
  res.report = fmt::format(
      "first divergence after {} matching events: {} ended, {} has {} more event(s):\n{}", n,
      leftLonger ? o.rightName : o.leftName, leftLonger ? o.leftName : o.rightName,
      (leftLonger ? l.size() : r.size()) - n,
      describeItem(extra, (leftLonger ? o.leftName : o.rightName).c_str(),
                   leftLonger ? o.leftSources : o.rightSources));
  return res;
}

} // namespace gcx::oracle
