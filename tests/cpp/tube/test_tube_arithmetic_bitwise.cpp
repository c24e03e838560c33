// Tube +, −, × (rounding kernels inlined, batch_kernels.h) give the interval
// operations slice by slice and gate by gate, bit for bit, on both rounding
// paths, for tubes crossing zero, touching it and unbounded.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sillage/interval/rounding_policies.h"
#include "sillage/tube/tube_arithmetic.h"

#include "kit/same_bits.h"

using namespace sillage;

namespace {

using test::same_bits;

Tube random_tube(const std::shared_ptr<TDomain>& td, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> c(-2, 2), w(0, 1);
  std::vector<Interval> s(td->nb_slices());
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double a = c(rng);
    switch (k % 7) {
      case 0: s[k] = Interval(0.0, w(rng)); break;
      case 1: s[k] = Interval(a); break;
      case 2: s[k] = Interval(a, rounding::kInf); break;
      case 3: s[k] = Interval(-std::fabs(a), std::fabs(a)); break;
      default: s[k] = Interval(a, a + w(rng));
    }
  }
  return Tube(td, s);
}

template <class TubeOp, class IntervalOp>
void expect_slicewise(const Tube& a, const Tube& b, TubeOp top, IntervalOp iop) {
  const Tube z = top(a, b);
  for (std::size_t k = 0; k < a.nb_slices(); ++k)
    ASSERT_TRUE(same_bits(z.slice(k), iop(a.slice(k), b.slice(k)))) << "slice " << k;
  for (std::size_t k = 0; k <= a.nb_slices(); ++k)
    ASSERT_TRUE(same_bits(z.gate(k), iop(a.gate(k), b.gate(k)))) << "gate " << k;
}

}  // namespace

TEST(TubeArithmeticBitwise, AddSubMul) {
  const auto td = TDomain::create(0.0, 5.0, 0.01);
  std::mt19937_64 rng(11);
  const Tube a = random_tube(td, rng), b = random_tube(td, rng);
  const bool was = detail::hardware_rounding();
  for (const bool hard : {true, false}) {
    if (hard && !detail::hardware_rounding_available()) continue;
    detail::set_hardware_rounding(hard);
    expect_slicewise(a, b, [](const Tube& x, const Tube& y) { return x + y; },
                     [](const Interval& x, const Interval& y) { return x + y; });
    expect_slicewise(a, b, [](const Tube& x, const Tube& y) { return x - y; },
                     [](const Interval& x, const Interval& y) { return x - y; });
    expect_slicewise(a, b, [](const Tube& x, const Tube& y) { return x * y; },
                     [](const Interval& x, const Interval& y) { return x * y; });
    expect_slicewise(a, a, [](const Tube& x, const Tube& y) { return x - y; },
                     [](const Interval& x, const Interval& y) { return x - y; });
  }
  detail::set_hardware_rounding(was);
}
