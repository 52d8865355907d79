// The interpreter's side of the contour cycles (cycles/contour_cycles.h, wl4.md §5.6): the
// block's words, the contour P..Q traced from the block's start point on a scratch copy of the
// engine (turning_cycles.cpp), the allowances, and the passes run like any cycle's ops. An
// equidistant allowance and the tool radius offset the contour with the geometry radius
// compensation uses (offset_geometry.h): outer corners on an arc about the corner point.
#include <cmath>
#include <fmt/format.h>

#include "cycles/contour_cycles.h"
#include "diag/codes.h"
#include "machine/code_names.h"
#include "machine/interpreter.h"

namespace gcx::machine {

namespace {

using cycles::OpKind;
using cycles::Profile;
using cycles::ProfileSegment;

bool isArc(OpKind k) {
  return k == OpKind::ArcCW || k == OpKind::ArcCCW;
}

comp::Path2 pathOf(const ProfileSegment& s) {
  return {isArc(s.kind), s.from, s.to, s.center, s.kind == OpKind::ArcCCW};
}

/// The swept angle of an arc from a to b in its direction, in [0, 2π).
double sweep(const comp::Path2& p, const comp::Vec2& a, const comp::Vec2& b) {
  double t = std::atan2(comp::cross(a - p.c, b - p.c), (a - p.c).dot(b - p.c));
  if (!p.ccw) t = -t;
  return t < -1e-12 ? t + 2 * M_PI : std::max(t, 0.0);
}

/// The profile's equidistant at distance d, left of travel positive (the lathe plane's own
/// orientation, as G41 has it): each element offset, inner corners at the offsets'
/// intersection, outer corners on an arc of |d| about the corner point. Nullopt (reported)
/// when an element does not survive the offset.
std::optional<Profile> equidistant(const Profile& p, double d, const std::string& label,
                                   diag::Engine& diags) {
  if (std::abs(d) < 1e-9 || p.segments.empty()) return p;
  auto refuse = [&](const SourceRange& at) {
    diags.error(diag::code::CycleParam, at,
                fmt::format("{}: the contour's equidistant at {:g} mm does not fit this block (an "
                            "inner arc or a block shorter than the allowance; wl4.md §5.6)",
                            label, std::abs(d)));
    return std::nullopt;
  };
  const std::size_t n = p.segments.size();
  std::vector<comp::Path2> off(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto o = comp::offsetPath(pathOf(p.segments[i]), d);
    if (!o) return refuse(p.segments[i].range);
    off[i] = *o;
  }
  // the corner after element i: where i ends, where i + 1 starts, and what joins them
  std::vector<ProfileSegment> joins;
  std::vector<std::vector<ProfileSegment>> after(n);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const comp::Path2 first = pathOf(p.segments[i]), second = pathOf(p.segments[i + 1]);
    const comp::CornerResult c =
        comp::corner(first, second, d, d, comp::Join::Normal, comp::OuterCorner::Arc);
    if (c.noIntersection || c.points.empty()) return refuse(p.segments[i + 1].range);
    off[i].b = c.points.front();
    off[i + 1].a = c.points.back();
    for (std::size_t k = 0; k + 1 < c.points.size(); ++k) {
      ProfileSegment j;
      j.range = p.segments[i].range;
      j.from = c.points[k], j.to = c.points[k + 1];
      if (c.arcAbout) { // about the corner, turning the way the contour turns
        const double turn =
            comp::cross(comp::tangentAt(first, true), comp::tangentAt(second, false));
        j.kind = turn > 0 ? OpKind::ArcCCW : OpKind::ArcCW;
        j.center = first.b;
      }
      after[i].push_back(j);
    }
  }
  Profile q = p;
  q.segments.clear();
  q.aPrime = off.front().a;
  for (std::size_t i = 0; i < n; ++i) {
    const ProfileSegment& s = p.segments[i];
    const comp::Path2 whole = *comp::offsetPath(pathOf(s), d);
    const bool kept =
        whole.arc ? sweep(whole, off[i].a, off[i].b) <= sweep(whole, whole.a, whole.b) + 1e-9 ||
                        (whole.a - whole.b).norm() < 1e-9
                  : (off[i].b - off[i].a).dot(whole.b - whole.a) > -1e-12;
    if (!kept) return refuse(s.range);
    ProfileSegment t = s;
    t.from = off[i].a, t.to = off[i].b;
    q.segments.push_back(t);
    for (const ProfileSegment& j : after[i])
      q.segments.push_back(j);
  }
  return q;
}

} // namespace

bool Interpreter::contourCycleSide(const BlockWords& w, const ModalState& before) {
  const ir::Word* code = w.findAction(GAction::ContourCycle);
  contourSide_ = state_.radiusComp == GAction::RadiusCompLeft    ? 1
                 : state_.radiusComp == GAction::RadiusCompRight ? -1
                                                                 : 0;
  if (before.radiusComp != GAction::RadiusCompOff)
    return fail(diag::code::CycleParam, code->range,
                fmt::format("{}: radius compensation must be off ({}) before the cycle; the "
                            "cycle's own {} switches it on for its passes (wl4.md §5.6)",
                            gName(*code), codeName(profile_, GAction::RadiusCompOff),
                            codeName(profile_, GAction::RadiusCompLeft)));
  state_.radiusComp = GAction::RadiusCompOff; // on only inside the cycle, off after it
  for (const GCodeSpec& g : profile_.gcodes)
    if (g.action == GAction::RadiusCompOff) {
      setModalCode(&g);
      break;
    }
  return true;
}

