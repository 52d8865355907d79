#include "equiv/html_page.h"

#include "equiv/report.h"

namespace gcx::equiv {

namespace {
report::EquivSide side(const char* label, const ProgramSide& p, const SideSummary& s,
                       const SideAt* at) {
  report::EquivSide out;
  out.name = label;
  out.file = p.name();
  out.length = s.stats.totalLength();
  out.time = s.stats.totalSeconds();
  out.excerpt.file = p.name();
  if (at && at->present && at->event.from.at.line > 0) {
    const SourceLoc& loc = at->event.from.at;
    out.excerpt.file = p.sources().name(loc.file);
    out.excerpt.line = static_cast<int>(loc.line);
    out.excerpt.column = static_cast<int>(loc.col);
    out.excerpt.lines = report::readExcerpt(out.excerpt.file, out.excerpt.line);
    if (!at->event.from.chain.empty())
      out.excerpt.chain = provenanceText(at->event.from, p.sources());
  }
  return out;
}
} // namespace

report::EquivPage htmlPage(const EquivOutcome& o, double tolerance) {
  const EquivResult& r = o.result;
  const Divergence* d = r.divergence ? &*r.divergence : nullptr;
  report::EquivPage page;
  page.equivalent = r.equivalent;
  page.summary = d ? d->summary : headline(o, tolerance);
  page.a = side("A", *o.a, r.a, d ? &d->a : nullptr);
  page.b = side("B", *o.b, r.b, d ? &d->b : nullptr);
  if (d) page.divergence = d->where;
  page.maxDeviation = r.maxDeviation;
  page.tolerance = tolerance;
  return page;
}

} // namespace gcx::equiv
