// The generic contractor laws (sillage/testing/contractor_kit.h) on the tube
// contractors: CtcDeriv (each sweep, scalar and vector, restricted), CtcEval,
// CtcIncrement, CtcQEval, CtcEvalList. True trajectories: sums of sines with their exact
// derivative (kit::SineSum). The thesis values stay in each
// contractor's own tests.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

#include "deriv_test_util.h"
#include "sillage/testing/contractor_kit.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/dynamics/ctc_eval_list.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/dynamics/ctc_qeval.h"

using namespace sillage;
using sillage::kit::SineSum;

namespace {

const auto pos = kit::position;
const auto vel = kit::velocity;

// x' = v: x around f with many unknown slices and gates, v around f'.
// (The example of docs/contractors.md, "Testing a contractor".)
kit::Case deriv_case(std::mt19937_64& rng) {  // x' = v around a known trajectory f
  const kit::SineSum f(rng);
  const auto td = kit::random_tdomain(rng, 30);
  const kit::Trajectory1 x = kit::position(f), v = kit::velocity(f);
  return {{kit::tube_around(td, x, rng, 0.3, 0.5), kit::tube_around(td, v, rng, 0.5)}, {x, v}};
}

kit::Contract deriv(TimePropag p) {
  return [p](kit::Domains& d) { CtcDeriv(p).contract(std::get<Tube>(d[0]), std::get<Tube>(d[1])); };
}

kit::Options deriv_options(kit::Idempotence idem) {
  kit::Options o;
  o.idempotence = idem;
  o.outputs = {0};  // only x is contracted; an empty v empties x
  return o;
}

// Under both rounding policies of the slice rule (deriv_test_util.h).
class DynamicsLawsRounding : public sillage::test::BothRoundings {};
INSTANTIATE_TEST_SUITE_P(Rounding, DynamicsLawsRounding, ::testing::Bool(), sillage::test::rounding_name);

TEST_P(DynamicsLawsRounding, CtcDerivFwdBwd) {
  // FWD_BWD claims the fixed point bit for bit (ctc_deriv.h).
  EXPECT_TRUE(kit::check_laws(deriv(TimePropag::FWD_BWD), deriv_case, deriv_options(kit::Idempotence::Exact)));
}

TEST(DynamicsLaws, CtcDerivOneSweep) {
  // One sweep is not a fixed point: a slice contracted late tightens a gate
  // the sweep has passed (only FWD_BWD claims idempotence).
  const auto o = deriv_options(kit::Idempotence::ContractionOnly);
  EXPECT_TRUE(kit::check_laws(deriv(TimePropag::FORWARD), deriv_case, o));
  EXPECT_TRUE(kit::check_laws(deriv(TimePropag::BACKWARD), deriv_case, o));
}

TEST(DynamicsLaws, CtcDerivRestricted) {
  // Slices 5..20 only: outside, nothing changes (contraction keeps the rest).
  const auto contract = [](kit::Domains& d) {
    Tube& x = std::get<Tube>(d[0]);
    const Tube before = x;
    CtcDeriv().contract(x, std::get<Tube>(d[1]), 5, 20);
    if (x.is_empty()) return;
    for (std::size_t k = 0; k < x.nb_slices(); ++k) {
      if (k < 5 || k > 20) {
        ASSERT_TRUE(kit::same_bits(x.slice(k), before.slice(k))) << "slice " << k;
      }
    }
  };
  auto o = deriv_options(kit::Idempotence::Exact);
  o.outputs = {};  // an empty v outside 5..20 is not read
  o.empty_inputs = false;
  EXPECT_TRUE(kit::check_laws(contract, deriv_case, o));
}

TEST(DynamicsLaws, CtcDerivOverATimeInterval) {
  const auto contract = [](kit::Domains& d) {
    // Inside [t_0, t_N]: at least 30 slices of 0.05 at least.
    CtcDeriv().contract(std::get<Tube>(d[0]), std::get<Tube>(d[1]), Interval(0.7, 1.4));
  };
  auto o = deriv_options(kit::Idempotence::Exact);
  o.outputs = {};  // an empty v outside [0.7, 1.4] is not read
  o.empty_inputs = false;
  EXPECT_TRUE(kit::check_laws(contract, deriv_case, o));
}

TEST(DynamicsLaws, CtcDerivVector) {
  const auto gen = [](std::mt19937_64& rng) {
    const SineSum f(rng), g(rng);
    const auto td = kit::random_tdomain(rng, 20);
    kit::Case c;
    c.domains = {TubeVector({kit::tube_around(td, pos(f), rng, 0.3, 0.5), kit::tube_around(td, pos(g), rng, 0.3, 0.5)}),
                 TubeVector({kit::tube_around(td, vel(f), rng, 0.5), kit::tube_around(td, vel(g), rng, 0.5)})};
    c.truth = {std::vector<kit::Trajectory1>{pos(f), pos(g)}, std::vector<kit::Trajectory1>{vel(f), vel(g)}};
    return c;
  };
  const auto contract = [](kit::Domains& d) {
    CtcDeriv().contract(std::get<TubeVector>(d[0]), std::get<TubeVector>(d[1]));
  };
  auto o = deriv_options(kit::Idempotence::Exact);
  o.cases = 20;
  EXPECT_TRUE(kit::check_laws(contract, gen, o));
}

// z = y(t), y' = w: domains t, z, y, w. t* uniform in the TDomain; [t] a
// random interval around it (degenerate one time in four).
kit::Case eval_case(std::mt19937_64& rng) {
  const SineSum f(rng);
  const auto td = kit::random_tdomain(rng, 30);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double ts = td->t(0) + u(rng) * (td->t(td->nb_slices()) - td->t(0));
  const Interval tt = u(rng) < 0.25 ? Interval(ts) : kit::around(Interval(ts), rng, 2.0);
  kit::Case c;
  c.domains = {tt, kit::around(f.x(Interval(ts)), rng, 0.3), kit::tube_around(td, pos(f), rng, 0.5, 0.4),
               kit::tube_around(td, vel(f), rng, 0.5)};
  c.truth = {Interval(ts), f.x(Interval(ts)), pos(f), vel(f)};
  return c;
}

kit::Contract eval(bool sampling) {
  return [sampling](kit::Domains& d) {
    CtcEval e;
    e.enable_time_sampling(sampling);
    e.contract(std::get<Interval>(d[0]), std::get<Interval>(d[1]), std::get<Tube>(d[2]), std::get<Tube>(d[3]));
  };
}

TEST(DynamicsLaws, CtcEval) {
  kit::Options o;
  o.cases = 30;
  o.idempotence = kit::Idempotence::Exact;  // one call iterates to its own fixed point
  o.outputs = {0, 1, 2};  // Lemma 5.1: t, z and y emptied together
  EXPECT_TRUE(kit::check_laws(eval(false), eval_case, o));
}

TEST(DynamicsLaws, CtcEvalSamplingTheTDomain) {
  kit::Options o;
  o.cases = 30;
  o.idempotence = kit::Idempotence::ContractionOnly;
  o.outputs = {0, 1, 2};
  EXPECT_TRUE(kit::check_laws(eval(true), eval_case, o));
}

TEST(DynamicsLaws, CtcEvalWithoutDerivative) {
  // Only [t], [z] and the gate at a time point t are contracted.
  const auto contract = [](kit::Domains& d) {
    CtcEval().contract(std::get<Interval>(d[0]), std::get<Interval>(d[1]), std::get<Tube>(d[2]));
  };
  kit::Options o;
  o.cases = 30;
  o.idempotence = kit::Idempotence::ContractionOnly;
  o.outputs = {0, 1, 2};
  o.skip_empty = o.skip_unbounded = {3};  // w is not used
  EXPECT_TRUE(kit::check_laws(contract, eval_case, o));
}

TEST(DynamicsLaws, CtcEvalVector) {
  // z = y(t) in 2-d with one t: domains t, z, y, w.
  const auto gen = [](std::mt19937_64& rng) {
    const SineSum f(rng), g(rng);
    const auto td = kit::random_tdomain(rng, 20);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double ts = td->t(0) + u(rng) * (td->t(td->nb_slices()) - td->t(0));
    const IntervalVector z{f.x(Interval(ts)), g.x(Interval(ts))};
    kit::Case c;
    c.domains = {kit::around(Interval(ts), rng, 1.0),
                 IntervalVector{kit::around(z[0], rng, 0.3), kit::around(z[1], rng, 0.3)},
                 TubeVector({kit::tube_around(td, pos(f), rng, 0.5, 0.4), kit::tube_around(td, pos(g), rng, 0.5, 0.4)}),
                 TubeVector({kit::tube_around(td, vel(f), rng, 0.5), kit::tube_around(td, vel(g), rng, 0.5)})};
    c.truth = {Interval(ts), z, std::vector<kit::Trajectory1>{pos(f), pos(g)},
               std::vector<kit::Trajectory1>{vel(f), vel(g)}};
    return c;
  };
  const auto contract = [](kit::Domains& d) {
    CtcEval().contract(std::get<Interval>(d[0]), std::get<IntervalVector>(d[1]), std::get<TubeVector>(d[2]),
                       std::get<TubeVector>(d[3]));
  };
  kit::Options o;
  o.cases = 20;
  o.idempotence = kit::Idempotence::ContractionOnly;
  o.outputs = {0, 1, 2};
  EXPECT_TRUE(kit::check_laws(contract, gen, o));
}

// x(t_{k+1}) - x(t_k) ∈ [i](k): domains x, i (the increments' tube, whose
// gates are not used; its truth is not a trajectory).
kit::Case increment_case(std::mt19937_64& rng) {
  const SineSum f(rng);
  const auto td = kit::random_tdomain(rng, 30);
  std::vector<Interval> inc(td->nb_slices());
  for (std::size_t k = 0; k < inc.size(); ++k) {
    inc[k] = kit::around(f.x(Interval(td->t(k + 1))) - f.x(Interval(td->t(k))), rng, 0.1);
  }
  kit::Case c;
  c.domains = {kit::tube_around(td, pos(f), rng, 0.5, 0.7),
               Tube(td, inc, std::vector<Interval>(td->nb_slices() + 1, Interval()))};
  c.truth = {pos(f), std::monostate{}};
  return c;
}

TEST(DynamicsLaws, CtcIncrement) {
  const auto contract = [](kit::Domains& d) { CtcIncrement().contract(std::get<Tube>(d[0]), std::get<Tube>(d[1])); };
  kit::Options o;
  o.outputs = {0};
  // "One forward-backward call reaches the fixed point" (ctc_increment.h).
  o.idempotence = kit::Idempotence::Exact;
  EXPECT_TRUE(kit::check_laws(contract, increment_case, o));
}

// Fixes on a 2-d trajectory (one of them wrong if one_wrong): domains x, v,
// then (t_i, z_i) for 4 observations.
kit::Case fixes_case(std::mt19937_64& rng, bool one_wrong) {
  const SineSum f(rng), g(rng);
  const auto td = kit::random_tdomain(rng, 20);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 3);
  kit::Case c;
  c.domains = {TubeVector({kit::tube_around(td, pos(f), rng, 1.0, 0.3), kit::tube_around(td, pos(g), rng, 1.0, 0.3)}),
               TubeVector({kit::tube_around(td, vel(f), rng, 0.3), kit::tube_around(td, vel(g), rng, 0.3)})};
  c.truth = {std::vector<kit::Trajectory1>{pos(f), pos(g)}, std::vector<kit::Trajectory1>{vel(f), vel(g)}};
  const int wrong = one_wrong ? pick(rng) : -1;
  for (int i = 0; i < 4; ++i) {
    const double ts = td->t(0) + u(rng) * (td->t(td->nb_slices()) - td->t(0));
    const Interval t = kit::around(Interval(ts), rng, 0.3) & Interval(td->t(0), td->t(td->nb_slices()));
    IntervalVector z{kit::around(f.x(Interval(ts)), rng, 0.2), kit::around(g.x(Interval(ts)), rng, 0.2)};
    if (i == wrong) z = IntervalVector{Interval(5.0, 6.0), Interval(-6.0, -5.0)};  // |x| <= 4.5: never true
    c.domains.push_back(t);
    c.domains.push_back(z);
    if (i == wrong) {  // no truth in a wrong fix
      c.truth.emplace_back();
      c.truth.emplace_back();
    } else {
      c.truth.emplace_back(std::in_place_type<Interval>, ts);
      c.truth.emplace_back(std::in_place_type<IntervalVector>, IntervalVector{f.x(Interval(ts)), g.x(Interval(ts))});
    }
  }
  return c;
}

