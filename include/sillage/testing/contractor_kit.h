#pragma once
// The contractor test kit: the generic laws every contractor obeys, checked on
// random problems whose true solution is known. Installed with the headers (not
// part of sillage.h: it needs GoogleTest and oneTBB headers), header only, for
// the tests of sillage and of contractors written outside it; its Python twin
// is the module sillage.testing (same names). A contractor's test gives the kit
//   - a Contract: a callable that contracts a list of domains in place (each an
//     Interval, an IntervalVector, a Tube or a TubeVector), a few lines around
//     the contractor's own contract call or around ContractorNetwork::add;
//   - a Generator: from a random engine, a Case = input domains + the truth,
//     one true value per domain (an enclosure of a real, of a vector, or a
//     trajectory t -> enclosure of x(t)) that satisfies the constraint and lies
//     in the input domains;
// and calls check_laws(contract, generator, options), which runs, on
// options.cases random cases:
//   (a) contraction (check_contracted): every output ⊆ its input, component by
//       component, slice by slice and gate by gate;
//   (b) truth kept (check_truth): the true value meets every output (at every
//       gate and at options.samples times in each slice of a tube);
//   (c) idempotence (check_idempotent): a second call changes nothing, bit for
//       bit (Idempotence::Exact), or only contracts and keeps the truth
//       (Idempotence::ContractionOnly, for one-pass contractors such as HC4);
//   (e) thread-count independence (check_threads): the same case contracted
//       under tbb::global_control with 1 and 2 threads, and concurrently from
//       two threads on copies (contract must be const and stateless), gives
//       the same result bit for bit;
//   (f) empty and unbounded inputs (check_special_inputs): each domain in turn
//       replaced by the empty set (then every domain in options.outputs must
//       come out empty -- or one domain, options.empty_any, for a network --
//       and no exception) or by all the reals (no exception, no NaN bound,
//       contraction and the truth kept).
// (d) order independence is a property of a composition: check_order_independent
// runs a Contract that takes an insertion order with two orders and compares.
// (g) monotonicity (X ⊆ Y ⇒ C(X) ⊆ C(Y)) is not a law of every contractor:
// check_monotone tests it for those that have it.
// docs/extending.md ("Testing your contractor") and docs/contractors.md
// ("Testing a contractor") say how to use the kit. Every failure names the
// law, the case, the domain, the slice/gate index and the values (GoogleTest
// AssertionResult messages): EXPECT_TRUE(kit::check_laws(contract, gen, o)).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "sillage/interval/elementary.h"
#include "sillage/interval/interval.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/tube/tdomain.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage::kit {

using Dom = std::variant<Interval, IntervalVector, Tube, TubeVector>;
using Domains = std::vector<Dom>;
// A true scalar trajectory: for a time interval t, an enclosure of x over t
// (evaluated at degenerate t by the kit).
using Trajectory1 = std::function<Interval(const Interval&)>;
// One true value per domain: Interval for an Interval, IntervalVector for a
// box, Trajectory1 for a Tube, one Trajectory1 per component for a TubeVector.
// std::monostate: nothing known (the truth check skips that domain).
using Truth = std::variant<std::monostate, Interval, IntervalVector, Trajectory1, std::vector<Trajectory1>>;

struct Case {
  Domains domains;
  std::vector<Truth> truth;  // same length as domains
};

using Contract = std::function<void(Domains&)>;
using Generator = std::function<Case(std::mt19937_64&)>;

enum class Idempotence { Exact, ContractionOnly, None };

struct Options {
  int cases = 40;   // random cases
  int samples = 4;  // times sampled inside each slice (besides its ends)
  std::uint64_t seed = 20170101;
  Idempotence idempotence = Idempotence::Exact;
  bool threads = true;           // law (e)
  bool empty_inputs = true;      // law (f), empty
  bool unbounded_inputs = true;  // law (f), unbounded
  // Domains that must come out empty when any domain is empty on input
  // (law f); empty list: all of them.
  std::vector<std::size_t> outputs;
  // A contractor network stops at the first empty domain, leaving the others
  // at valid enclosures: then one empty domain is enough.
  bool empty_any = false;
  std::vector<std::size_t> skip_empty;      // domains not tried empty
  std::vector<std::size_t> skip_unbounded;  // domains not tried unbounded
};

// ---------------------------------------------------------------- helpers

