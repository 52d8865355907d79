#include "equiv/walker.h"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "motion/describe.h"

namespace gcx::equiv {

using motion::Event;
using motion::Kind;

bool ListSource::next(Event& e) {
  if (i_ >= events_.size()) return false;
  e = events_[i_++];
  return true;
}

const char* kindName(DivergenceKind k) {
  switch (k) {
  case DivergenceKind::Geometry:
    return "geometry";
  case DivergenceKind::State:
    return "state";
  case DivergenceKind::Event:
    return "event";
  case DivergenceKind::Ended:
    return "ended";
  }
  return "?";
}

namespace {

/// Dwells, stops and tool changes are compared in order; spindle and coolant are state; the
/// rest (messages, modal changes, M19, override locks, the program end) do not move the tool.
bool isDiscrete(Kind k) {
  return k == Kind::Dwell || k == Kind::Stop || k == Kind::ToolChange;
}
bool isMove(Kind k) {
  return k == Kind::Rapid || k == Kind::Feed || k == Kind::Arc;
}

double maxAbs(const Vec3& v) {
  return v.cwiseAbs().maxCoeff();
}

/// One side of the walk: its current item (a piece and how far along it, a discrete event, or
/// the end), the piece before it (for reports), the running state and statistics.
class Side {
public:
  enum class Type { Piece, Discrete, End };

  Side(EventSource& src, const WalkOptions& o, double rapidRate)
      : src_(src), o_(o), stats_(motion::StatsOptions{rapidRate}) {}

  Type type = Type::End;
  std::optional<Piece> piece;
  double t = 0; // along piece
  Event event;  // Discrete
  std::optional<Piece> prev;
  SideSummary summary;

  double remaining() const { return piece->lengthFrom(t); }
  bool mid() const { return type == Type::Piece && t > 0; }

  /// Leaves the current item (a finished piece becomes prev) and reads the next one.
  void advance() {
    if (type == Type::Piece) {
      beforePrev_ = before_;
      prev = std::move(piece);
      ++summary.segments;
    } else if (type == Type::Discrete) {
      ++summary.events;
    }
    piece.reset();
    t = 0;
    load();
  }
  /// The summary "up to the difference": what came before the item the report names (the
  /// previous piece when `namesPrev`, else the current item), so an identical prefix counts the
  /// same on both sides however far each has read. A side that ended counts everything.
  void finishStats(bool diverged) {
    summary.stats = stats_.stats();
    if (!diverged || (type == Type::End && !namesPrev)) return;
    const Mark& m = namesPrev ? beforePrev_ : before_;
    summary.stats = m.stats;
    summary.segments = m.segments;
    summary.events = m.events;
  }
  bool namesPrev = false; // the divergence names prev rather than the current item

private:
  /// Statistics and counts before an item's first event.
  struct Mark {
    motion::Stats stats;
    std::size_t segments = 0, events = 0;
  };

  /// The next event; counted in the statistics by count() once it is consumed, so an event
  /// read ahead of a rapid run (pending_) counts only when its own item is read.
  bool pull(Event& e) {
    if (pending_) {
      e = std::move(*pending_);
      pending_.reset();
      return true;
    }
    return src_.next(e);
  }
  void count(const Event& e) { stats_.event(e); }
  /// e starts the current item.
  void countFirst(const Event& e) {
    before_ = Mark{stats_.stats(), summary.segments, summary.events};
    count(e);
  }

  bool zeroLength(const Event& e) const {
    if (e.kind == Kind::Arc) return motion::pathLength(e) <= o_.tolerance * 1e-3;
    return maxAbs(e.end - e.start) <= o_.tolerance * 1e-3 &&
           (e.extraEnd - e.extraStart).cwiseAbs().maxCoeff() <= o_.tolerance * 1e-3;
  }

  void load() {
    Event e;
    while (pull(e)) {
      if (isDiscrete(e.kind) || (isMove(e.kind) && !zeroLength(e)))
        countFirst(e);
      else
        count(e);
      switch (e.kind) {
      case Kind::Spindle:
        state_.spindleSpeed = e.value;
        state_.spindleDirection = e.direction;
        state_.spindleSetAt = e.from.at;
        continue;
      case Kind::Coolant:
        if (e.value == 7) state_.mist = true;
        if (e.value == 8) state_.flood = true;
        if (e.value == 9) state_.mist = state_.flood = false;
        state_.coolantSetAt = e.from.at;
        continue;
      case Kind::ToolChange:
        state_.tool = static_cast<int>(e.value);
        break;
      default:
        break;
      }
      if (isDiscrete(e.kind)) {
        type = Type::Discrete;
        event = std::move(e);
        return;
      }
      if (!isMove(e.kind) || zeroLength(e)) continue;
      MotionState s = state_;
      s.rapid = e.kind == Kind::Rapid;
      if (!s.rapid) {
        s.feed = e.feed;
        s.perRevolution = e.perRevolution;
        s.lead = e.lead;
      }
      type = Type::Piece;
      if (s.rapid && !o_.strictRapids) {
        piece = rapidRun(e, s);
      } else {
        piece.emplace(e, s);
      }
      return;
    }
    type = Type::End;
  }

