// CtcBiasedIncrement: x(t_j) − x(t_i) ∈ Σ [i](k) − b0 (t_j − t_i) + [−d, d] (t_j − t_i), b0 shared.
// The contractor laws on sums of sines measured with a constant bias and a drift, exact values
// on a small case, the bias and the gates against a brute force over every pair of gates, the
// network form (a bias learnt from two far gates narrows the gates between them) and emptiness.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>

#include "sillage/testing/contractor_kit.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/dynamics/ctc_biased_increment.h"
#include "sillage/error.h"

using namespace sillage;

namespace {

// A true x (sum of sines), a true bias b and drift |d_k| <= drift per slice, the increments
// measured as i_k = x(t_{k+1}) − x(t_k) + (b − d_k) δ_k (enclosed, then widened a little).
struct Biased {
  std::shared_ptr<TDomain> td;
  kit::SineSum f;
  double b;
  Tube inc;  // the increments are its slices; its gates say nothing
  Biased(std::mt19937_64& rng, double drift, int n, double noise)
      : td(kit::random_tdomain(rng, n)), f(rng), b(std::uniform_real_distribution<double>(-1, 1)(rng)), inc(td) {
    std::uniform_real_distribution<double> u(-drift, drift);
    const Tube::Writer w = inc.write();
    for (std::size_t k = 0; k < td->nb_slices(); ++k) {
      const Interval dx = f.x(Interval(td->t(k + 1))) - f.x(Interval(td->t(k)));
      w.slices()[k] = kit::around(dx + (Interval(b) - Interval(u(rng))) * td->slice_width(k), rng, noise);
    }
  }
};

kit::Case biased_case(std::mt19937_64& rng) {
  const double drift = std::uniform_real_distribution<double>(0, 0.2)(rng);
  const Biased m(rng, drift, 20, 0.02);
  Tube x = kit::tube_around(m.td, kit::position(m.f), rng, 1.0, 0.2);
  kit::Case c;
  c.domains = {x, kit::around(Interval(m.b), rng, 2.0, 0.2), m.inc};
  c.truth = {kit::position(m.f), Interval(m.b), std::monostate{}};
  return c;
}

// The bias and the gates of the contractor's fixed point by brute force over every pair of gates:
// b0 ∈ ∩ (S_ij − ([x]_j − [x]_i)) / (t_j − t_i), then [x]_j ∩= [x]_i + S_ij − [b0] (t_j − t_i).
void brute_force(const TDomain& td, std::vector<Interval>& g, Interval& b, const Tube& inc, double drift) {
  const std::size_t n = td.nb_slices();
  const auto sum = [&](std::size_t i, std::size_t j) {
    Interval s(0.0);
    for (std::size_t k = i; k < j; ++k) s += inc.slice(k) + Interval(-drift, drift) * td.slice_width(k);
    return s;
  };
  for (int round = 0; round < 20; ++round) {
    for (std::size_t i = 0; i <= n; ++i) {
      for (std::size_t j = i + 1; j <= n; ++j) {
        b &= (sum(i, j) - (g[j] - g[i])) / (Interval(td.t(j)) - Interval(td.t(i)));
      }
    }
    for (std::size_t i = 0; i <= n; ++i) {
      for (std::size_t j = 0; j <= n; ++j) {
        const Interval tau = Interval(td.t(std::max(i, j))) - Interval(td.t(std::min(i, j)));
        if (i < j) g[j] &= g[i] + sum(i, j) - b * tau;
        if (j < i) g[j] &= g[i] - sum(j, i) + b * tau;
      }
    }
  }
}

bool near(const Interval& a, const Interval& b, double tol) {
  return std::abs(a.lb() - b.lb()) <= tol && std::abs(a.ub() - b.ub()) <= tol;
}

}  // namespace

TEST(CtcBiasedIncrement, ContractorLaws) {
  kit::Options o;
  o.outputs = {0, 1};
  o.skip_empty = {};
  EXPECT_TRUE(kit::check_laws(
      [](kit::Domains& d) {
        CtcBiasedIncrement(0.1).contract(std::get<Tube>(d[0]), std::get<Interval>(d[1]), std::get<Tube>(d[2]));
      },
      biased_case, o));
}

