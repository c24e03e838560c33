// A tube from a function of t: each slice and gate is f over its time
// element, as the batch evaluator gives it for that element alone, with the
// undefined places unknown; the same bits whether one thread or several
// compute the chunks (from 2048 elements on). sin and cos of a tube too.
#include <gtest/gtest.h>

#include <vector>

#include "sillage/expr/function.h"
#include "sillage/threads.h"
#include "sillage/tube/large_array.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_arithmetic.h"
#include "sillage/tube/tube_vector.h"

#include "kit/same_tube.h"

using namespace sillage;

namespace {

using test::expect_same_bits;
using test::same_bits;

// f over one time element, through the same batch evaluator.
Interval one_element(const Function& f, const Interval& t) {
  const Interval* xs[1] = {&t};
  Interval y;
  Interval* ys[1] = {&y};
  f.eval_batch(std::span<const Interval* const>(xs, 1), 1, std::span<Interval* const>(ys, 1));
  return detail::unknown_where_undefined(y);
}

void expect_elementwise(const Tube& x, const Function& f) {
  const TDomain& td = *x.tdomain();
  for (std::size_t k = 0; k < x.nb_slices(); ++k) {
    ASSERT_TRUE(same_bits(x.slice(k), one_element(f, Interval(td.t(k), td.t(k + 1))))) << "slice " << k;
  }
  for (std::size_t k = 0; k <= x.nb_slices(); ++k) {
    ASSERT_TRUE(same_bits(x.gate(k), one_element(f, Interval(td.t(k))))) << "gate " << k;
  }
}

}  // namespace

TEST(TubeFromFunction, EachElementIsTheFunctionOverIt) {
  const Function f({"t"}, "-9/20*cos(t/5) + sqrt(t - 3) * [-0.001, 0.001]");
  for (const std::size_t n : {1u, 255u, 256u, 2047u, 2048u, 5001u}) {
    const auto td = TDomain::create(0.0, 10.0, 10.0 / static_cast<double>(n));
    const Tube x(td, f);
    ASSERT_EQ(x.nb_slices(), td->nb_slices());
    expect_elementwise(x, f);
  }
}

TEST(TubeFromFunction, UndefinedPlacesAreUnknown) {
  const auto td = TDomain::create(0.0, 10.0, 0.001);  // 10000 slices: several threads
  const Tube x(td, "sqrt(t - 5)");
  EXPECT_TRUE(x.slice(0).is_unbounded());
  EXPECT_TRUE(x.gate(4000).is_unbounded());
  EXPECT_TRUE(x.gate(6000).is_bounded());
  EXPECT_TRUE(x.gate(6000).contains(1.0));
  for (std::size_t k = 0; k < x.nb_slices(); ++k) ASSERT_FALSE(x.slice(k).is_empty()) << k;
}

TEST(TubeFromFunction, TheSameBitsForAnyNumberOfThreads) {
  const Function f({"t"}, "sin(t)^2 + atan(t/7) - exp(-t/100)*[0.9, 1.1]");
  for (const std::size_t n : {3000u, 40000u, 140001u}) {  // the last one on large pages
    const auto td = TDomain::create(0.0, 100.0, 100.0 / static_cast<double>(n));
    const Tube several(td, f);
    const ThreadLimit one(1);
    const Tube alone(td, f);
    expect_same_bits(several, alone);
  }
}

TEST(TubeFromFunction, SinAndCosOfATubeTheSameForAnyNumberOfThreads) {
  const auto td = TDomain::create(0.0, 1000.0, 0.01);  // 10^5 slices
  const Tube x(td, "t/3 + [-0.02, 0.01]*sin(t)");
  const Tube s = sin(x), c = cos(x);
  const ThreadLimit one(1);
  expect_same_bits(s, sin(x));
  expect_same_bits(c, cos(x));
}

TEST(TubeFromFunction, VectorsOfOutputsAreWrittenEach) {
  const auto td = TDomain::create(0.0, 20.0, 0.002);
  const Function f({"t"}, "(cos(t), sin(t), t^2)");
  const TubeVector x(td, f);
  ASSERT_EQ(x.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) expect_same_bits(x[i], Tube(td, f[i]));
}

TEST(TubeFromFunction, AnUnwrittenArrayHasItsSize) {
  TubeArray v = detail::unwritten_array<Interval>(5);
  ASSERT_EQ(v.size(), 5u);
  for (Interval& y : v) y = Interval(2.0);
  v = detail::unwritten_array<Interval>(0);
  EXPECT_TRUE(v.empty());
  v = detail::unwritten_array<Interval>(detail::kLargeArrayBytes / sizeof(Interval) + 3);  // mapped
  v.back() = Interval(1.0, 2.0);
  EXPECT_EQ(v.back(), Interval(1.0, 2.0));
}