  /// A run of rapids with nothing but other rapids (and events that neither move nor change
  /// state) between them. The piece's event is the last rapid that moved the axis which moved
  /// last, so reports name the block that set the differing coordinate (see setterOf()).
  Piece rapidRun(const Event& first, const MotionState& s) {
    Event last = first;
    setters_.fill(first);
    Event n;
    while (pull(n)) {
      if (n.kind == Kind::Rapid) {
        count(n);
        if (zeroLength(n)) continue;
        for (int i = 0; i < 3; ++i)
          if (std::abs(n.end[i] - n.start[i]) > o_.tolerance * 1e-3) setters_[i] = n;
        last = n;
        continue;
      }
      if (!isMove(n.kind) && !isDiscrete(n.kind) && n.kind != Kind::Spindle &&
          n.kind != Kind::Coolant) {
        count(n);
        continue;
      }
      pending_ = std::move(n);
      break;
    }
    return Piece::rapidRun(first, last, s);
  }

public:
  /// The rapid of the current run that last moved axis i (X Y Z).
  const Event& setterOf(int i) const { return setters_[static_cast<std::size_t>(i)]; }

private:
  EventSource& src_;
  const WalkOptions& o_;
  motion::StatsCollector stats_;
  MotionState state_;
  std::optional<Event> pending_;
  std::array<Event, 3> setters_;
  Mark before_, beforePrev_;
};

SideAt sideAt(const Event& e) {
  return SideAt{true, e, motion::describeEvent(e)};
}

const char* axisName(int i) {
  static const char* names[] = {"X", "Y", "Z"};
  return names[i];
}

/// "end point X differs by 0.500 mm, Z by 0.100 mm" for the axes beyond the tolerance, the
/// extra axes too when given ("A by 45.000 deg": A B C turn, U V W are linear).
std::string endSummary(const Vec3& d, double tol, const char* what = "end point",
                       const motion::Extra& dx = motion::Extra::Zero()) {
  std::string s;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(d[i]) <= tol) continue;
    s += fmt::format("{}{} by {:.3f} mm", s.empty() ? "" : ", ", axisName(i), std::abs(d[i]));
  }
  for (int i = 0; i < dx.size(); ++i) {
    if (std::abs(dx[i]) <= tol) continue;
    s += fmt::format("{}{} by {:.3f} {}", s.empty() ? "" : ", ", motion::kExtraAxisNames[i],
                     std::abs(dx[i]), i < 3 ? "deg" : "mm");
  }
  if (s.empty()) return fmt::format("{} differs by {:.4f} mm", what, d.norm());
  const std::size_t space = s.find(' ');
  return fmt::format("{} {} differs{}", what, s.substr(0, space), s.substr(space));
}

std::string spindleText(const MotionState& s) {
  if (s.spindleDirection == 0) return "stopped";
  return fmt::format("S{} {}", s.spindleSpeed, s.spindleDirection > 0 ? "CW" : "CCW");
}
std::string coolantText(const MotionState& s) {
  if (s.mist && s.flood) return "mist and flood";
  if (s.mist) return "mist";
  if (s.flood) return "flood";
  return "off";
}

bool close(double a, double b, double tol) {
  return std::abs(a - b) <= tol;
}

