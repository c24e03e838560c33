// WindowInputs (CtcHeadingWindow's memory between runs): after any sequence
// of changes of d, Δψ, w, the times or the bounds, every window sum it gives
// is bit for bit the one a fresh WindowInputs computes from the same tubes;
// and a network node whose inputs change between contract() calls gives what
// the standalone contractor gives.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>

#include "sillage/cn/contractor_network.h"
#include "sillage/dynamics/ctc_heading_window.h"
#include "sillage/dynamics/heading_window_inputs.h"

using namespace sillage;

namespace {

bool same_bits(const Interval& a, const Interval& b) {
  return std::bit_cast<std::uint64_t>(a.lb()) == std::bit_cast<std::uint64_t>(b.lb()) &&
         std::bit_cast<std::uint64_t>(a.ub()) == std::bit_cast<std::uint64_t>(b.ub());
}

Interval around(std::mt19937_64& rng, double mid, double spread) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  return Interval(mid - spread * u(rng), mid + spread * u(rng));
}

}  // namespace

TEST(WindowInputs, RememberedSumsAreTheFreshOnes) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::size_t n = 60;
  auto td = TDomain::create(0.0, 6.0, 0.1);
  Tube d(td), dpsi(td), w(td);
  for (std::size_t j = 0; j < n; ++j) {
    d.set(around(rng, 0.1, 0.02), j);
    dpsi.set(around(rng, 0.05, 0.01), j);
    w.set(Interval(-1, 1), j);
  }
  detail::WindowInputs kept;
  double accel = 2.0, track = 0.05;
  for (int step = 0; step < 40; ++step) {
    // Change a few slices of one input (or the bounds), then compare every window.
    const int what = step % 5;
    for (int k = 0; k < 3; ++k) {
      const auto j = static_cast<std::size_t>(u(rng) * n);
      if (what == 0) d.set(around(rng, 0.1, 0.03), j);
      if (what == 1) dpsi.set(around(rng, 0.05, 0.02), j);
      if (what == 2) w.set(k == 0 ? Interval::all_reals() : Interval(-0.5, 0.5), j);
    }
    if (what == 3) accel = step % 2 ? INFINITY : 1.0 + u(rng);
    if (what == 4) track = 0.1 * u(rng);
    detail::WindowInputs fresh;
    ASSERT_EQ(kept.update(*td, d.data(), dpsi.data(), w.data(), accel, track),
              fresh.update(*td, d.data(), dpsi.data(), w.data(), accel, track));
    // Windows of 10 slices every 3 (the middle in the middle), and a few odd ones.
    for (std::size_t a = 0; a + 10 <= n; a += 3) {
      const std::size_t b = a + 10 + (step % 3 == 0 && a % 2 ? 1 : 0), c = (a + std::min(b, n)) / 2;
      const detail::WindowSum x = kept.sum(a, std::min(b, n), c), y = fresh.sum(a, std::min(b, n), c);
      ASSERT_TRUE(same_bits(x.vx, y.vx) && same_bits(x.vy, y.vy) && same_bits(x.cone, y.cone)) << step << " " << a;
    }
  }
}

// A domain that grows at its end (online estimation): the slices it had are kept, the new ones
// computed, and every window sum is still the fresh one's, bit for bit.
TEST(WindowInputs, GrowingDomainGivesTheFreshSums) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto td = TDomain::create(0.0, 2.0, 0.1);
  Tube d(td), dpsi(td), w(td);
  const auto fill = [&](std::size_t from) {
    for (std::size_t j = from; j < td->nb_slices(); ++j) {
      d.set(around(rng, 0.1, 0.02), j);
      dpsi.set(around(rng, 0.05, 0.01), j);
      w.set(Interval(-1, 1), j);
    }
  };
  fill(0);
  detail::WindowInputs kept;
  for (int step = 0; step < 30; ++step) {
    const std::size_t before = td->nb_slices();
    td->extend(td->tf() + 0.05 + 0.1 * u(rng));  // new slices, the whole line
    if (step % 2) td->extend(td->tf() + 0.1);
    fill(before);
    if (step % 3 == 0) d.set(around(rng, 0.1, 0.03), static_cast<std::size_t>(u(rng) * before));  // an old slice too
    detail::WindowInputs fresh;
    ASSERT_EQ(kept.update(*td, d.data(), dpsi.data(), w.data(), 2.0, 0.05),
              fresh.update(*td, d.data(), dpsi.data(), w.data(), 2.0, 0.05));
    const std::size_t n = td->nb_slices();
    for (std::size_t a = 0; a + 10 <= n; a += 4) {
      const detail::WindowSum x = kept.sum(a, a + 10, a + 5), y = fresh.sum(a, a + 10, a + 5);
      ASSERT_TRUE(same_bits(x.vx, y.vx) && same_bits(x.vy, y.vy) && same_bits(x.cone, y.cone)) << step << " " << a;
    }
  }
}

TEST(WindowInputs, NodeFollowsInputsChangedBetweenContracts) {
  // A straight path along x at 1 m/s; the heading known to be near 0; d changed between runs.
  auto td = TDomain::create(0.0, 10.0, 0.1);
  const std::size_t n = td->nb_slices();
  const auto make = [&](double dist) {
    auto p = std::make_shared<TubeVector>(td, 2);
    p->set_gate(0, IntervalVector{{-0.1, 0.1}, {-0.1, 0.1}});
    (*p)[0].set_gate(n, Interval(9.0, 11.0));
    (*p)[1].set_gate(n, Interval(-1.0, 1.0));
    auto psi = std::make_shared<Tube>(td, Interval(-0.3, 0.3));
    auto d = std::make_shared<Tube>(td, Interval(dist - 0.01, dist + 0.01));
    auto dpsi = std::make_shared<Tube>(td, Interval(-0.001, 0.001));
    auto w = std::make_shared<Tube>(td, Interval(-0.1, 0.1));
    return std::make_tuple(p, psi, d, dpsi, w);
  };
  const CtcHeadingWindow ctc(2.0, 0.01, 1.0, 5);
  auto [p, psi, d, dpsi, w] = make(0.1);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcHeadingWindow>(ctc), {p, psi, d, dpsi, w});
  ASSERT_FALSE(cn.contract().empty);
  // The odometry now says 0.105 m per slice on the second half: the node must use it.
  for (std::size_t j = n / 2; j < n; ++j) d->set(Interval(0.104, 0.106), j);
  ASSERT_FALSE(cn.contract().empty);
  // The standalone contractor on copies of the same inputs, run as often (the node's two runs).
  auto [p2, psi2, d2, dpsi2, w2] = make(0.1);
  ASSERT_TRUE(ctc.contract(*p2, *psi2, *d2, *dpsi2, *w2));
  for (std::size_t j = n / 2; j < n; ++j) d2->set(Interval(0.104, 0.106), j);
  ASSERT_TRUE(ctc.contract(*p2, *psi2, *d2, *dpsi2, *w2));
  EXPECT_EQ(*psi, *psi2);
  EXPECT_EQ((*p)[0], (*p2)[0]);
  EXPECT_EQ((*p)[1], (*p2)[1]);
}