kit::Case qeval_case(std::mt19937_64& rng) { return fixes_case(rng, true); }

// The fixes of the domains (t_i, z_i) held by the NetworkCtc `make` builds, on
// x and v in a network of their own; x written back.
template <class Make>
void fixes_in_a_network(kit::Domains& d, Make make) {
  std::vector<TubeObservation> obs;
  for (std::size_t i = 2; i + 1 < d.size(); i += 2) {
    obs.push_back({std::get<Interval>(d[i]), std::get<IntervalVector>(d[i + 1]), nullptr});
  }
  auto x = std::make_shared<TubeVector>(std::get<TubeVector>(d[0]));
  auto v = std::make_shared<TubeVector>(std::get<TubeVector>(d[1]));
  ContractorNetwork cn;
  cn.add(make(std::move(obs)), {x, v});
  cn.contract();
  d[0] = *x;
}

void qeval_contract(kit::Domains& d) {
  std::vector<TubeObservation> obs;
  for (std::size_t i = 2; i + 1 < d.size(); i += 2) {
    obs.push_back({std::get<Interval>(d[i]), std::get<IntervalVector>(d[i + 1]), nullptr});
  }
  CtcQEval(1).contract(std::get<TubeVector>(d[0]), std::get<TubeVector>(d[1]), obs);
}