/// Empty if the states of two overlapping segments agree, else what differs.
std::string stateDifference(const MotionState& a, const MotionState& b) {
  if (a.rapid != b.rapid)
    return fmt::format("motion differs: {} vs {}", a.rapid ? "rapid" : "feed",
                       b.rapid ? "rapid" : "feed");
  if (!a.rapid) {
    if (a.perRevolution != b.perRevolution)
      return fmt::format("feed mode differs: {} vs {}",
                         a.perRevolution ? "per revolution" : "per minute",
                         b.perRevolution ? "per revolution" : "per minute");
    const double ftol = std::max(1e-3, 1e-6 * std::max(a.feed, b.feed));
    if (!close(a.feed, b.feed, ftol))
      return fmt::format("feed differs: {} vs {} {}", a.feed, b.feed,
                         a.perRevolution ? "mm/rev" : "mm/min");
    if (!close(a.lead, b.lead, 1e-6))
      return fmt::format("spindle-synchronised lead differs: {} vs {} mm/rev", a.lead, b.lead);
  }
  const bool speedMatters = a.spindleDirection != 0 || b.spindleDirection != 0;
  if (a.spindleDirection != b.spindleDirection ||
      (speedMatters && !close(a.spindleSpeed, b.spindleSpeed, 1e-6)))
    return fmt::format("spindle differs: {} vs {}", spindleText(a), spindleText(b));
  if (a.mist != b.mist || a.flood != b.flood)
    return fmt::format("coolant differs: {} vs {}", coolantText(a), coolantText(b));
  if (a.tool != b.tool) return fmt::format("tool differs: T{} vs T{}", a.tool, b.tool);
  return {};
}

/// Empty if two discrete events agree, else what differs.
std::string eventDifference(const Event& a, const Event& b) {
  if (a.kind != b.kind)
    return fmt::format("events differ: {} vs {}", motion::describeEvent(a),
                       motion::describeEvent(b));
  switch (a.kind) {
  case Kind::Dwell:
    if (a.perRevolution != b.perRevolution || !close(a.value, b.value, 1e-4))
      return fmt::format("dwell differs: {} vs {}", motion::describeEvent(a),
                         motion::describeEvent(b));
    return {};
  case Kind::Stop:
    if (a.optional != b.optional)
      return fmt::format("stop differs: {} vs {}", a.optional ? "M1" : "M0",
                         b.optional ? "M1" : "M0");
    return {};
  case Kind::ToolChange:
    if (a.value != b.value) return fmt::format("tool change differs: T{} vs T{}", a.value, b.value);
    return {};
  default:
    return {};
  }
}

class Walk {
public:
  Walk(EventSource& a, EventSource& b, const WalkOptions& o)
      : o_(o), tol_(o.tolerance + o.resolution), a_(a, o, o.rapidRate),
        b_(b, o, o.rapidRateB > 0 ? o.rapidRateB : o.rapidRate) {}

  EquivResult run() {
    a_.advance();
    b_.advance();
    while (!done_)
      step();
    a_.finishStats(r_.divergence.has_value());
    b_.finishStats(r_.divergence.has_value());
    r_.a = a_.summary;
    r_.b = b_.summary;
    return std::move(r_);
  }

private:
  /// The tolerance plus the resolution of the numbers read (chords written within the
  /// tolerance may be a rounding beyond it once printed).
  double tol() const { return tol_; }

  void diverge(DivergenceKind kind, std::string summary, double amount, const Vec3& where, SideAt a,
               SideAt b) {
    Divergence d;
    d.kind = kind;
    d.summary = std::move(summary);
    d.amount = amount;
    d.where = where;
    d.a = std::move(a);
    d.b = std::move(b);
    r_.divergence = std::move(d);
    done_ = true;
  }

  /// Side x is at a boundary with something other than the continuation of y's current piece:
  /// x's last piece ended where y still moves on. Names x's last piece and y's current one.
  void endedEarly(Side& x, Side& y, bool xIsA) {
    const Vec3 xEnd = x.prev ? x.prev->end() : y.piece->point(y.t);
    const Vec3 d = y.piece->end() - xEnd;
    const motion::Extra dx = y.piece->extra(1) - (x.prev ? x.prev->extra(1) : y.piece->extra(y.t));
    x.namesPrev = x.prev.has_value();
    SideAt xs = x.prev ? sideAt(x.prev->event())
                       : (x.type == Side::Type::Discrete ? sideAt(x.event) : SideAt{});
    SideAt ys = sideAt(y.piece->event());
    std::string summary =
        endSummary(xIsA ? d : Vec3(-d), tol(), "end point", xIsA ? dx : motion::Extra(-dx));
    if (x.type == Side::Type::End)
      summary += fmt::format("; {} ended", xIsA ? "A" : "B");
    else if (x.type == Side::Type::Discrete)
      summary += fmt::format(" ({} has {} next)", xIsA ? "A" : "B", motion::describeEvent(x.event));
    if (xIsA)
      diverge(DivergenceKind::Geometry, summary, d.norm(), xEnd, xs, ys);
    else
      diverge(DivergenceKind::Geometry, summary, d.norm(), xEnd, ys, xs);
  }