TEST(CtcBiasedIncrement, TruthKeptWithTheDrift) {
  // The drift used by the truth is the contractor's own bound: the truth stays inside, the
  // bias is narrowed around the true one when two gates are known far apart.
  std::mt19937_64 rng(7);
  for (int c = 0; c < 50; ++c) {
    const double drift = 0.05;
    const Biased m(rng, drift, 40, 0.0);
    Tube x(m.td);
    x.set_gate(0, m.f.x(Interval(m.td->t(0))));
    x.set_gate(40, m.f.x(Interval(m.td->t(40))));
    Interval b(-1, 1);
    ASSERT_TRUE(CtcBiasedIncrement(drift).contract(x, b, m.inc));
    EXPECT_TRUE(b.contains(m.b)) << b << " " << m.b;
    EXPECT_LE(b.diam(), 2 * drift + 1e-9);  // what two exact gates give: (S ± drift τ − Δx) / τ
    for (std::size_t k = 0; k <= 40; ++k) EXPECT_TRUE(x.gate(k).intersects(m.f.x(Interval(m.td->t(k))))) << k;
  }
}

TEST(CtcBiasedIncrement, ExactValues) {
  // Increments of 1 per unit time, x(0) = 0 and x(10) = 5, no drift: b0 = (10 − 5) / 10 = 0.5,
  // x(t_k) = 0.5 k.
  const auto td = TDomain::create(0.0, 10.0, 1.0);
  Tube x(td), inc(td, Interval(1.0));
  x.set_gate(0, Interval(0.0));
  x.set_gate(10, Interval(5.0));
  Interval b(-1, 1);
  ASSERT_TRUE(CtcBiasedIncrement().contract(x, b, inc));
  EXPECT_EQ(b, Interval(0.5));
  for (std::size_t k = 0; k <= 10; ++k) EXPECT_TRUE(near(x.gate(k), Interval(0.5 * k), 1e-14)) << k << x.gate(k);
  // With a drift of 0.1: b0 ∈ [0.4, 0.6], x(5) ∈ [0, 5 (1 − 0.4 + 0.1)] ∩ [5 − 5 (1 − 0.4 + 0.1), ...]:
  // from the left 5 (1 − b − d) .. 5 (1 − b + d) = [1.5, 3.5], from the right the same: [1.5, 3.5].
  Tube y(td);
  y.set_gate(0, Interval(0.0));
  y.set_gate(10, Interval(5.0));
  Interval c(-1, 1);
  ASSERT_TRUE(CtcBiasedIncrement(0.1).contract(y, c, inc));
  EXPECT_TRUE(near(c, Interval(0.4, 0.6), 1e-14)) << c;
  EXPECT_TRUE(near(y.gate(5), Interval(1.5, 3.5), 1e-13)) << y.gate(5);
}

TEST(CtcBiasedIncrement, AgainstBruteForceOverEveryPair) {
  std::mt19937_64 rng(11);
  for (int c = 0; c < 60; ++c) {
    const double drift = std::uniform_real_distribution<double>(0, 0.1)(rng);
    const Biased m(rng, drift, 12, 0.01);
    Tube x = kit::tube_around(m.td, kit::position(m.f), rng, 0.5, 0.3);
    Interval b = kit::around(Interval(m.b), rng, 1.0, 0.3);
    std::vector<Interval> g(x.data().gates.begin(), x.data().gates.end());
    Interval bb = b;
    brute_force(*m.td, g, bb, m.inc, drift);
    ASSERT_TRUE(CtcBiasedIncrement(drift).contract(x, b, m.inc));
    EXPECT_TRUE(b.contains(m.b));
    EXPECT_TRUE(near(b, bb, 1e-9)) << c << ": " << b << " vs brute force " << bb;
    for (std::size_t k = 0; k < g.size(); ++k) EXPECT_TRUE(near(x.gate(k), g[k], 1e-9)) << c << " gate " << k;
  }
}

TEST(CtcBiasedIncrement, InANetworkTheBiasNarrowsTheGatesBetween) {
  // The bias learnt from the two ends narrows the middle, where a per-step bias of the same
  // class (CtcIncrement with |b| <= 1) would leave it much wider.
  const auto td = TDomain::create(0.0, 100.0, 1.0);
  auto x = std::make_shared<Tube>(td);
  auto inc = std::make_shared<Tube>(td, Interval(1.0));
  auto b = std::make_shared<Interval>(-1, 1);
  x->set_gate(0, Interval(-0.1, 0.1));
  x->set_gate(100, Interval(69.9, 70.1));
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcBiasedIncrement>(0.01), {x, b, inc});
  const ContractStats s = cn.contract();
  ASSERT_FALSE(s.empty);
  EXPECT_TRUE(b->contains(0.3) && b->diam() < 0.025) << *b;
  // from either end: ±0.1 + 50 (diam(b0) / 2 + 0.01), diam(b0) = (0.2 + 2 · 0.01 · 100) / 100
  EXPECT_TRUE(x->gate(50).contains(35.0) && x->gate(50).diam() < 2.5) << x->gate(50);
}