// Bit-for-bit equality of two intervals (all empty intervals alike).
inline bool same_bits(const Interval& a, const Interval& b) {
  if (a.is_empty() && b.is_empty()) return true;
  return std::bit_cast<std::uint64_t>(a.lb()) == std::bit_cast<std::uint64_t>(b.lb()) &&
         std::bit_cast<std::uint64_t>(a.ub()) == std::bit_cast<std::uint64_t>(b.ub());
}

namespace detail {

inline std::string str(const Interval& x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

inline bool has_nan(const Interval& a) { return std::isnan(a.lb()) || std::isnan(a.ub()); }

// Calls f(where, x_after, x_before) on every scalar atom of two domains of the
// same kind: "component i", "slice k of component i", "gate k". Returns the
// first failure.
template <class F>
::testing::AssertionResult for_atoms(const Dom& after, const Dom& before, F f) {
  if (after.index() != before.index()) return ::testing::AssertionFailure() << "domain kind changed";
  auto tube_atoms = [&](const Tube& a, const Tube& b, const std::string& pre) -> ::testing::AssertionResult {
    if (a.nb_slices() != b.nb_slices()) {
      return ::testing::AssertionFailure()
             << pre << "number of slices changed: " << b.nb_slices() << " -> " << a.nb_slices();
    }
    for (std::size_t k = 0; k <= a.nb_slices(); ++k) {
      auto r = f(pre + "gate " + std::to_string(k) + " (t = " + std::to_string(a.tdomain()->t(k)) + ")", a.gate(k),
                 b.gate(k));
      if (!r) return r;
    }
    for (std::size_t k = 0; k < a.nb_slices(); ++k) {
      auto r = f(pre + "slice " + std::to_string(k) + " " + str(a.tdomain()->slice_domain(k)), a.slice(k), b.slice(k));
      if (!r) return r;
    }
    return ::testing::AssertionSuccess();
  };
  switch (after.index()) {
    case 0:
      return f("", std::get<0>(after), std::get<0>(before));
    case 1: {
      const auto& a = std::get<1>(after);
      const auto& b = std::get<1>(before);
      if (a.size() != b.size()) return ::testing::AssertionFailure() << "box size changed";
      for (std::size_t i = 0; i < a.size(); ++i) {
        auto r = f("component " + std::to_string(i), a[i], b[i]);
        if (!r) return r;
      }
      return ::testing::AssertionSuccess();
    }
    case 2:
      return tube_atoms(std::get<2>(after), std::get<2>(before), "");
    default: {
      const auto& a = std::get<3>(after);
      const auto& b = std::get<3>(before);
      if (a.size() != b.size()) return ::testing::AssertionFailure() << "tube vector size changed";
      for (std::size_t i = 0; i < a.size(); ++i) {
        auto r = tube_atoms(a[i], b[i], "component " + std::to_string(i) + ", ");
        if (!r) return r;
      }
      return ::testing::AssertionSuccess();
    }
  }
}

}  // namespace detail

inline bool dom_is_empty(const Dom& d) {
  return std::visit([](const auto& x) { return x.is_empty(); }, d);
}

// The same domain, every atom set to y (empty set, all reals).
inline Dom filled(const Dom& d, const Interval& y) {
  switch (d.index()) {
    case 0:
      return y;
    case 1:
      return IntervalVector(std::get<1>(d).size(), y);
    case 2: {
      Tube t(std::get<2>(d));
      t.set(y);
      return t;
    }
    default: {
      TubeVector t(std::get<3>(d));
      t.set(IntervalVector(t.size(), y));
      return t;
    }
  }
}

// ---------------------------------------------------------------- the laws

// (a) every atom of `after` inside the same atom of `before`, no NaN.
inline ::testing::AssertionResult check_contracted(const Domains& after, const Domains& before,
                                             const std::string& law = "contraction") {
  for (std::size_t d = 0; d < after.size(); ++d) {
    auto r = detail::for_atoms(after[d], before[d], [&](const std::string& where, const Interval& a,
                                                        const Interval& b) {
      const std::string at = where.empty() ? "" : " " + where;
      if (detail::has_nan(a))
        return ::testing::AssertionFailure() << law << ": NaN bound in domain " << d << at << ": " << detail::str(a);
      if (a.is_subset(b)) return ::testing::AssertionSuccess();
      return ::testing::AssertionFailure()
             << law << ": domain " << d << at << " grew from " << detail::str(b) << " to " << detail::str(a);
    });
    if (!r) return r;
  }
  return ::testing::AssertionSuccess();
}

// Bit-for-bit equality of two lists of domains; the message shows both,
// named name_b and name_a.
inline ::testing::AssertionResult check_identical(const Domains& a, const Domains& b, const std::string& law,
                                            const std::string& name_a = "second", const std::string& name_b = "first") {
  for (std::size_t d = 0; d < a.size(); ++d) {
    auto r = detail::for_atoms(a[d], b[d], [&](const std::string& where, const Interval& x, const Interval& y) {
      if (same_bits(x, y)) return ::testing::AssertionSuccess();
      return ::testing::AssertionFailure() << law << ": domain " << d << (where.empty() ? "" : " ") << where << ": "
                                           << name_b << " " << detail::str(y) << ", " << name_a << " "
                                           << detail::str(x);
    });
    if (!r) return r;
  }
  return ::testing::AssertionSuccess();
}

// (b) the truth meets every domain: at every gate and at `samples` + 2 times
// of each slice for tubes. The truth is an enclosure: it must meet the domain
// (a disjoint enclosure proves the true value lost).
inline ::testing::AssertionResult check_truth(const Domains& doms, const std::vector<Truth>& truth, int samples) {
  auto meets = [](const Interval& t, const Interval& y, std::size_t d,
                  const std::string& where) -> ::testing::AssertionResult {
    if (t.intersects(y)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "truth kept: domain " << d << (where.empty() ? "" : " ") << where
                                         << ": true value " << detail::str(t) << " not in " << detail::str(y);
  };
  auto tube = [&](const Tube& x, const Trajectory1& f, std::size_t d,
                  const std::string& pre) -> ::testing::AssertionResult {
    const auto& td = *x.tdomain();
    for (std::size_t k = 0; k <= td.nb_slices(); ++k) {
      auto r = meets(f(Interval(td.t(k))), x.gate(k), d,
                     pre + "gate " + std::to_string(k) + " (t = " + std::to_string(td.t(k)) + ")");
      if (!r) return r;
    }
    for (std::size_t k = 0; k < td.nb_slices(); ++k) {
      for (int i = 0; i <= samples + 1; ++i) {
        double t = td.t(k) + (td.t(k + 1) - td.t(k)) * i / (samples + 1);
        t = std::min(std::max(t, td.t(k)), td.t(k + 1));
        std::ostringstream w;
        w.precision(17);
        w << pre << "slice " << k << " at t = " << t;
        auto r = meets(f(Interval(t)), x.slice(k), d, w.str());
        if (!r) return r;
      }
    }
    return ::testing::AssertionSuccess();
  };
  for (std::size_t d = 0; d < doms.size() && d < truth.size(); ++d) {
    const Dom& x = doms[d];
    const Truth& t = truth[d];
    ::testing::AssertionResult r = ::testing::AssertionSuccess();
    if (std::holds_alternative<std::monostate>(t)) continue;
    if (x.index() == 0) {
      r = meets(std::get<Interval>(t), std::get<0>(x), d, "");
    } else if (x.index() == 1) {
      const auto& b = std::get<1>(x);
      const auto& p = std::get<IntervalVector>(t);
      for (std::size_t i = 0; i < b.size() && r; ++i) r = meets(p[i], b[i], d, "component " + std::to_string(i));
    } else if (x.index() == 2) {
      r = tube(std::get<2>(x), std::get<Trajectory1>(t), d, "");
    } else {
      const auto& tv = std::get<3>(x);
      const auto& fs = std::get<std::vector<Trajectory1>>(t);
      for (std::size_t i = 0; i < tv.size() && r; ++i)
        r = tube(tv[i], fs[i], d, "component " + std::to_string(i) + ", ");
    }
    if (!r) return r;
  }
  return ::testing::AssertionSuccess();
}

// Copies of the domains that share nothing mutable with the originals except
// the TDomain (a Tube copy is attached to the same TDomain).
inline Domains copy(const Domains& d) { return d; }

namespace detail {

// Runs contract on a copy; an exception becomes a failure naming the law.
inline ::testing::AssertionResult run(const Contract& contract, Domains& d, const std::string& law) {
  try {
    contract(d);
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << law << ": exception " << e.what();
  }
  return ::testing::AssertionSuccess();
}

}  // namespace detail

// (c) idempotence of one case, from its contracted state `once`.
inline ::testing::AssertionResult check_idempotent(const Contract& contract, const Domains& once,
                                             const std::vector<Truth>& truth, Idempotence mode, int samples) {
  if (mode == Idempotence::None) return ::testing::AssertionSuccess();
  Domains twice = copy(once);
  auto r = detail::run(contract, twice, "idempotence");
  if (!r) return r;
  if (mode == Idempotence::Exact) {
    return check_identical(twice, once, "idempotence (a second call changed the result)", "after 2 calls",
                           "after 1 call");
  }
  r = check_contracted(twice, once, "idempotence (contraction on a second call)");
  if (!r) return r;
  return check_truth(twice, truth, samples);
}

// (e) 1 thread vs 2 threads (tbb::global_control), and two concurrent calls
// on independent copies of the same case (regenerated from `seed`).
inline ::testing::AssertionResult check_threads(const Contract& contract, const Generator& gen,
                                                     std::uint64_t seed) {
  auto fresh = [&] {
    std::mt19937_64 rng(seed);
    return gen(rng).domains;
  };
  Domains one = fresh(), two = fresh(), c1 = fresh(), c2 = fresh();
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    auto r = detail::run(contract, one, "threads (1)");
    if (!r) return r;
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    auto r = detail::run(contract, two, "threads (2)");
    if (!r) return r;
  }
  auto r = check_identical(two, one, "thread count", "2 threads", "1 thread");
  if (!r) return r;
  ::testing::AssertionResult r1 = ::testing::AssertionSuccess(), r2 = ::testing::AssertionSuccess();
  std::thread a([&] { r1 = detail::run(contract, c1, "concurrent calls"); });
  std::thread b([&] { r2 = detail::run(contract, c2, "concurrent calls"); });
  a.join();
  b.join();
  if (!r1) return r1;
  if (!r2) return r2;
  r = check_identical(c1, one, "concurrent calls", "thread A", "serial");
  if (!r) return r;
  return check_identical(c2, one, "concurrent calls", "thread B", "serial");
}

namespace detail {

inline bool listed(const std::vector<std::size_t>& v, std::size_t i) {
  return std::find(v.begin(), v.end(), i) != v.end();
}

}  // namespace detail

// (f) each domain in turn empty / all reals.
inline ::testing::AssertionResult check_special_inputs(const Contract& contract, const Case& c, const Options& o) {
  const std::size_t n = c.domains.size();
  for (std::size_t d = 0; d < n; ++d) {
    if (o.empty_inputs && !detail::listed(o.skip_empty, d)) {
      Domains in = copy(c.domains);
      in[d] = filled(in[d], Interval::empty());
      Domains out = copy(in);
      const std::string law = "empty input (domain " + std::to_string(d) + " empty)";
      auto r = detail::run(contract, out, law);
      if (r) r = check_contracted(out, in, law);
      if (r && o.empty_any) {
        if (std::none_of(out.begin(), out.end(), dom_is_empty)) {
          r = ::testing::AssertionFailure() << law << ": no domain is empty after the call";
        }
      }
      for (std::size_t e = 0; e < n && r && !o.empty_any; ++e) {
        const bool is_output = o.outputs.empty() || detail::listed(o.outputs, e);
        if (is_output && !dom_is_empty(out[e])) {
          r = ::testing::AssertionFailure() << law << ": domain " << e << " is not empty after the call";
        }
      }
      if (!r) return r;
    }
    if (o.unbounded_inputs && !detail::listed(o.skip_unbounded, d)) {
      Domains in = copy(c.domains);
      in[d] = filled(in[d], Interval());
      Domains out = copy(in);
      const std::string law = "unbounded input (domain " + std::to_string(d) + " all reals)";
      auto r = detail::run(contract, out, law);
      if (r) r = check_contracted(out, in, law);
      if (r) r = check_truth(out, c.truth, o.samples);
      if (!r) return ::testing::AssertionFailure() << law << ": " << r.message();
    }
  }
  return ::testing::AssertionSuccess();
}

// (g) monotonicity, X ⊆ Y ⇒ C(X) ⊆ C(Y): not a law every contractor obeys
// (nor claims), but what makes the fixed point of a network independent of
// the order. Y is the case's input, X a random sub-domain (each bounded atom
// shrunk by up to 30% on each side, independently: gates and slices too).
namespace detail {

inline Interval shrink_atom(const Interval& y, std::mt19937_64& rng) {
  if (y.is_empty() || y.is_unbounded()) return y;
  std::uniform_real_distribution<double> u(0.0, 0.3);
  const double w = y.diam(), a = y.lb() + u(rng) * w, b = y.ub() - u(rng) * w;
  return a <= b ? Interval(a, b) & y : y;
}

inline void shrink_tube(Tube& x, std::mt19937_64& rng) {
  const Tube::Writer w = x.write();
  for (auto& y : w.slices()) y = shrink_atom(y, rng);
  for (auto& y : w.gates()) y = shrink_atom(y, rng);
}

}  // namespace detail

inline Dom shrunk(const Dom& d, std::mt19937_64& rng) {
  Dom r = d;
  if (auto* x = std::get_if<Interval>(&r)) *x = detail::shrink_atom(*x, rng);
  if (auto* x = std::get_if<IntervalVector>(&r)) {
    for (auto& y : *x) y = detail::shrink_atom(y, rng);
  }
  if (auto* x = std::get_if<Tube>(&r)) detail::shrink_tube(*x, rng);
  if (auto* x = std::get_if<TubeVector>(&r)) {
    for (std::size_t i = 0; i < x->size(); ++i) detail::shrink_tube((*x)[i], rng);
  }
  return r;
}

inline ::testing::AssertionResult check_monotone(const Contract& contract, const Generator& gen,
                                                 const Options& o = {}) {
  for (int i = 0; i < o.cases; ++i) {
    const std::uint64_t seed = o.seed + static_cast<std::uint64_t>(i);
    std::mt19937_64 rng(seed);
    const Case c = gen(rng);
    Domains big = copy(c.domains), small;
    std::mt19937_64 srng(seed ^ 0x5eed);
    for (const auto& d : c.domains) small.push_back(shrunk(d, srng));
    auto r = detail::run(contract, big, "monotonicity (C(Y))");
    if (r) r = detail::run(contract, small, "monotonicity (C(X))");
    if (r) r = check_contracted(small, big, "monotonicity: X ⊆ Y but C(X) ⊄ C(Y)");
    if (!r) return ::testing::AssertionFailure() << "case " << i << " (seed " << seed << "): " << r.message();
  }
  return ::testing::AssertionSuccess();
}

// All the laws on o.cases random cases. Use as
//   EXPECT_TRUE(kit::check_laws(contract, gen, options));
inline ::testing::AssertionResult check_laws(const Contract& contract, const Generator& gen, const Options& o = {}) {
  for (int i = 0; i < o.cases; ++i) {
    const std::uint64_t seed = o.seed + static_cast<std::uint64_t>(i);
    std::mt19937_64 rng(seed);
    const Case c = gen(rng);
    auto fail = [&](const ::testing::AssertionResult& r) {
      return ::testing::AssertionFailure() << "case " << i << " (seed " << seed << "): " << r.message();
    };
    auto r = check_truth(c.domains, c.truth, o.samples);
    if (!r) return fail(::testing::AssertionFailure() << "generator: the truth is not in the input: " << r.message());
    Domains out = copy(c.domains);
    r = detail::run(contract, out, "contract");
    if (r) r = check_contracted(out, c.domains);
    if (r) r = check_truth(out, c.truth, o.samples);
    if (r) r = check_idempotent(contract, out, c.truth, o.idempotence, o.samples);
    if (r && o.threads) r = check_threads(contract, gen, seed);
    if (r) r = check_special_inputs(contract, c, o);
    if (!r) return fail(r);
  }
  return ::testing::AssertionSuccess();
}

// (d) A composition run with two insertion orders: contract(d, order) applies
// (or adds to a network) its parts in that order. Both results contract the
// input and keep the truth; with `same_fixed_point` they are also equal bit
// for bit (monotone, idempotent parts propagated to the exact fixed point).
using OrderedContract = std::function<void(Domains&, const std::vector<std::size_t>&)>;

inline ::testing::AssertionResult check_order_independent(const OrderedContract& contract, const Generator& gen,
                                                          std::vector<std::size_t> order1,
                                                          std::vector<std::size_t> order2, bool same_fixed_point,
                                                          const Options& o = {}) {
  for (int i = 0; i < o.cases; ++i) {
    const std::uint64_t seed = o.seed + static_cast<std::uint64_t>(i);
    std::mt19937_64 rng(seed);
    const Case c = gen(rng);
    Domains a = copy(c.domains), b = copy(c.domains);
    auto r = detail::run([&](Domains& d) { contract(d, order1); }, a, "order 1");
    if (r) r = detail::run([&](Domains& d) { contract(d, order2); }, b, "order 2");
    if (r) r = check_contracted(a, c.domains, "order 1, contraction");
    if (r) r = check_contracted(b, c.domains, "order 2, contraction");
    if (r) r = check_truth(a, c.truth, o.samples);
    if (r) r = check_truth(b, c.truth, o.samples);
    if (r && same_fixed_point) r = check_identical(b, a, "order independence", "order 2", "order 1");
    if (!r) return ::testing::AssertionFailure() << "case " << i << " (seed " << seed << "): " << r.message();
  }
  return ::testing::AssertionSuccess();
}

// ---------------------------------------------------------------- generators' helpers

// A random interval around the enclosure y of a true value: each side widened
// by 0 .. w (outward: one ulp more), or unbounded with probability p_inf.
inline Interval around(const Interval& y, std::mt19937_64& rng, double w = 0.5, double p_inf = 0.0) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double inf = std::numeric_limits<double>::infinity();
  double lo = u(rng) < p_inf ? -inf : std::nextafter(y.lb() - w * u(rng), -inf);
  double hi = u(rng) < p_inf ? inf : std::nextafter(y.ub() + w * u(rng), inf);
  return Interval(lo, hi);
}