  void step() {
    for (Side* s : {&a_, &b_})
      while (s->type == Side::Type::Piece && !s->piece->isRapidRun() && s->remaining() <= tol())
        s->advance();
    const bool pa = a_.type == Side::Type::Piece, pb = b_.type == Side::Type::Piece;
    if (a_.type == Side::Type::End && b_.type == Side::Type::End) {
      r_.equivalent = true;
      done_ = true;
      return;
    }
    // a side mid-piece while the other has something else next
    if (a_.mid() && (!pb || b_.piece->isRapidRun() != a_.piece->isRapidRun()))
      return endedEarly(b_, a_, false);
    if (b_.mid() && (!pa || a_.piece->isRapidRun() != b_.piece->isRapidRun()))
      return endedEarly(a_, b_, true);
    if (pa && pb) return pieces();
    if (a_.type == Side::Type::Discrete && b_.type == Side::Type::Discrete) {
      const std::string why = eventDifference(a_.event, b_.event);
      if (!why.empty())
        return diverge(DivergenceKind::Event, why, std::abs(a_.event.value - b_.event.value),
                       a_.piece ? a_.piece->start() : lastPoint(), sideAt(a_.event),
                       sideAt(b_.event));
      a_.advance();
      b_.advance();
      return;
    }
    if (a_.type == Side::Type::End || b_.type == Side::Type::End) {
      const bool aEnded = a_.type == Side::Type::End;
      Side& other = aEnded ? b_ : a_;
      Side& ended = aEnded ? a_ : b_;
      SideAt o =
          other.type == Side::Type::Piece ? sideAt(other.piece->event()) : sideAt(other.event);
      SideAt e = ended.prev ? sideAt(ended.prev->event()) : SideAt{};
      const std::string why = fmt::format("{} ended; {} continues with {}", aEnded ? "A" : "B",
                                          aEnded ? "B" : "A", o.description);
      return aEnded ? diverge(DivergenceKind::Ended, why, 0, lastPoint(), e, o)
                    : diverge(DivergenceKind::Ended, why, 0, lastPoint(), o, e);
    }
    // a discrete event on one side where the other moves
    const bool aEvent = a_.type == Side::Type::Discrete;
    const Event& ev = aEvent ? a_.event : b_.event;
    const Side& mover = aEvent ? b_ : a_;
    const std::string why = fmt::format("{} has {} where {} moves", aEvent ? "A" : "B",
                                        motion::describeEvent(ev), aEvent ? "B" : "A");
    diverge(DivergenceKind::Event, why, 0, mover.piece->start(),
            aEvent ? sideAt(ev) : sideAt(mover.piece->event()),
            aEvent ? sideAt(mover.piece->event()) : sideAt(ev));
  }

  Vec3 lastPoint() const {
    if (a_.prev) return a_.prev->end();
    if (b_.prev) return b_.prev->end();
    return Vec3::Zero();
  }

  void pieces() {
    const Piece &pa = *a_.piece, &pb = *b_.piece;
    if (std::string why = stateDifference(pa.state(), pb.state()); !why.empty()) {
      // at a joint where the paths part already, the path is the difference, not the state
      // the next piece starts with
      if (a_.mid() != b_.mid() && !pa.isRapidRun() && !pb.isRapidRun() && partsAtJoint()) return;
      diverge(DivergenceKind::State, why, 0, pa.point(a_.t), sideAt(pa.firstEvent()),
              sideAt(pb.firstEvent()));
      if (why.starts_with("spindle")) {
        r_.divergence->stateSetA = pa.state().spindleSetAt;
        r_.divergence->stateSetB = pb.state().spindleSetAt;
      } else if (why.starts_with("coolant")) {
        r_.divergence->stateSetA = pa.state().coolantSetAt;
        r_.divergence->stateSetB = pb.state().coolantSetAt;
      }
      return;
    }
    if (pa.isRapidRun() && pb.isRapidRun()) return rapidRuns();

    Side& lead = a_.remaining() <= b_.remaining() ? a_ : b_;
    Side& follow = &lead == &a_ ? b_ : a_;
    const bool leadIsA = &lead == &a_;
    const Piece &lp = *lead.piece, &fp = *follow.piece;
    const Vec3 end = lp.end();
    const motion::Extra endExtra = lp.extra(1);
    const double hint = std::min(1.0, follow.t + lead.remaining() / std::max(fp.length(), 1e-12));
    const double tf = fp.nearest(end, follow.t, 1, hint, tol(), &endExtra);
    const Vec3 onFollow = fp.point(tf);
    const double dEnd = (end - onFollow).norm();
    const double dExtra = (lp.extra(1) - fp.extra(tf)).cwiseAbs().maxCoeff();
    if (dEnd > tol() || dExtra > tol()) return geometry(lead, follow, leadIsA, end, onFollow);

    double dev = dEnd;
    Vec3 where = end;
    if (!lp.sameCarrier(fp, tol())) {
      auto check = [&](const Piece& p, double lo, double hi, const Piece& q, double qlo,
                       double qhi) {
        for (double s : p.samples(lo, hi)) {
          const Vec3 x = p.point(s);
          const double h = hi > lo ? qlo + (qhi - qlo) * (s - lo) / (hi - lo) : qlo;
          const double d = (x - q.point(q.nearest(x, qlo, qhi, h, tol()))).norm();
          if (d > dev) {
            dev = d;
            where = x;
          }
        }
      };
      check(lp, lead.t, 1, fp, follow.t, tf);
      check(fp, follow.t, tf, lp, lead.t, 1);
    }
    if (dev > tol()) {
      return diverge(
          DivergenceKind::Geometry,
          fmt::format("path deviates by {:.4f} mm (tolerance {:g} mm)", dev, o_.tolerance), dev,
          where, sideAt(pa.event()), sideAt(pb.event()));
    }
    r_.maxDeviation = std::max(r_.maxDeviation, dev);
    lead.advance();
    follow.t = tf;
  }

