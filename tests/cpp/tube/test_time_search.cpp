// The search of a time among the time points of a domain, started from its
// place on a uniform grid (time_search.h): the same indices as
// std::upper_bound and std::lower_bound on uniform, sampled, clustered and
// tiny grids, for times at, between, before and after the points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "sillage/tube/time_search.h"

namespace {

void check(const std::vector<double>& ts, double t) {
  const auto up = static_cast<std::size_t>(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin());
  const auto low = static_cast<std::size_t>(std::lower_bound(ts.begin(), ts.end(), t) - ts.begin());
  ASSERT_EQ(sillage::detail::first_time_after(ts, t), up) << "t = " << t << " among " << ts.size() << " points";
  ASSERT_EQ(sillage::detail::first_time_from(ts, t), low) << "t = " << t << " among " << ts.size() << " points";
}

// Every point, its neighbours, the midpoints, and times outside.
void check_all(const std::vector<double>& ts) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (const double t : {-inf, inf, ts.front() - 1, ts.back() + 1, std::nan("")}) check(ts, t);
  for (std::size_t k = 0; k < ts.size(); ++k) {
    check(ts, ts[k]);
    check(ts, std::nextafter(ts[k], -inf));
    check(ts, std::nextafter(ts[k], inf));
    if (k + 1 < ts.size()) check(ts, ts[k] + (ts[k + 1] - ts[k]) / 2);
  }
}

}  // namespace

TEST(TimeSearch, AsTheStandardSearchesOnUniformGrids) {
  for (const std::size_t n : {1u, 2u, 3u, 10u, 1001u}) {
    std::vector<double> ts(n);
    for (std::size_t k = 0; k < n; ++k) ts[k] = 0.1 * static_cast<double>(k);  // rounded: not exactly uniform
    check_all(ts);
  }
}

TEST(TimeSearch, AsTheStandardSearchesOnIrregularGrids) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t n = 2 + rng() % 500;
    std::vector<double> ts(n);
    double t = std::uniform_real_distribution<double>(-100, 100)(rng);
    for (std::size_t k = 0; k < n; ++k) {
      // Clusters: most steps tiny, a few huge, so that the uniform guess is far off.
      t += rng() % 10 == 0 ? std::uniform_real_distribution<double>(1, 1000)(rng)
                           : std::uniform_real_distribution<double>(1e-9, 1e-3)(rng);
      ts[k] = t;
    }
    check_all(ts);
  }
  // A grid with a point inserted at each end of a uniform one (TDomain::sample).
  std::vector<double> ts;
  for (int k = 0; k <= 100; ++k) ts.push_back(k);
  ts.insert(ts.begin() + 1, 1e-12);
  ts.insert(ts.end() - 1, 100 - 1e-12);
  check_all(ts);
}