// A tube around the trajectory f: slices around f over the slice, gates around
// f at t_k (all reals with probability p_unknown), widened by up to w.
inline Tube tube_around(const std::shared_ptr<TDomain>& td, const Trajectory1& f, std::mt19937_64& rng, double w,
                        double p_unknown = 0.0) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Interval> s(td->nb_slices()), g(td->nb_slices() + 1);
  for (std::size_t k = 0; k < s.size(); ++k)
    s[k] = u(rng) < p_unknown ? Interval() : around(f(td->slice_domain(k)), rng, w);
  for (std::size_t k = 0; k < g.size(); ++k)
    g[k] = u(rng) < p_unknown ? Interval() : around(f(Interval(td->t(k))), rng, w);
  return Tube(td, s, g);
}

// x(t) = sum of a_i sin(w_i t + p_i), with x' = sum of a_i w_i cos(w_i t + p_i),
// evaluated in interval arithmetic: X(t) and V(t) contain the exact values
// (and, for an interval t, the exact ranges).
struct SineSum {
  std::vector<double> a, w, p;

  explicit SineSum(std::mt19937_64& rng, int terms = 3) {
    std::uniform_real_distribution<double> ua(-1.5, 1.5), uw(0.3, 3.0), up(-3.0, 3.0);
    for (int i = 0; i < terms; ++i) {
      a.push_back(ua(rng));
      w.push_back(uw(rng));
      p.push_back(up(rng));
    }
  }
  Interval x(const Interval& t) const {
    Interval r(0.0);
    for (std::size_t i = 0; i < a.size(); ++i) r += Interval(a[i]) * sin(Interval(w[i]) * t + Interval(p[i]));
    return r;
  }
  Interval v(const Interval& t) const {
    Interval r(0.0);
    for (std::size_t i = 0; i < a.size(); ++i) {
      r += Interval(a[i]) * Interval(w[i]) * cos(Interval(w[i]) * t + Interval(p[i]));
    }
    return r;
  }
};

// The trajectory t ↦ x(t) of f and its derivative, for a Case's truth.
inline Trajectory1 position(const SineSum& f) {
  return [f](const Interval& t) { return f.x(t); };
}
inline Trajectory1 velocity(const SineSum& f) {
  return [f](const Interval& t) { return f.v(t); };
}

// Random increasing time points from t0, n slices of widths in [0.05, 0.5].
inline std::shared_ptr<TDomain> random_tdomain(std::mt19937_64& rng, int n, double t0 = 0.0) {
  std::uniform_real_distribution<double> d(0.05, 0.5);
  std::vector<double> ts{t0};
  for (int i = 0; i < n; ++i) ts.push_back(ts.back() + d(rng));
  return TDomain::create(ts);
}

}  // namespace sillage::kit