  /// Whether the end of the shorter remaining piece is off the other side's path (then reports
  /// it as a geometry divergence).
  bool partsAtJoint() {
    Side& lead = a_.remaining() <= b_.remaining() ? a_ : b_;
    Side& follow = &lead == &a_ ? b_ : a_;
    const Vec3 end = lead.piece->end();
    const motion::Extra endExtra = lead.piece->extra(1);
    const double hint =
        std::min(1.0, follow.t + lead.remaining() / std::max(follow.piece->length(), 1e-12));
    const double tf = follow.piece->nearest(end, follow.t, 1, hint, tol(), &endExtra);
    const Vec3 onFollow = follow.piece->point(tf);
    if ((end - onFollow).norm() <= tol() &&
        (endExtra - follow.piece->extra(tf)).cwiseAbs().maxCoeff() <= tol())
      return false;
    geometry(lead, follow, &lead == &a_, end, onFollow);
    return true;
  }

  /// The paths part: where one side turned at a joint while the other was mid-piece, that
  /// side's previous piece ended early (or late); otherwise the current pieces differ.
  void geometry(Side& lead, Side& follow, bool leadIsA, const Vec3& end, const Vec3& onFollow) {
    if (a_.mid() != b_.mid()) {
      Side& x = a_.mid() ? b_ : a_; // at the start of its piece
      Side& y = a_.mid() ? a_ : b_;
      if (x.prev) return endedEarly(x, y, &x == &a_);
    }
    const Piece &pa = *a_.piece, &pb = *b_.piece;
    // pieces that start together and end apart: their end points; else where the lead ended
    Vec3 d = pb.end() - pa.end();
    const motion::Extra dx = pb.extra(1) - pa.extra(1);
    const bool endsDiffer = maxAbs(d) > tol() || dx.cwiseAbs().maxCoeff() > tol();
    if (a_.t > 0 || b_.t > 0 || !endsDiffer)
      d = leadIsA ? Vec3(onFollow - end) : Vec3(end - onFollow);
    (void)follow;
    (void)lead;
    const std::string why =
        maxAbs(d) > tol() ? endSummary(d, tol()) : endSummary(d, tol(), "end point", dx);
    diverge(DivergenceKind::Geometry, why, d.norm(), end, sideAt(pa.event()), sideAt(pb.event()));
  }

  void rapidRuns() {
    const Piece &pa = *a_.piece, &pb = *b_.piece;
    const Vec3 d = pb.end() - pa.end();
    const double dx = (pb.extra(1) - pa.extra(1)).cwiseAbs().maxCoeff();
    if (maxAbs(d) > tol() || dx > tol()) {
      int axis = 0;
      d.cwiseAbs().maxCoeff(&axis);
      const std::string why = endSummary(d, tol(), "rapid end point", pb.extra(1) - pa.extra(1));
      return diverge(DivergenceKind::Geometry, why, d.norm(), pa.end(), sideAt(a_.setterOf(axis)),
                     sideAt(b_.setterOf(axis)));
    }
    r_.maxDeviation = std::max(r_.maxDeviation, d.norm());
    a_.advance();
    b_.advance();
  }

  const WalkOptions& o_;
  double tol_;
  Side a_, b_;
  EquivResult r_;
  bool done_ = false;
};

} // namespace

EquivResult walk(EventSource& a, EventSource& b, const WalkOptions& options) {
  return Walk(a, b, options).run();
}

} // namespace gcx::equiv
