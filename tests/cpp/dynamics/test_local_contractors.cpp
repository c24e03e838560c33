// The local contractions of CtcIncrement, CtcSecondDeriv and CtcHeading
// (what their network nodes run after the first run) against contract(): on
// tubes that were a fixed point of contract() before a change in slices
// first..last, they give the same tubes bit for bit and report every atom
// that shrank; a change that makes the tubes inconsistent is found by both.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <set>
#include <vector>

#include "sillage/dynamics/ctc_heading.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/dynamics/ctc_second_deriv.h"
#include "sillage/error.h"
#include "sillage/testing/contractor_kit.h"
#include "turning_vehicle.h"

using namespace sillage;

namespace {

::testing::AssertionResult same(const Tube& a, const Tube& b) {
  if (a.nb_slices() != b.nb_slices()) return ::testing::AssertionFailure() << "slices differ";
  for (std::size_t k = 0; k <= a.nb_slices(); ++k) {
    if (!kit::same_bits(a.gate(k), b.gate(k))) {
      return ::testing::AssertionFailure() << "gate " << k << ": " << a.gate(k) << " vs " << b.gate(k);
    }
    if (k < a.nb_slices() && !kit::same_bits(a.slice(k), b.slice(k))) {
      return ::testing::AssertionFailure() << "slice " << k << ": " << a.slice(k) << " vs " << b.slice(k);
    }
  }
  return ::testing::AssertionSuccess();
}

// Every atom of `after` that differs from `before` is in `reported` (ratio 0).
::testing::AssertionResult reported_all(const Tube& before, const Tube& after, const std::vector<std::size_t>& reported) {
  const std::set<std::size_t> r(reported.begin(), reported.end());
  for (std::size_t k = 0; k <= after.nb_slices(); ++k) {
    if (after.gate(k) != before.gate(k) && !r.count(2 * k)) return ::testing::AssertionFailure() << "gate " << k;
    if (k < after.nb_slices() && after.slice(k) != before.slice(k) && !r.count(2 * k + 1)) {
      return ::testing::AssertionFailure() << "slice " << k;
    }
  }
  return ::testing::AssertionSuccess();
}

// An interval narrowed around its middle (a measurement), or a point of it.
Interval narrowed(const Interval& x, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.05, 0.6);
  if (x.is_unbounded()) return Interval(-1, 1);
  return x.mid() + Interval(-1, 1) * Interval(x.rad() * u(rng));
}

// contract_local on slices a..b against contract() on a copy: the same
// result and tube, and every atom that shrank reported.
template <class Ctc>
void expect_local_is_whole(const Ctc& ctc, Tube& x, const Tube& v, std::size_t a, std::size_t b) {
  Tube whole = x;
  const bool ok = ctc.contract(whole, v);
  const Tube before = x;
  std::vector<std::size_t> changed;
  ASSERT_EQ(ctc.contract_local(x, v, a, b, TubeChanges(changed, 0, 0.0)), ok);
  ASSERT_TRUE(same(x, whole));
  if (ok) {
    ASSERT_TRUE(reported_all(before, x, changed));
  }
}

}  // namespace