TEST(CtcBiasedIncrement, EmptyNamesTheContractorAndTheBias) {
  const auto td = TDomain::create(0.0, 10.0, 1.0);
  auto x = std::make_shared<Tube>(td);
  auto inc = std::make_shared<Tube>(td, Interval(1.0));
  auto b = std::make_shared<Interval>(-1, 1);
  x->set_gate(0, Interval(0.0));
  x->set_gate(10, Interval(50.0));  // a bias of −4 would be needed
  ContractorNetwork cn;
  cn.set_name(b, "b0");
  cn.add(std::make_shared<CtcBiasedIncrement>(), {x, b, inc});
  const ContractStats s = cn.contract();
  EXPECT_TRUE(s.empty);
  EXPECT_NE(s.emptiness.find("CtcBiasedIncrement"), std::string::npos) << s.emptiness;
  EXPECT_NE(s.emptiness.find("b0"), std::string::npos) << s.emptiness;
}

TEST(CtcBiasedIncrement, BadArguments) {
  EXPECT_THROW(CtcBiasedIncrement{-1.0}, Error);
  EXPECT_THROW(CtcBiasedIncrement{INFINITY}, Error);
  Tube x(TDomain::create(0.0, 1.0, 0.5)), i(TDomain::create(0.0, 1.0, 0.25));
  Interval b(-1, 1);
  EXPECT_THROW(CtcBiasedIncrement().contract(x, b, i), DimensionError);
  ContractorNetwork cn;
  EXPECT_THROW(cn.add(std::make_shared<CtcBiasedIncrement>(), {std::make_shared<Tube>(x), std::make_shared<Tube>(x),
                                                               std::make_shared<Tube>(x)}),
               DimensionError);
}

TEST(CtcBiasedIncrement, NarrowsTheTrueIncrements) {
  // j: the true increments, first known to the bias class alone (|b| <= 1): i_k + [−1, 1] δ_k; the
  // bias learnt from the two ends ([0.4, 0.6]) narrows them to i_k − [b0] δ_k ± d δ_k = [0.3, 0.7].
  const auto td = TDomain::create(0.0, 10.0, 1.0);
  Tube x(td), inc(td, Interval(1.0)), j(td, Interval(0.0, 2.0));
  x.set_gate(0, Interval(0.0));
  x.set_gate(10, Interval(5.0));
  Interval b(-1, 1);
  ASSERT_TRUE(CtcBiasedIncrement(0.1).contract(x, b, inc, j));
  for (std::size_t k = 0; k < 10; ++k) EXPECT_TRUE(near(j.slice(k), Interval(0.3, 0.7), 1e-14)) << j.slice(k);
  // In a network: the same, and an empty bias empties j too.
  auto xn = std::make_shared<Tube>(td), jn = std::make_shared<Tube>(td, Interval(0.0, 2.0));
  xn->set_gate(0, Interval(0.0));
  xn->set_gate(10, Interval(5.0));
  auto bn = std::make_shared<Interval>(-1, 1);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcBiasedIncrement>(0.1), {xn, bn, std::make_shared<Tube>(inc), jn});
  ASSERT_FALSE(cn.contract().empty);
  EXPECT_TRUE(near(jn->slice(3), Interval(0.3, 0.7), 1e-14)) << jn->slice(3);
  Tube y(td), k2(td);
  y.set_gate(0, Interval(0.0));
  y.set_gate(10, Interval(50.0));
  Interval c(-1, 1);
  EXPECT_FALSE(CtcBiasedIncrement().contract(y, c, inc, k2));
  EXPECT_TRUE(c.is_empty() && y.is_empty() && k2.is_empty());
}

TEST(CtcBiasedIncrement, FourArgumentLaws) {
  kit::Options o;
  o.outputs = {0, 1, 3};
  EXPECT_TRUE(kit::check_laws(
      [](kit::Domains& d) {
        CtcBiasedIncrement(0.1).contract(std::get<Tube>(d[0]), std::get<Interval>(d[1]), std::get<Tube>(d[2]),
                                         std::get<Tube>(d[3]));
      },
      [](std::mt19937_64& rng) {
        kit::Case c = biased_case(rng);
        const Tube& inc = std::get<Tube>(c.domains[2]);
        // j around the true increments: the measured ones minus the bias class [−3, 3] per unit time
        Tube j(inc.tdomain());
        {
          const Tube::Writer w = j.write();
          for (std::size_t k = 0; k < inc.nb_slices(); ++k) {
            w.slices()[k] = inc.slice(k) + Interval(-3, 3) * inc.tdomain()->slice_width(k);
          }
        }
        c.domains.push_back(j);
        c.truth.push_back(std::monostate{});
        return c;
      },
      o));
}