TEST(DynamicsLaws, CtcQEvalWithOneWrongFix) {
  kit::Options o;
  o.cases = 20;
  o.idempotence = kit::Idempotence::ContractionOnly;  // a q-relaxed intersection is not idempotent
  o.outputs = {0};
  // An empty fix is one wrong observation (q = 1 tolerates it), not an empty
  // result; an unknown fix time or value is tried.
  o.skip_empty = {2, 3, 4, 5, 6, 7, 8, 9};
  EXPECT_TRUE(kit::check_laws(qeval_contract, qeval_case, o));
}

// The network form of CtcQEval on the same cases: the fixes held by the
// contractor (the domains t_i, z_i are read, not contracted).
TEST(DynamicsLaws, CtcQEvalInANetwork) {
  const auto contract = [](kit::Domains& d) {
    fixes_in_a_network(d, [](std::vector<TubeObservation> obs) { return std::make_shared<CtcQEval>(1, std::move(obs)); });
  };
  kit::Options o;
  o.cases = 20;
  o.idempotence = kit::Idempotence::ContractionOnly;
  o.outputs = {0};
  o.empty_any = true;
  o.threads = false;  // a network per call
  o.skip_empty = {2, 3, 4, 5, 6, 7, 8, 9};
  EXPECT_TRUE(kit::check_laws(contract, qeval_case, o));
}

