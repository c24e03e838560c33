#include "sillage/problem/explain_empty.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>

#include <tbb/parallel_for.h>

#include "sillage/problem/explain_search.h"

namespace sillage {

bool ProvenValue::disjoint() const {
  if ((stated & proven).is_empty()) return true;
  return !pieces.empty() && std::none_of(pieces.begin(), pieces.end(), [&](const Interval& x) { return stated.intersects(x); });
}

const char* outcome_name(TrialOutcome o) {
  switch (o) {
    case TrialOutcome::Empty: return "empty";
    case TrialOutcome::NotEmpty: return "not empty";
    case TrialOutcome::Stopped: return "stopped";
  }
  return "?";
}

namespace {

using detail::ExplainSearch;

// The smaller statements first: a gate is one value, a constraint a whole law.
int kind_rank(const ExplainItem& it) {
  switch (it.kind) {
    case ItemKind::Gate: return 0;
    case ItemKind::Rows: return it.all_rows ? 4 : 1;
    case ItemKind::Bound: return 2;
    case ItemKind::TableBound: return 3;
    case ItemKind::Constraint: return 5;
  }
  return 6;
}

// How telling a relaxation is: 0 when the relaxed problem proves a stated value impossible; 1 when
// it bounds every relaxed value; 2 when it has no value to bound (constraints, rows); 3 when a
// relaxed value is left unbounded: the contradiction goes only if that value may be anything.
int tier(const Relaxation& r) {
  const auto any = [&](auto pred) { return std::any_of(r.values.begin(), r.values.end(), pred); };
  if (any([](const ProvenValue& v) { return v.disjoint(); })) return 0;
  if (any([](const ProvenValue& v) { return !v.proven.is_bounded(); })) return 3;
  return r.values.empty() ? 2 : 1;
}

void rank(Explanation& e) {
  const auto key = [&](const Relaxation& r) {
    int best = 6;
    for (const std::size_t i : r.items) best = std::min(best, kind_rank(e.items[i]));
    return std::make_tuple(tier(r), r.items.size(), best, r.items.front());
  };
  std::stable_sort(e.relaxations.begin(), e.relaxations.end(),
                   [&](const Relaxation& a, const Relaxation& b) { return key(a) < key(b); });
}

// Each item alone, in parallel: the relaxations that leave the contraction non-empty.
void singles(ExplainSearch& s) {
  const std::size_t n = s.e.items.size();
  std::vector<std::optional<Relaxation>> found(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    Relaxation r;
    if (s.trial({i}, &r) == TrialOutcome::NotEmpty) found[i] = std::move(r);
  });
  for (auto& r : found)
    if (r) s.e.relaxations.push_back(std::move(*r));
}

// A blamed eval narrowed to a run of its rows: 4 runs tried at each step, the first whose
// relaxation alone restores kept, until min_rows or no run alone does (the contradiction then
// needs rows of several runs).
void narrow_rows(ExplainSearch& s, std::size_t item) {
  std::optional<Relaxation> narrowest;
  ExplainItem current = s.e.items[item];
  while (current.nb_rows > s.o.min_rows && !s.out_of_time()) {
    const std::vector<ExplainItem> runs = row_runs(s.p, current, 4);
    if (runs.size() < 2) break;
    const std::size_t first = s.e.items.size();
    s.e.items.insert(s.e.items.end(), runs.begin(), runs.end());
    std::vector<std::optional<Relaxation>> found(runs.size());
    tbb::parallel_for(std::size_t{0}, runs.size(), [&](std::size_t j) {
      Relaxation r;
      if (s.trial({first + j}, &r) == TrialOutcome::NotEmpty) found[j] = std::move(r);
    });
    const auto hit = std::find_if(found.begin(), found.end(), [](const auto& r) { return r.has_value(); });
    if (hit == found.end()) break;
    narrowest = std::move(**hit);
    current = s.e.items[narrowest->items.front()];
  }
  if (narrowest) s.e.relaxations.push_back(std::move(*narrowest));
}

// FastDiag (Felfernig, Schubert, Zehentner 2012): a set D of the candidates C whose relaxation,
// with the items of `relaxed` already relaxed, leaves the contraction non-empty; the candidates
// at the end of C are relaxed first. consistent(X): the contraction with X relaxed is not empty.
std::vector<std::size_t> fast_diag(ExplainSearch& s, const std::vector<std::size_t>& d, const std::vector<std::size_t>& c,
                                   const std::vector<std::size_t>& relaxed) {
  if (!d.empty() && s.trial(relaxed, nullptr) == TrialOutcome::NotEmpty) return {};
  if (c.size() == 1 || s.out_of_time()) return c;
  const std::size_t k = c.size() / 2;
  const std::vector<std::size_t> c1(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(k)),
      c2(c.begin() + static_cast<std::ptrdiff_t>(k), c.end());
  std::vector<std::size_t> r2 = relaxed;
  r2.insert(r2.end(), c2.begin(), c2.end());
  const std::vector<std::size_t> d1 = fast_diag(s, c2, c1, r2);
  std::vector<std::size_t> r1 = relaxed;
  r1.insert(r1.end(), d1.begin(), d1.end());
  const std::vector<std::size_t> d2 = fast_diag(s, d1, c2, r1);
  std::vector<std::size_t> out = d1;
  out.insert(out.end(), d2.begin(), d2.end());
  return out;
}

// No item alone restores: a set of them, checked item by item.
void find_set(ExplainSearch& s) {
  std::vector<std::size_t> c(s.e.items.size());
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = i;
  // The most trusted first (kept longest): constraints, whole evals, ..., gates last.
  std::stable_sort(c.begin(), c.end(), [&](std::size_t a, std::size_t b) {
    return kind_rank(s.e.items[a]) > kind_rank(s.e.items[b]);
  });
  if (s.trial(c, nullptr) != TrialOutcome::NotEmpty) return;  // even everything relaxed: nothing found
  std::vector<std::size_t> d = fast_diag(s, {}, c, {});
  std::sort(d.begin(), d.end());
  if (d.empty() || s.out_of_time()) return;
  Relaxation r;
  if (s.trial(d, &r) != TrialOutcome::NotEmpty) return;  // FastDiag assumes monotony: checked
  std::atomic<bool> minimal = true;
  tbb::parallel_for(std::size_t{0}, d.size(), [&](std::size_t j) {
    std::vector<std::size_t> back = d;
    back.erase(back.begin() + static_cast<std::ptrdiff_t>(j));
    if (s.trial(back, nullptr) != TrialOutcome::Empty) minimal = false;
  });
  r.minimal = minimal && d.size() > 0;
  s.e.relaxations.push_back(std::move(r));
}

void search(ExplainSearch& s) {
  singles(s);
  for (Relaxation& r : s.e.relaxations) detail::probe_gate(s, r);
  if (s.o.refine_rows) {
    const std::size_t n = s.e.relaxations.size();
    for (std::size_t k = 0; k < n; ++k) {
      const ExplainItem& it = s.e.items[s.e.relaxations[k].items.front()];
      if (it.kind == ItemKind::Rows && it.all_rows) narrow_rows(s, s.e.relaxations[k].items.front());
    }
  }
  if (s.e.relaxations.empty()) find_set(s);
  for (Relaxation& r : s.e.relaxations)
    if (r.items.size() == 1) r.minimal = true;  // the problem itself is empty: one item is needed
  rank(s.e);
}

}  // namespace

Explanation explain_empty(const Problem& p, const SolveResult& failed, const ExplainOptions& o) {
  ExplainSearch s(p, o, failed);
  if (s.e.empty) {
    s.e.items = explain_items(p);
    search(s);
  }
  s.finish();
  return std::move(s.e);
}

Explanation explain_empty(const Problem& p, const ExplainOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  SolveOptions so;
  so.delta = o.delta;
  so.scheduling = o.scheduling;
  so.budget = o.budget;
  so.keep_before_empty = false;
  Explanation e = explain_empty(p, solve_problem(p, so), o);
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return e;
}

}  // namespace sillage
