// The batch evaluator and the batch HC4 give the per-box results bit for bit
// (signs of zero included), on random boxes mixing bounded, unbounded,
// degenerate, zero-touching and empty intervals, for every operation that has
// a row loop of its own and for the generic ones; with each rounding policy
// of the row kernels (batch_kernels.h: AVX-512 rounding and the portable one).
// sin and cos rows have a kernel of their own (trig_batch.h, its MPFR sweeps
// in test_mpfr_trig.cpp): there the batch is checked against the per-box
// results up to rounding, and the batch HC4 against true points.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "sillage/expr/function.h"
#include "sillage/interval/arith_rows.h"
#include "sillage/interval/rounding_policies.h"

#include "kit/close_bounds.h"
#include "kit/same_bits.h"

using namespace sillage;

namespace {

using test::same_bits;

// A random interval of one of the shapes the tubes meet.
Interval random_interval(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> c(-4, 4), w(0, 3);
  const double a = c(rng);
  switch (rng() % 10) {
    case 0: return Interval::empty();
    case 1: return Interval(a);
    case 2: return Interval(0.0, w(rng));
    case 3: return Interval(-w(rng), 0.0);
    case 4: return Interval(a, rounding::kInf);
    case 5: return Interval(-rounding::kInf, a);
    case 6: return Interval(0.0);
    default: return Interval(a, a + w(rng));
  }
}

// The batch HC4 kept every point of the boxes that provably solves f in y
// (the enclosure of f at the point lies inside y), and contracted only;
// enough boxes contracted to make the test meaningful.
void check_true_points(const Function& f, const IntervalVector& y, const std::vector<IntervalVector>& boxes,
                       const std::vector<std::vector<Interval>>& cols, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  int changed = 0, solutions = 0;
  for (std::size_t j = 0; j < boxes.size(); ++j) {
    IntervalVector got(boxes[j].size());
    for (std::size_t i = 0; i < got.size(); ++i) got[i] = cols[i][j];
    ASSERT_TRUE(got.is_subset(boxes[j])) << f << ": " << got << " not inside " << boxes[j];
    changed += got != boxes[j] ? 1 : 0;
    if (boxes[j].is_empty() || boxes[j].is_unbounded()) continue;
    for (int s = 0; s < 20; ++s) {
      IntervalVector p(got.size());
      for (std::size_t i = 0; i < p.size(); ++i) {
        const Interval& b = boxes[j][i];
        p[i] = Interval(std::clamp(b.lb() + u(rng) * b.diam(), b.lb(), b.ub()));
      }
      if (!f.eval_vector(p).is_interior_subset(y)) continue;
      ++solutions;
      ASSERT_TRUE(p.is_subset(got)) << f << ": the solution " << p << " of box " << boxes[j] << " lost, got " << got;
    }
  }
  EXPECT_GT(changed, 10) << f;
  EXPECT_GT(solutions, 100) << f;
}

// Batch and box-by-box results of f on `count` random boxes, compared bit for
// bit; with `trig`, eval up to rounding and HC4 by true points.
void check_one(const Function& f, const IntervalVector& y, std::uint64_t seed, bool trig) {
  const std::size_t n = f.nb_vars(), m = f.image_dim(), count = 1000;
  std::mt19937_64 rng(seed);
  std::vector<std::vector<Interval>> cols(n, std::vector<Interval>(count));
  for (auto& c : cols)
    for (Interval& x : c) x = random_interval(rng);
  std::vector<Interval*> xs(n);
  std::vector<const Interval*> cxs(n);
  for (std::size_t i = 0; i < n; ++i) cxs[i] = xs[i] = cols[i].data();

  std::vector<std::vector<Interval>> out(m, std::vector<Interval>(count));
  std::vector<Interval*> os(m);
  for (std::size_t i = 0; i < m; ++i) os[i] = out[i].data();
  f.eval_batch(cxs, count, os);
  std::vector<IntervalVector> boxes(count, IntervalVector(n));
  for (std::size_t j = 0; j < count; ++j)
    for (std::size_t i = 0; i < n; ++i) boxes[j][i] = cols[i][j];
  for (std::size_t j = 0; j < count; ++j) {
    const IntervalVector e = f.eval_vector(boxes[j]);
    for (std::size_t i = 0; i < m; ++i)
      ASSERT_TRUE(trig ? test::close_bounds(out[i][j], e[i], 1e-12) : same_bits(out[i][j], e[i]))
          << f << " eval, box " << boxes[j] << ": " << out[i][j] << " vs " << e[i];
  }

  f.hc4_revise_batch(xs, count, y);
  if (trig) return check_true_points(f, y, boxes, cols, rng);
  int changed = 0;
  for (std::size_t j = 0; j < count; ++j) {
    IntervalVector b = boxes[j];
    f.hc4_revise(b, y);
    changed += b != boxes[j] ? 1 : 0;
    for (std::size_t i = 0; i < n; ++i)
      ASSERT_TRUE(same_bits(cols[i][j], b[i])) << f << " hc4, box " << boxes[j] << ": " << cols[i][j] << " vs " << b[i];
  }
  EXPECT_GT(changed, 10) << f;
}

// check_one on both rounding paths (the portable one alone without AVX-512F),
// each with and without the AVX2 rows (the forward rows take them on both paths).
void check(const Function& f, const IntervalVector& y, std::uint64_t seed, bool trig = false) {
  const bool was = detail::hardware_rounding(), rows_were = detail::avx2_rows();
  for (const bool hard : {true, false}) {
    if (hard && !detail::hardware_rounding_available()) continue;
    detail::set_hardware_rounding(hard);
    for (const bool rows : {true, false}) {
      if (rows && !detail::avx2_rows_available()) continue;
      detail::set_avx2_rows(rows);
      check_one(f, y, seed, trig);
    }
  }
  detail::set_avx2_rows(rows_were);
  detail::set_hardware_rounding(was);
}

// Bounds whose exact sums, differences and products are zero, tiny or overflow.
TEST(BatchBitwise, ZerosTinyAndHuge) {
  const double t = 0x1p-1000, h = 0x1p1020;
  const std::vector<Interval> v{Interval(-1, 1), Interval(1), Interval(-1), Interval(0.0), Interval(-0.0, 0.0),
                                Interval(t, 3 * t), Interval(-3 * t, -t), Interval(h, 2 * h), Interval(-2 * h, -h),
                                Interval(0.1, 0.3), Interval(-0.3, 0.7), Interval(-rounding::kInf, 0.0),
                                Interval(0.0, rounding::kInf), Interval::empty(), Interval(t, h)};
  const Function f({"a", "b"}, "(a + b, a - b, a * b, -a - b)");
  const std::size_t count = v.size() * v.size();
  std::vector<Interval> a(count), b(count);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = 0; j < v.size(); ++j) {
      a[i * v.size() + j] = v[i];
      b[i * v.size() + j] = v[j];
    }
  const bool was = detail::hardware_rounding(), rows_were = detail::avx2_rows();
  for (const int path : {0, 1, 2, 3}) {  // hardware or not, AVX2 rows or not
    const bool hard = path < 2, rows = path % 2 == 0;
    if ((hard && !detail::hardware_rounding_available()) || (rows && !detail::avx2_rows_available())) continue;
    detail::set_hardware_rounding(hard);
    detail::set_avx2_rows(rows);
    std::vector<std::vector<Interval>> out(4, std::vector<Interval>(count));
    const std::vector<const Interval*> xs{a.data(), b.data()};
    const std::vector<Interval*> os{out[0].data(), out[1].data(), out[2].data(), out[3].data()};
    f.eval_batch(xs, count, os);
    for (std::size_t j = 0; j < count; ++j) {
      const IntervalVector e = f.eval_vector(IntervalVector{a[j], b[j]});
      for (std::size_t i = 0; i < 4; ++i)
        ASSERT_TRUE(same_bits(out[i][j], e[i])) << "hard " << hard << " rows " << rows << " output " << i << " of " << a[j] << ", " << b[j]
                                                << ": " << out[i][j] << " vs " << e[i];
    }
  }
  detail::set_avx2_rows(rows_were);
  detail::set_hardware_rounding(was);
}

}  // namespace