TEST(CtcIncrementLocal, SameTubeAsTheWholeContractionAfterALocalChange) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::size_t n = 300;
  const CtcIncrement ctc;
  for (int trial = 0; trial < 80; ++trial) {
    auto td = TDomain::create(0.0, 30.0, 0.1);
    Tube x(td), inc(td);
    for (std::size_t k = 0; k < n; ++k) inc.set(Interval(0.1) + Interval(-1, 1) * Interval(0.02 + 0.05 * (u(rng) + 1)), k);
    x.set_gate(0, Interval(-0.1, 0.1));
    for (std::size_t k = 11; k <= n; k += 37) x.set_gate(k, Interval(0.1 * k - 2 + u(rng), 0.1 * k + 2 + u(rng)));
    ASSERT_TRUE(ctc.contract(x, inc));
    Tube again = x;
    ASSERT_TRUE(ctc.contract(again, inc));
    ASSERT_TRUE(same(again, x));  // a fixed point
    std::uniform_int_distribution<std::size_t> pick(0, n - 1);
    const std::size_t a = pick(rng), b = std::min(n - 1, a + pick(rng) % 6);
    if (trial % 3 == 0) {
      for (std::size_t k = a; k <= b; ++k) inc.set(narrowed(inc.slice(k), rng), k);
    } else {
      const std::size_t j = trial % 3 == 1 ? a : b + 1;  // a gate at either end of the change
      x.set_gate(j, narrowed(x.gate(j), rng));
    }
    ASSERT_NO_FATAL_FAILURE(expect_local_is_whole(ctc, x, inc, a, b)) << "trial " << trial;
  }
  Tube x(TDomain::create(0.0, 1.0, 0.1)), i(x.tdomain());
  EXPECT_THROW(ctc.contract_local(x, i, 3, 2, {}), Error);
  EXPECT_THROW(ctc.contract_local(x, i, 0, 10, {}), Error);
}

TEST(CtcSecondDerivLocal, SameTubeAsTheWholeContractionAfterALocalChange) {
  std::mt19937_64 rng(12);
  const std::size_t n = 200;
  const CtcSecondDeriv ctc;
  const kit::SineSum f(rng);
  for (int trial = 0; trial < 60; ++trial) {
    auto td = kit::random_tdomain(rng, static_cast<int>(n));
    Tube x = kit::tube_around(td, kit::position(f), rng, 1.0, 0.2);
    Tube acc(td, Interval(-3, 3));
    acc.set(Interval(), 7);  // unbounded: nothing learned there
    ASSERT_TRUE(ctc.contract(x, acc));
    std::uniform_int_distribution<std::size_t> pick(0, n - 1);
    const std::size_t a = pick(rng), b = std::min(n - 1, a + pick(rng) % 4);
    for (std::size_t k = a; k <= b; ++k) {
      if (trial % 2) acc.set(narrowed(acc.slice(k), rng), k);
      else x.set_gate(k + 1, narrowed(x.gate(k + 1), rng));
    }
    if (trial % 7 == 0) x.set_gate(a, Interval(1e3));  // far off: inconsistent with its slices' bow
    ASSERT_NO_FATAL_FAILURE(expect_local_is_whole(ctc, x, acc, a, b)) << "trial " << trial;
  }
}

namespace {

constexpr double kTrack = 0.05;

struct HeadingTubes {
  Tube px, py, psi, d, w;
};

// A vehicle turning at a constant rate on n slices: positions known every
// few slices, the heading loosely, distances and turn rate as odometry.
HeadingTubes heading_tubes(std::mt19937_64& rng, std::size_t n) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const test::Turning f{3 * u(rng), 0.3 + 0.2 * u(rng), 1.5 + u(rng), kTrack * u(rng), 5 * u(rng), 5 * u(rng)};
  auto td = TDomain::create(0.0, 0.5 * static_cast<double>(n), 0.5);  // steps of about 0.75 m
  HeadingTubes h{Tube(td), Tube(td), kit::tube_around(td, [f](const Interval& t) { return f.psi(t); }, rng, 1.0),
                 Tube(td), Tube(td, kit::around(Interval(f.b), rng, 0.02))};
  for (std::size_t k = 0; k < n; ++k) h.d.set(kit::around(Interval(f.s) * td->slice_width(k), rng, 0.01), k);
  for (std::size_t k = 0; k <= n; k += 1 + k % 2) {
    h.px.set_gate(k, kit::around(f.x(Interval(td->t(k))), rng, 0.05));
    h.py.set_gate(k, kit::around(f.y(Interval(td->t(k))), rng, 0.05));
  }
  return h;
}

