// CtcDeriv::contract_local against contract(): on a tube that was a fixed
// point before a change in slices first..last, the local sweeps give the same
// tube bit for bit (FORWARD or BACKWARD alone: the whole pass, one pass being
// no fixed point), and report what shrank.
#include <gtest/gtest.h>

#include <random>

#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/error.h"

using namespace sillage;

namespace {

struct Case {
  std::shared_ptr<TDomain> td;
  Tube x, v;
};

// A random tube x (gates every few slices, the rest unknown) with v = [c - e, c + e] per slice.
Case random_case(std::mt19937_64& gen, std::size_t n) {
  std::uniform_real_distribution<double> u(-1, 1);
  auto td = TDomain::create(0.0, static_cast<double>(n) * 0.1, 0.1);
  Tube x(td), v(td);
  {
    Tube::Writer w = v.write();
    for (auto& s : w.slices()) {
      const double c = u(gen), e = 0.05 + 0.5 * (u(gen) + 1);
      s = Interval(c - e, c + e);
    }
  }
  x.set_gate(0, Interval(-0.1, 0.1));
  for (std::size_t k = 7; k < n; k += 13) {
    const double c = u(gen) * 3;
    x.set_gate(k, Interval(c - 5, c + 5));
  }
  return {td, std::move(x), std::move(v)};
}

void expect_same(const Tube& a, const Tube& b) {
  ASSERT_EQ(a.nb_slices(), b.nb_slices());
  for (std::size_t k = 0; k < a.nb_slices(); ++k) {
    ASSERT_EQ(a.slice(k), b.slice(k)) << "slice " << k;
    ASSERT_EQ(a.gate(k), b.gate(k)) << "gate " << k;
  }
  ASSERT_EQ(a.gate(a.nb_slices()), b.gate(b.nb_slices()));
}

}  // namespace

TEST(CtcDerivLocal, SameTubeAsTheWholeContractionAfterALocalChange) {
  std::mt19937_64 gen(7);
  std::uniform_int_distribution<std::size_t> pick(0, 399);
  for (const TimePropag p : {TimePropag::FWD_BWD, TimePropag::FORWARD, TimePropag::BACKWARD}) {
    const CtcDeriv ctc(p);
    for (int trial = 0; trial < 60; ++trial) {
      Case c = random_case(gen, 400);
      ASSERT_TRUE(ctc.contract(c.x, c.v));  // a fixed point (of FWD_BWD; one pass otherwise)
      if (p == TimePropag::FWD_BWD) {
        Tube again = c.x;
        ASSERT_TRUE(ctc.contract(again, c.v));
        expect_same(again, c.x);
      }
      // A change: a measurement narrows a gate (or v narrows on a slice).
      std::size_t a = pick(gen), b = std::min<std::size_t>(399, a + pick(gen) % 5);
      if (trial % 3 == 0) {
        Tube::Writer w = c.v.write();
        for (std::size_t k = a; k <= b; ++k) w.slices()[k] = w.slices()[k].mid() + Interval(-0.01, 0.01);
      } else {
        const Interval g = c.x.gate(a);
        c.x.set_gate(a, Interval(g.mid() - g.rad() / 4, g.mid() + g.rad() / 4));
        a = a > 0 ? a - 1 : 0;
        b = std::max(a, std::min<std::size_t>(b, 399));
      }
      Tube whole = c.x;
      ASSERT_TRUE(ctc.contract(whole, c.v));
      std::vector<std::size_t> changed;
      ASSERT_TRUE(ctc.contract_local(c.x, c.v, a, b, TubeChanges(changed, 0, 0.0)));
      expect_same(c.x, whole);
    }
  }
}

TEST(CtcDerivLocal, ReportsWhatShrankAndFindsEmptiness) {
  auto td = TDomain::create(0.0, 10.0, 1.0);
  Tube x(td), v(td, Interval(-1, 1));
  x.set_gate(0, Interval(0));
  const CtcDeriv ctc;
  ASSERT_TRUE(ctc.contract(x, v));
  x.set_gate(5, Interval(4.5, 5));  // only [4.5, 5] at t = 5: the slices before narrow
  std::vector<std::size_t> changed;
  ASSERT_TRUE(ctc.contract_local(x, v, 4, 5, TubeChanges(changed, 100, 0.0)));
  EXPECT_EQ(x.gate(4), Interval(3.5, 4));
  EXPECT_EQ(x.gate(1), Interval(0.5, 1));
  EXPECT_NE(std::find(changed.begin(), changed.end(), 100u + 2), changed.end());  // gate 1
  x.set_gate(9, Interval(-3, -2));  // unreachable from [4.5, 5] at t = 5 with |v| <= 1
  EXPECT_FALSE(ctc.contract_local(x, v, 8, 9, TubeChanges()));
  EXPECT_TRUE(x.is_empty());
  EXPECT_THROW(ctc.contract_local(x, v, 3, 10, TubeChanges()), Error);
}