TEST(BatchBitwise, RowOperations) {
  const Interval band(-0.5, 0.5);
  check(Function({"v", "a", "b"}, "v - b*cos(a)"), IntervalVector{band}, 1, true);
  check(Function({"v", "a", "b"}, "v + b*sin(a)"), IntervalVector{band}, 2, true);
  check(Function({"y", "a", "b"}, "y - sqrt(sqr(a - 1) + (b + 2)^2)"), IntervalVector{Interval(0.0)}, 3);
  check(Function({"y", "a", "b"}, "a / b - y"), IntervalVector{band}, 4);
  check(Function({"y", "a", "b"}, "(y - a*b, y + 3/a)"), IntervalVector{Interval(0.0), Interval(1, 2)}, 5);
}

TEST(BatchBitwise, GenericOperations) {
  const Interval band(-1, 1);
  check(Function({"y", "a", "b"}, "y - exp(a) + log(b)"), IntervalVector{band}, 6);
  check(Function({"y", "a", "b"}, "y - atan2(a, b) - abs(a) + sign(b)"), IntervalVector{band}, 7);
  check(Function({"y", "a", "b"}, "y - a^3 + min(a, b) - max(a, -b) + tanh(b)"), IntervalVector{band}, 8);
  check(Function({"y", "a", "b"}, "(y - atan(a), -a - b)"), IntervalVector{band, Interval(0, 2)}, 9);
}

// Outputs that are a variable, a constant, or the same node twice: each
// column gets its row (an output row is written straight to its column).
TEST(BatchBitwise, OutputsSharingRows) {
  check(Function({"y", "a", "b"}, "(a, 3, a * b + y, a * b + y, y - 2 / b)"),
        IntervalVector{Interval(-1, 1), Interval(3.0), Interval(-2, 2), Interval(-2, 2), Interval(-1, 1)}, 10);
}