bool whole(const CtcHeading& ctc, HeadingTubes& h) { return ctc.contract(h.px, h.py, h.psi, h.d, h.w); }

}  // namespace

TEST(CtcHeadingLocal, SameTubesAsTheWholeContractionAfterALocalChange) {
  std::mt19937_64 rng(13);
  const std::size_t n = 240;
  const CtcHeading ctc(kTrack);
  int reached_heading = 0;
  for (int trial = 0; trial < 60; ++trial) {
    HeadingTubes h = heading_tubes(rng, n);
    // A fixed point of contract(): its passes stop at 1 %, so run it until nothing moves.
    for (int i = 0; i < 200; ++i) {
      const HeadingTubes before = h;
      ASSERT_TRUE(whole(ctc, h));
      if (same(before.px, h.px) && same(before.py, h.py) && same(before.psi, h.psi)) break;
    }
    std::uniform_int_distribution<std::size_t> pick(0, n - 1);
    const std::size_t a = pick(rng), b = std::min(n - 1, a + pick(rng) % 5);
    switch (trial % 4) {
      case 0:  // a position fix
        h.px.set_gate(a + 1, narrowed(h.px.gate(a + 1), rng));
        h.py.set_gate(a + 1, narrowed(h.py.gate(a + 1), rng));
        break;
      case 1:  // the heading narrowed
        for (std::size_t k = a; k <= b; ++k) h.psi.set(narrowed(h.psi.slice(k), rng), k);
        break;
      case 2:  // the odometry narrowed
        for (std::size_t k = a; k <= b; ++k) h.d.set(narrowed(h.d.slice(k), rng), k);
        break;
      default:  // the turn rate narrowed
        for (std::size_t k = a; k <= b; ++k) h.w.set(narrowed(h.w.slice(k), rng), k);
    }
    HeadingTubes w = h;
    const bool ok = whole(ctc, w);
    const HeadingTubes before = h;
    std::vector<std::size_t> cx, cy, cpsi;
    ASSERT_EQ(ctc.contract_local(h.px, h.py, h.psi, h.d, h.w, a, b, TubeChanges(cx, 0, 0.0), TubeChanges(cy, 0, 0.0),
                                 TubeChanges(cpsi, 0, 0.0)),
              ok)
        << "trial " << trial;
    ASSERT_TRUE(same(h.px, w.px)) << "trial " << trial;
    ASSERT_TRUE(same(h.py, w.py)) << "trial " << trial;
    ASSERT_TRUE(same(h.psi, w.psi)) << "trial " << trial;
    if (!ok) continue;
    ASSERT_TRUE(reported_all(before.px, h.px, cx)) << "trial " << trial;
    ASSERT_TRUE(reported_all(before.py, h.py, cy)) << "trial " << trial;
    ASSERT_TRUE(reported_all(before.psi, h.psi, cpsi)) << "trial " << trial;
    reached_heading += !same(before.psi, h.psi);
  }
  EXPECT_GT(reached_heading, 5);  // the cases reach the heading, not only the positions
}

TEST(CtcHeadingLocal, InconsistentChangeIsFoundAsByTheWholeContraction) {
  std::mt19937_64 rng(14);
  const std::size_t n = 120;
  const CtcHeading ctc(kTrack);
  HeadingTubes h = heading_tubes(rng, n);
  ASSERT_TRUE(whole(ctc, h));
  h.px.set_gate(60, h.px.gate(60).ub() + Interval(50.0));  // 50 m off: no path reaches it
  HeadingTubes w = h;
  EXPECT_FALSE(whole(ctc, w));
  EXPECT_FALSE(ctc.contract_local(h.px, h.py, h.psi, h.d, h.w, 59, 59));
  EXPECT_TRUE(h.px.is_empty() && h.py.is_empty() && h.psi.is_empty());
  EXPECT_THROW(ctc.contract_local(h.px, h.py, h.psi, h.d, h.w, 5, n), Error);
}
