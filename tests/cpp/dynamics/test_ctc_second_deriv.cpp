// CtcSecondDeriv: x'' ∈ [a] on each slice, so the slice of x lies within the
// hull of its gates bowed by −[a] [0, δ²/8]. The contractor laws on sums of
// sines (exact x and x''), the exact bow of a parabola, the network form,
// emptiness and argument errors.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "sillage/testing/contractor_kit.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/dynamics/ctc_second_deriv.h"
#include "sillage/error.h"
#include "sillage/interval/elementary.h"

using namespace sillage;

namespace {

// x'' of a sum of sines: −Σ a w² sin(w t + p).
Interval accel(const kit::SineSum& f, const Interval& t) {
  Interval r(0.0);
  for (std::size_t i = 0; i < f.a.size(); ++i) {
    r -= Interval(f.a[i]) * sqr(Interval(f.w[i])) * sin(Interval(f.w[i]) * t + Interval(f.p[i]));
  }
  return r;
}

// Domains: x (wide slices, gates near the truth), a (slices around x'').
kit::Case second_case(std::mt19937_64& rng) {
  const kit::SineSum f(rng);
  const auto td = kit::random_tdomain(rng, 20);
  const std::size_t n = td->nb_slices();
  std::vector<Interval> acc(n);
  for (std::size_t k = 0; k < n; ++k) acc[k] = kit::around(accel(f, td->slice_domain(k)), rng, 0.5, 0.1);
  Tube x = kit::tube_around(td, kit::position(f), rng, 1.0);
  for (std::size_t k = 0; k <= n; ++k) x.set_gate(k, kit::around(f.x(Interval(td->t(k))), rng, 0.05));
  kit::Case c;
  c.domains = {x, Tube(td, acc, std::vector<Interval>(n + 1, Interval()))};
  c.truth = {kit::position(f), std::monostate{}};
  return c;
}

}  // namespace

TEST(CtcSecondDeriv, ContractorLaws) {
  kit::Options o;
  o.outputs = {0};
  EXPECT_TRUE(kit::check_laws([](kit::Domains& d) { CtcSecondDeriv().contract(std::get<Tube>(d[0]), std::get<Tube>(d[1])); },
                              second_case, o));
}

TEST(CtcSecondDeriv, ExactBowOfAParabola) {
  // x = t²/2 on [0, 1] (x'' = 1): gates 0 and 1/2, chord t/2, x − chord = −t (1 − t) / 2 ∈ [−1/8, 0].
  // The slice comes out as [0, 1/2] − [0, 1/8] = [−1/8, 1/2], which holds x([0, 1]) = [0, 1/2].
  const auto td = TDomain::create(std::vector<double>{0.0, 1.0});
  Tube x(td);
  x.set_gate(0, Interval(0.0));
  x.set_gate(1, Interval(0.5));
  ASSERT_TRUE(CtcSecondDeriv().contract(x, Tube(td, Interval(1.0))));
  EXPECT_EQ(x.slice(0), Interval(-0.125, 0.5));
  // With x'' in [-0.8, 0.8] around the same gates: [0, 1/2] + [-0.1, 0.1].
  Tube y(td);
  y.set_gate(0, Interval(0.0));
  y.set_gate(1, Interval(0.5));
  ASSERT_TRUE(CtcSecondDeriv().contract(y, Tube(td, Interval(-0.8, 0.8))));
  EXPECT_NEAR(y.slice(0).lb(), -0.1, 1e-15);
  EXPECT_NEAR(y.slice(0).ub(), 0.6, 1e-15);
}

TEST(CtcSecondDeriv, UnboundedAccelerationLearnsNothing) {
  const auto td = TDomain::create(0.0, 2.0, 1.0);
  Tube x(td, Interval(-5.0, 5.0));
  x.set_gate(1, Interval(0.0));
  ASSERT_TRUE(CtcSecondDeriv().contract(x, Tube(td, Interval::pos_reals())));
  EXPECT_EQ(x.slice(0), Interval(-5.0, 5.0));
  EXPECT_EQ(x.slice(1), Interval(-5.0, 5.0));
}

TEST(CtcSecondDeriv, EmptyAccelerationEmptiesX) {
  // A gate always meets its slices and the bow holds 0: only an empty input leaves no trajectory.
  const auto td = TDomain::create(std::vector<double>{0.0, 1.0});
  Tube x(td, Interval(1.0, 2.0));
  EXPECT_FALSE(CtcSecondDeriv().contract(x, Tube(td, Interval::empty())));
  EXPECT_TRUE(x.is_empty());
}

TEST(CtcSecondDeriv, NetworkEqualsTheDirectCall) {
  std::mt19937_64 rng(3);
  const kit::Case c = second_case(rng);
  Tube x = std::get<Tube>(c.domains[0]);
  const Tube& a = std::get<Tube>(c.domains[1]);
  auto nx = std::make_shared<Tube>(x);
  ASSERT_TRUE(CtcSecondDeriv().contract(x, a));
  EXPECT_FALSE(std::get<Tube>(c.domains[0]).is_subset(x));  // not vacuous
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcSecondDeriv>(), {nx, std::make_shared<Tube>(a)});
  EXPECT_FALSE(cn.contract().empty);
  EXPECT_TRUE(nx->is_subset(x) && x.is_subset(*nx));
}

TEST(CtcSecondDeriv, TubeVectorsInANetworkAndErrors) {
  const auto td = TDomain::create(std::vector<double>{0.0, 1.0});
  auto x = std::make_shared<TubeVector>(td, 2);
  x->set_gate(0, IntervalVector{Interval(0.0), Interval(1.0)});
  x->set_gate(1, IntervalVector{Interval(0.0), Interval(1.0)});
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcSecondDeriv>(),
         {x, std::make_shared<TubeVector>(td, IntervalVector{Interval(-8.0, 8.0), Interval(0.0)})});
  EXPECT_FALSE(cn.contract().empty);
  EXPECT_EQ((*x)[0].slice(0), Interval(-1.0, 1.0));
  EXPECT_EQ((*x)[1].slice(0), Interval(1.0));
  Tube y(td);
  EXPECT_THROW(CtcSecondDeriv().contract(y, Tube(TDomain::create(0.0, 1.0, 0.5))), DimensionError);
}
