// probe_gate: the values of a relaxed gate that the contraction alone leaves unbounded.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>

#include <tbb/parallel_for.h>

#include "sillage/problem/explain_search.h"
#include "sillage/problem/interval_text.h"

namespace sillage::detail {

namespace {

constexpr std::size_t kCells = 16;

// "[lo, hi]" in 17 digits: read back rigorously (outward), so the cell stated is at least [lo, hi].
std::string cell_expr(const Interval& x) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "[%.17g, %.17g]", x.lb(), x.ub());
  return buf;
}

}  // namespace

void probe_gate(ExplainSearch& s, Relaxation& r) {
  const std::size_t k = r.items.front();
  const ExplainItem& it = s.e.items[k];
  if (r.items.size() != 1 || it.kind != ItemKind::Gate) return;
  for (std::size_t i = 0; i < r.values.size(); ++i) {  // a gate's values: one per component, in order
    ProvenValue& v = r.values[i];
    if (v.proven.is_bounded() || !v.stated.is_bounded() || s.out_of_time()) continue;
    const double radius = std::max(M_PI, 32 * v.stated.diam());
    const Interval window = Interval(v.stated.mid()).inflate(radius);
    // Cells halved while their contraction is not empty, down to the stated value's width: a
    // cell much wider than the stated value hides the contradiction as the stated one did not.
    const double finest = v.stated.diam() > 0 ? v.stated.diam() : window.diam() / 256;
    std::vector<Interval> cells, found;
    for (std::size_t c = 0; c < kCells; ++c) {
      const double w = window.diam() / kCells;
      cells.push_back(Interval(window.lb() + w * static_cast<double>(c),
                               c + 1 == kCells ? window.ub() : window.lb() + w * static_cast<double>(c + 1)));
    }
    std::mutex m;
    while (!cells.empty()) {
      std::vector<Interval> next;
      tbb::parallel_for(std::size_t{0}, cells.size(), [&](std::size_t c) {
        const Interval cell = cells[c];
        // The gate stated in the cell for component i, the whole line for the others.
        Problem q = s.p;
        for (VarSpec& var : q.vars) {
          if (var.name != it.var) continue;
          for (std::size_t j = 0; j < var.dim; ++j) var.at[it.index].value[j].expr = j == i ? cell_expr(cell) : "";
        }
        Relaxation cr;
        const TrialOutcome o = s.run(q, {k}, &cr, v.what + " in " + interval_text(cell));
        const std::lock_guard<std::mutex> lock(m);
        if (o == TrialOutcome::Stopped) found.push_back(cell);  // undecided: the whole cell stays
        else if (o == TrialOutcome::NotEmpty && cell.diam() > finest) {
          next.push_back(Interval(cell.lb(), cell.mid()));
          next.push_back(Interval(cell.mid(), cell.ub()));
        } else if (o == TrialOutcome::NotEmpty) {
          found.push_back(cr.values[i].proven);
        }
      });
      cells = std::move(next);
    }
    // The union, pieces closer than the finest cell merged (a larger set: still an enclosure).
    std::sort(found.begin(), found.end(), [](const Interval& a, const Interval& b) { return a.lb() < b.lb(); });
    v.pieces.clear();
    for (const Interval& f : found) {
      if (f.is_empty()) continue;
      if (!v.pieces.empty() && f.lb() <= v.pieces.back().ub() + finest) v.pieces.back() |= f;
      else v.pieces.push_back(f);
    }
    Interval hull = Interval::empty();
    for (const Interval& f : v.pieces) hull |= f;
    v.proven = hull;
    v.window = window;
  }
}

}  // namespace sillage::detail
