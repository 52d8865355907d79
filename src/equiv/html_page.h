// What `gcx equiv --report` shows, taken from the outcome of the check (report/equiv_page.h).
#pragma once
#include "equiv/equiv.h"
#include "report/equiv_page.h"

namespace gcx::equiv {

/// The page's data: verdict, summary, both sides' statistics and, at a divergence, where it is
/// and the source around each side's event (read from the files the locations name).
report::EquivPage htmlPage(const EquivOutcome& o, double tolerance);

} // namespace gcx::equiv