// (g) Monotone: X ⊆ Y ⇒ C(X) ⊆ C(Y).
TEST(DynamicsLaws, CtcDerivAndCtcIncrementAreMonotone) {
  kit::Options o;
  o.cases = 60;
  EXPECT_TRUE(kit::check_monotone(deriv(TimePropag::FWD_BWD), deriv_case, o));
  EXPECT_TRUE(kit::check_monotone(deriv(TimePropag::FORWARD), deriv_case, o));
  EXPECT_TRUE(kit::check_monotone(deriv(TimePropag::BACKWARD), deriv_case, o));
  const auto increment = [](kit::Domains& d) { CtcIncrement().contract(std::get<Tube>(d[0]), std::get<Tube>(d[1])); };
  EXPECT_TRUE(kit::check_monotone(increment, increment_case, o));
}

// CtcEval is monotone: every gate is swept to both ends of the domain and
// every slice gets the hull of its polygon, whatever the input (a sweep that
// stopped once its front held a gate made the result depend on how far the
// input was already contracted). CtcQEval, built on it, is too.
TEST(DynamicsLaws, CtcEvalIsMonotone) {
  kit::Options o;
  o.cases = 60;
  EXPECT_TRUE(kit::check_monotone(eval(false), eval_case, o));
  EXPECT_TRUE(kit::check_monotone(qeval_contract, qeval_case, o));
}

}  // namespace

// CtcEvalList on the same fixes, all true, in a network of its own (the fronts
// beyond each [t] are its own then): the fixes held by the contractor.
TEST(DynamicsLaws, CtcEvalListInANetwork) {
  const auto contract = [](kit::Domains& d) {
    fixes_in_a_network(d, [](std::vector<TubeObservation> obs) { return std::make_shared<CtcEvalList>(std::move(obs)); });
  };
  kit::Options o;
  o.cases = 20;
  o.idempotence = kit::Idempotence::ContractionOnly;  // a network at the ratio 0.01
  o.outputs = {0};
  o.empty_any = true;
  o.threads = false;  // a network per call
  o.skip_empty = {2, 4, 6, 8};  // a time outside the domain is bad input (Error), as for CtcQEval
  EXPECT_TRUE(kit::check_laws(contract, [](std::mt19937_64& rng) { return fixes_case(rng, false); }, o));
}
