// The reduction of CtcIvp's zonotope generators (dynamics/ivp_generators.h):
// the reduced zonotope must contain the original one, also after any later
// linear map (the flow shears the active states into the passive ones), and
// merging along the active states must lose far less than boxing.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "sillage/dynamics/ivp_generators.h"

using namespace sillage;
using detail::reduce_generators;

namespace {

using Mat = std::vector<std::vector<double>>;

// Half-widths of the hull of L·(Σ g_j w_j + [extra]) (extra symmetric).
std::vector<double> sheared_radius(const Mat& L, const std::vector<Vector>& G, const IntervalVector& extra) {
  const std::size_t n = L.size();
  std::vector<double> r(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    for (const Vector& g : G) {
      double s = 0.0;
      for (std::size_t k = 0; k < n; ++k) s += L[i][k] * g[k];
      r[i] += std::abs(s);
    }
    for (std::size_t k = 0; k < n; ++k) r[i] += std::abs(L[i][k]) * extra[k].mag();
  }
  return r;
}

// Generators as CtcIvp makes them on dead reckoning: states (x1, x2)
// passive, (x3, x4) active; an input generator born at step j is along x3
// or x4 with passive parts that vary smoothly with j.
std::vector<Vector> born_in_time(std::size_t count) {
  std::vector<Vector> G;
  for (std::size_t j = 0; j < count; ++j) {
    const double t = 0.05 * static_cast<double>(j / 2);
    const double d = 1e-3 * (1.0 + 0.1 * std::sin(t));
    if (j % 2 == 0) {
      G.push_back({d * 10 * std::cos(t), d * 10 * std::sin(t), d, 0.0});
    } else {
      G.push_back({-d * std::sin(t), d * std::cos(t), 0.0, d});
    }
  }
  return G;
}

Mat random_shear(std::mt19937_64& rng, std::size_t n, const std::vector<bool>& passive) {
  std::uniform_real_distribution<double> d(-20.0, 20.0);
  Mat L(n, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    L[i][i] = 1.0;
    for (std::size_t k = 0; k < n; ++k) {
      if (passive[i] && !passive[k]) L[i][k] = d(rng);  // active states move the passive ones
    }
  }
  return L;
}

}  // namespace

TEST(IvpGenerators, ReducedZonotopeContainsTheVerticesAfterShears) {
  const std::vector<bool> passive{true, true, false, false};
  const std::vector<Vector> G0 = born_in_time(300);
  std::vector<Vector> G = G0;
  IntervalVector extra(4, Interval(0.0));
  reduce_generators(G, extra, passive, 64);
  EXPECT_LE(G.size(), 48u);
  // Merging along the active states leaves no active residual (rounding aside).
  EXPECT_LT(extra[2].mag(), 1e-15);
  EXPECT_LT(extra[3].mag(), 1e-15);
  // The same reduction by boxing only (no passive state declared).
  std::vector<Vector> Gb = G0;
  IntervalVector extra_b(4, Interval(0.0));
  reduce_generators(Gb, extra_b, std::vector<bool>(4, false), 64);
  double loss = 0.0, loss_boxing = 0.0;
  std::mt19937_64 rng(7);
  std::bernoulli_distribution coin(0.5);
  for (int trial = 0; trial < 50; ++trial) {
    const Mat L = random_shear(rng, 4, passive);
    const std::vector<double> r = sheared_radius(L, G, extra);
    for (int v = 0; v < 20; ++v) {  // vertices of the original zonotope
      std::vector<double> x(4, 0.0);
      for (const Vector& g : G0) {
        const double w = coin(rng) ? 1.0 : -1.0;
        for (std::size_t k = 0; k < 4; ++k) x[k] += w * g[k];
      }
      for (std::size_t i = 0; i < 4; ++i) {
        double y = 0.0;
        for (std::size_t k = 0; k < 4; ++k) y += L[i][k] * x[k];
        EXPECT_LE(std::abs(y), r[i] * (1 + 1e-12)) << trial << " " << i;
      }
    }
    // Tight: within 15 % of the original hull after the shear (300
    // generators down to 48), where boxing loses far more.
    const std::vector<double> r0 = sheared_radius(L, G0, IntervalVector(4, Interval(0.0)));
    const std::vector<double> rb = sheared_radius(L, Gb, extra_b);
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_LT(r[i], 1.15 * r0[i]) << trial << " " << i;
      loss += r[i] - r0[i];
      loss_boxing += rb[i] - r0[i];
    }
  }
  EXPECT_LT(loss, 0.25 * loss_boxing) << loss << " " << loss_boxing;
}

TEST(IvpGenerators, WithoutPassiveStatesTheCheapestAreBoxed) {
  const std::vector<bool> passive(4, false);
  std::vector<Vector> G = born_in_time(300);
  const std::vector<Vector> G0 = G;
  IntervalVector extra(4, Interval(0.0));
  reduce_generators(G, extra, passive, 64);
  EXPECT_EQ(G.size(), 48u);
  // The hull is kept (Girard: the boxed generators' magnitudes in extra).
  const Mat I{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  const std::vector<double> r = sheared_radius(I, G, extra), r0 = sheared_radius(I, G0, IntervalVector(4, Interval(0.0)));
  for (std::size_t i = 0; i < 4; ++i) EXPECT_GE(r[i], r0[i] * (1 - 1e-12)) << i;
}

TEST(IvpGenerators, FewGeneratorsAreLeftAlone) {
  std::vector<Vector> G = born_in_time(10);
  const std::vector<Vector> G0 = G;
  IntervalVector extra(4, Interval(0.0));
  reduce_generators(G, extra, {true, true, false, false}, 64);
  EXPECT_EQ(G, G0);
  EXPECT_EQ(extra[0], Interval(0.0));
}
