#include "sillage/slam/temporal_slam.h"

#include <chrono>
#include <string>

#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/slam/ctc_p_implies_z.h"

namespace sillage {

namespace {

IntervalVector concat(const IntervalVector& a, const IntervalVector& b) {
  IntervalVector c(a.size() + b.size());
  for (std::size_t i = 0; i < a.size(); ++i) c[i] = a[i];
  for (std::size_t i = 0; i < b.size(); ++i) c[a.size() + i] = b[i];
  return c;
}

// The components of y written in place: their versions step once, when these go.
std::vector<Tube::Writer> writers(TubeVector& y) {
  std::vector<Tube::Writer> w;
  w.reserve(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) w.push_back(y[i].write());
  return w;
}

// Slice k (or gate k) of every component of y ∩= b.
void intersect_atom(const std::vector<Tube::Writer>& y, std::size_t k, bool gate, const IntervalVector& b) {
  for (std::size_t i = 0; i < y.size(); ++i) (gate ? y[i].gates() : y[i].slices())[k] &= b[i];
}

// Every slice and gate of y ∩= g(arguments at that slice / gate).
template <class Args>
void eval_into(TubeVector& y, const Function& g, const Args& args) {
  const std::size_t n = y.nb_slices();
  const auto w = writers(y);
  for (std::size_t k = 0; k <= n; ++k) {
    intersect_atom(w, k, true, g.eval_vector(args(k, true)));
    if (k < n) intersect_atom(w, k, false, g.eval_vector(args(k, false)));
  }
}

// C_f on every slice and gate: v ∩= f(x, u), then x ∩= the x-part of
// HC4-revise of (x, u) against v (u is an input: read only). An empty result
// empties x and v.
void evolution(TubeVector& x, TubeVector& v, const TubeVector& u, const Function& f) {
  const std::size_t n = x.nb_slices(), nx = x.size();
  const auto wx = writers(x), wv = writers(v);
  bool empty = false;
  for (std::size_t k = 0; k <= n && !empty; ++k) {
    for (bool gate : {true, false}) {
      if (!gate && k == n) continue;
      const auto at = [&](const TubeVector& y) { return gate ? y.gate(k) : y.slice(k); };
      IntervalVector args = u.size() ? concat(at(x), at(u)) : at(x);
      intersect_atom(wv, k, gate, f.eval_vector(args));
      if (!f.hc4_revise(args, at(v))) {
        empty = true;
        break;
      }
      intersect_atom(wx, k, gate, args.subvector(0, nx - 1));
    }
  }
  if (empty) {
    for (std::size_t i = 0; i < nx; ++i) x[i].set(Interval::empty()), v[i].set(Interval::empty());
  }
}

void check(const TubeVector& x, const TubeVector& v, const TubeVector& u, const Function& f, const Function& h,
           const TemporalSlamOptions& o) {
  const std::string where = "temporal_slam(x, v, u, z, f, h)";
  if (v.size() != x.size() || v.tdomain() != x.tdomain()) {
    throw DimensionError(where + ": v must have x's size (" + std::to_string(x.size()) + ") and TDomain");
  }
  if (u.size() > 0 && u.tdomain() != x.tdomain()) throw DimensionError(where + ": u must be on x's TDomain");
  if (f.nb_vars() != x.size() + u.size() || f.image_dim() != x.size()) {
    throw DimensionError(where + ": f must map the " + std::to_string(x.size() + u.size()) +
                         " variables (x, u) to " + std::to_string(x.size()) + " values");
  }
  if (h.nb_vars() != x.size() || (h.image_dim() != 2 && h.image_dim() != 1)) {
    throw DimensionError(where + ": h must map the " + std::to_string(x.size()) + " variables of x to 2 values (or 1)");
  }
  if (!o.fast && !o.accurate) throw Error(where + ": options.fast and options.accurate are both off");
  if (o.max_rounds == 0) throw Error(where + ": options.max_rounds must be at least 1");
}

}  // namespace

namespace {

// Ends the summary as NoSolution, x emptied `where` (the provenance).
void no_solution(TubeVector& x, Summary& s, bool fast, std::size_t round, const char* where) {
  for (std::size_t i = 0; i < x.size(); ++i) x[i].set(Interval::empty());
  s.status = Status::NoSolution;
  s.reason = std::string("temporal_slam: x emptied ") + where + " in round " + std::to_string(round + 1) + " of the " +
             (fast ? "fast" : "accurate") + " algorithm";
}

// The run; Cancelled from options.cancel is left to the caller.
void run_rounds(TubeVector& x, TubeVector& v, const TubeVector& u, const TubeVector& z, const Function& f,
                const Function& h, const TemporalSlamOptions& options, TemporalSlamResult& result) {
  const auto td = x.tdomain();
  const std::size_t n = x.nb_slices();
  const auto at = [&](const TubeVector& y, std::size_t k, bool gate) { return gate ? y.gate(k) : y.slice(k); };
  const std::size_t m = h.image_dim();  // 2, or 1 for a scalar configuration (scalar_loops.h)
  TubeVector p(td, m), w(td, m);
  // The reference of the contractions: dead reckoning, p after the first C_d/dt.
  IntervalVector tf0(m), t00(m);
  bool reference = false;
  const auto start = std::chrono::steady_clock::now();
  std::vector<SlamRow>& rows = result.rows;
  Summary& summary = result.summary;
  double cumulated = 0.0;
  for (bool fast : {true, false}) {
    if ((fast && !options.fast) || (!fast && !options.accurate)) continue;
    const CtcPImpliesZ cpz(options.eps, fast);
    bool fixed_point = false;
    for (std::size_t round = 0; round < options.max_rounds && !fixed_point; ++round) {
      check_cancel(options.cancel, "temporal_slam");
      // 1-2. Evolution: v = f(x, u) both ways (x from v too), x' = v.
      evolution(x, v, u, f);
      if (x.is_empty()) return no_solution(x, summary, fast, round, "by the evolution f(x, u)");
      CtcDeriv().contract(x, v);
      if (x.is_empty()) return no_solution(x, summary, fast, round, "by x' = v");
      // 3. Configurations p = h(x) and their derivative w = h(v).
      eval_into(p, h, [&](std::size_t k, bool g) { return at(x, k, g); });
      eval_into(w, h, [&](std::size_t k, bool g) { return at(v, k, g); });
      if (p.is_empty()) return no_solution(x, summary, fast, round, "by p = h(x)");
      if (!reference) {
        tf0 = p.gate(n);
        t00 = p.gate(0);
        reference = true;
      }
      // 4. The inter-temporal implication, one iteration at a time.
      std::size_t nb_its = 0;
      for (std::size_t it = 0; it < cpz.max_iterations(); ++it) {
        SlamRow r;
        const auto it_start = std::chrono::steady_clock::now();
        const bool shrunk = cpz.iterate(p, w, z, r, options.cancel);
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - it_start).count();
        r.iteration = rows.size() + 1;
        cumulated += r.seconds;
        r.cumulated_seconds = cumulated;
        r.contraction_tf = detail::contraction(tf0, p.gate(n));
        r.contraction_t0 = detail::contraction(t00, p.gate(0));
        rows.push_back(r);
        ++nb_its;
        summary.work = rows.size();
        if (options.on_iteration) options.on_iteration(rows.back(), p);
        if (options.progress) {
          summary.rounds = rows.size();
          options.progress(Progress{"temporal_slam", rows.size(), rows.size(),
                                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
        }
        if (!shrunk || p.is_empty()) break;
      }
      // 5. Back to the states: x ∩= h⁻¹(p).
      {
        const auto wx = writers(x);
        for (std::size_t k = 0; k <= n; ++k) {
          for (bool gate : {true, false}) {
            if (!gate && k == n) continue;
            IntervalVector b = gate ? x.gate(k) : x.slice(k);
            h.hc4_revise(b, gate ? p.gate(k) : p.slice(k));
            intersect_atom(wx, k, gate, b);
          }
        }
      }
      if (p.is_empty()) return no_solution(x, summary, fast, round, "by the loops C_{p=>z}");
      fixed_point = nb_its <= 1;  // C_{p⇒z} found nothing more: this algorithm's fixed point
    }
    if (!fixed_point && summary.status == Status::Converged) {
      summary.status = Status::Stopped;
      summary.reason = std::string("temporal_slam: the ") + (fast ? "fast" : "accurate") + " algorithm ran max_rounds = " +
                       std::to_string(options.max_rounds) + " rounds without reaching its fixed point; raise "
                       "options.max_rounds";
    }
  }
}

}  // namespace

TemporalSlamResult temporal_slam_run(TubeVector& x, TubeVector& v, const TubeVector& u, const TubeVector& z,
                                     const Function& f, const Function& h, const TemporalSlamOptions& options) {
  check(x, v, u, f, h, options);
  TemporalSlamResult result;
  const auto start = std::chrono::steady_clock::now();
  try {
    run_rounds(x, v, u, z, f, h, options, result);
  } catch (const Cancelled&) {
    if (!options.cancel.cancelled()) throw;  // not ours (a callback's): not a cancellation of the run
    result.summary.status = Status::Cancelled;
    result.summary.reason = "temporal_slam: cancelled";
  }
  result.summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::vector<SlamRow> temporal_slam(TubeVector& x, TubeVector& v, const TubeVector& u, const TubeVector& z,
                                   const Function& f, const Function& h, const TemporalSlamOptions& options) {
  TemporalSlamResult r = temporal_slam_run(x, v, u, z, f, h, options);
  if (r.summary.status == Status::Cancelled) throw Cancelled("temporal_slam");
  return std::move(r.rows);
}

}  // namespace sillage