bool Interpreter::contourCycleBlock(const BlockWords& w, const ModalState& before) {
  using cycles::ContourCycle;
  const auto cycle = static_cast<ContourCycle>(pendingContour_->arg);
  const ir::Word* code = w.findAction(GAction::ContourCycle);
  const std::string label = gName(*code);
  const cycles::LatheAxes ax = cycles::latheAxes(state_.plane);
  const bool approach = cycle == ContourCycle::Approach;
  auto value = [&](const ir::Word* x) { return x ? mm(x->number) : 0.0; };
  // the cycle's words: E depth per pass; I K the finishing allowance along X and Z and R the
  // equidistant one; G76: U W the initial allowance along X and Z, C the equidistant one (all
  // radius values, signed where linear)
  const ir::Word *iw = w.ijk[ax.p2], *kw = w.ijk[ax.p1], *cw = w.letter('C');
  const ir::Word* uw = approach ? w.uvw[ax.p2] : nullptr;
  const ir::Word* ww = approach ? w.uvw[ax.p1] : nullptr;
  auto param = [&](const ir::Word* at, const std::string& why) {
    return fail(diag::code::CycleParam, at ? at->range : code->range,
                fmt::format("{}: {} (wl4.md §5.6)", label, why));
  };
  if (w.e && w.e->number <= 0) return param(w.e, "the depth of cut E must be > 0");
  if (w.r && (iw || kw)) return param(w.r, "a linear allowance I K and an equidistant R together");
  if (cw && (uw || ww)) return param(cw, "an initial allowance U W and an equidistant C together");
  if (w.r && !contourSide_) return param(w.r, "an equidistant allowance R needs G41 or G42");
  if (approach && cw && !contourSide_)
    return param(cw, "an equidistant allowance C needs G41 or G42");
  if (!approach && cw) return param(cw, "C is an initial allowance of the approach cycle only");
  if (approach && w.e && !uw && !ww && !cw)
    return param(w.e, "roughing needs the initial allowance U W or C");
  if (state_.motion != GAction::Rapid && state_.motion != GAction::Linear)
    return param(nullptr, "the block needs G0 or G1: the infeed at rapid or at feed");
  if (state_.feed <= 0) // before the contour's G1 blocks need it
    return fail(diag::code::MissingData, code->range, fmt::format("{}: no feed F", label));
  // P: the contour's start, the block's axis words (G77/G78 take U W as increments)
  Vec3 start = program_;
  for (int a : {ax.p1, ax.p2}) {
    if (const ir::Word* x = w.axis[a])
      start[a] = (state_.incremental || x->incremental ? program_[a] : 0) + coordinate(a, *x);
    if (!approach && w.uvw[a]) start[a] += coordinate(a, *w.uvw[a]);
  }
  std::vector<ContourBlock> blocks;
  if (!contourBlocks(w, blocks)) return false;
  const int most = profile_.cycleChoices.maxContourBlocks;
  const auto count = std::count_if(blocks.begin(), blocks.end(), [](const ContourBlock& b) {
    return !b.block.words.empty() || !b.block.stmts.empty();
  });
  if (most > 0 && !approach && count > most)
    return param(w.q, fmt::format("the contour has {} blocks, at most {}", count, most));
  std::vector<cycles::ContourSegment> segments(1);
  cycles::ContourSegment& in = segments.front(); // A -> P in the block's G0/G1
  in.kind = state_.motion == GAction::Rapid ? OpKind::Rapid : OpKind::Feed;
  in.from = program_, in.to = start, in.range = code->range;
  if (!traceContour(blocks, segments, &start)) return false;
  const auto contour = cycles::makeProfile(segments, state_.plane, code->range, diags_);
  if (!contour) return false;
  if (contour->segments.empty())
    return fail(diag::code::CycleContourDegenerate, w.p->range,
                fmt::format("{}: the contour P..Q has no move", label));
  // the allowances of each pass: a shift (z, x) and an equidistant; the tool radius adds to
  // the equidistant under G41/G42 (the nose centre follows it, wl4.md §4.1)
  const auto radius = contourSide_ ? compensationRadius(w) : std::optional<double>(0.0);
  if (!radius) return false;
  const double tool = *radius;
  const cycles::Vec2 finish(value(kw), value(iw));
  cycles::ContourCycleRequest req;
  req.cycle = cycle, req.label = label, req.plane = state_.plane;
  req.start = program_, req.infeed = segments.front().kind;
  req.feed = state_.feed;
  if (w.e) req.depth = mm(w.e->number), req.depthWord = w.e->range;
  req.block = code->range;
  req.programmed = *contour;
  auto add = [&](const cycles::Vec2& shift, double allowance) {
    const auto c = equidistant(cycles::shifted(*contour, shift), contourSide_ * (allowance + tool),
                               label, diags_);
    if (c) req.contours.push_back(*c);
    return c.has_value();
  };
  if (approach && req.depth) { // pass i of N: the finishing allowance + initial·(N − i)/N
    const cycles::Vec2 initial(value(ww), value(uw));
    const double c = value(cw);
    const int n = cycles::approachPasses(std::max({std::abs(initial[0]), std::abs(initial[1]), c}),
                                         *req.depth);
    for (int i = 1; i <= n; ++i) {
      const double t = static_cast<double>(n - i) / n;
      if (!add(finish + t * initial, value(w.r) + t * c)) return false;
    }
  } else if (!add(finish, value(w.r))) {
    return false;
  }
  const auto ops = cycles::expandContourCycle(req, diags_);
  if (!ops) return false;
  if (!runCycleOps(*ops, static_cast<std::size_t>(-1), w, ax.normal, label.c_str())) return false;
  state_.feed = before.feed; // F acts only inside the cycle
  return afterMotion(w);
}

} // namespace gcx::machine
