// The AVX2 rows of + − × ÷ x² √ (arith_rows.h) give Interval's operators bit
// for bit (signs of zero and the empty set's bounds included), on every
// rounding path: rows of adversarial pairs and of random ones mixing empty,
// unbounded, zero-straddling, degenerate, tiny (< 2^-968) and huge
// intervals, a constant on either side (constant points among them), lengths that leave a tail, results
// written over an operand.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "sillage/interval/arith_rows.h"
#include "sillage/interval/hardware_rounding.h"

#include "kit/arith_samples.h"

using namespace sillage;
using detail::RowArg;
using detail::RowOp;

namespace {

bool same_raw_bits(const Interval& x, const Interval& y) {
  return std::bit_cast<std::uint64_t>(x.lb()) == std::bit_cast<std::uint64_t>(y.lb()) &&
         std::bit_cast<std::uint64_t>(x.ub()) == std::bit_cast<std::uint64_t>(y.ub());
}

std::string bits(const Interval& x) {
  char s[80];
  std::snprintf(s, sizeof s, "[%a, %a]", x.lb(), x.ub());
  return s;
}

Interval reference(RowOp op, const Interval& x, const Interval& y) {
  switch (op) {
    case RowOp::Add: return x + y;
    case RowOp::Sub: return x - y;
    case RowOp::Mul: return x * y;
    case RowOp::Div: return x / y;
    case RowOp::Sqr: return sqr(x);
    case RowOp::Sqrt: return sqrt(x);
  }
  return {};
}

constexpr RowOp kOps[] = {RowOp::Add, RowOp::Sub, RowOp::Mul, RowOp::Div, RowOp::Sqr, RowOp::Sqrt};

// Rows a op b (a or b one constant when its size is 1), checked against the operators.
void check(RowOp op, const std::vector<Interval>& a, const std::vector<Interval>& b, int& failures) {
  const bool ca = a.size() == 1, cb = b.size() == 1;
  const std::size_t n = ca ? b.size() : a.size();
  std::vector<Interval> r(n);
  detail::arith_rows_avx2(op, r.data(), RowArg{a.data(), ca}, RowArg{b.data(), cb}, n);
  for (std::size_t i = 0; i < n; ++i) {
    const Interval& x = a[ca ? 0 : i];
    const Interval& y = b[cb ? 0 : i];
    const Interval want = reference(op, x, y);
    if (!same_raw_bits(r[i], want) && ++failures <= 20)
      ADD_FAILURE() << "op " << int(op) << " of " << bits(x) << ", " << bits(y) << ": " << bits(r[i]) << " vs "
                    << bits(want);
  }
}

// Random rows with one interval in 8 made a point (a degenerate interval).
std::vector<Interval> mixed(std::size_t n, std::uint64_t seed) {
  std::vector<Interval> v = test::random_intervals(n, seed);
  for (std::size_t i = 0; i < v.size(); i += 8)
    if (!v[i].is_empty()) v[i] = Interval(v[i].is_unbounded() ? 1.5 : v[i].lb());
  return v;
}

void check_all() {
  int failures = 0;
  const auto adv = test::adversarial_intervals();
  // Every adversarial pair: row a holds adv[i] repeated, row b all of adv.
  std::vector<Interval> a, b;
  for (const Interval& x : adv)
    for (const Interval& y : adv) {
      a.push_back(x);
      b.push_back(y);
    }
  for (RowOp op : kOps) check(op, a, b, failures);
  for (std::size_t len : {std::size_t{1}, std::size_t{3}, std::size_t{1021}, std::size_t{200'001}}) {
    const auto x = mixed(len, 7 + len), y = mixed(len, 11 + len);
    for (RowOp op : kOps) {
      check(op, x, y, failures);
      for (std::size_t k = 0; k < adv.size(); k += 37) {  // a constant operand on either side
        check(op, {adv[k]}, y, failures);
        check(op, x, {adv[k]}, failures);
      }
      // Constant points (× and ÷ by a finite nonzero constant have kernels of their own), tiny,
      // huge, negative, and the ones that keep the generic kernels (0, infinite bounds).
      for (const double c : {5.0, 0.2, 1.0 / 3, -3.0, -0.1, 0x1p-968, 1e-300, -0x1p-1074, 0x1p1000, 3e300,
                             -rounding::kMax, 0.0}) {
        check(op, {Interval(c)}, y, failures);
        check(op, x, {Interval(c)}, failures);
      }
      // Constants of one sign (× and ÷ by them share those kernels): thin, wide, tiny, huge, and
      // the ones that keep the generic kernels (a zero bound, an infinite bound, 0 inside).
      for (const Interval& c : {Interval(-9.0) / 20, Interval(1.0) / 10, Interval(0.5, 3.0), Interval(-3.0, -1e-300),
                                Interval(0x1p-1074, 0x1p-1000), Interval(1.0, rounding::kMax),
                                Interval(-rounding::kMax, -1.0), Interval(-0x1p-1074), Interval(0.0, 1.0),
                                Interval(-1.0, 0.0), Interval(-1.0, 1.0), Interval(-rounding::kInf, -1.0)}) {
        check(op, {c}, y, failures);
        check(op, x, {c}, failures);
      }
      check(op, x, {Interval(1.0, rounding::kInf)}, failures);
    }
  }
  EXPECT_EQ(failures, 0);
}

}  // namespace

TEST(ArithRows, EqualOperatorsBitForBitOnEveryPath) {
  if (!detail::avx2_rows()) GTEST_SKIP() << "no AVX2 on this CPU";
  const bool initial = detail::hardware_rounding();
  for (const bool hardware : {false, true}) {
    if (hardware && !detail::hardware_rounding_available()) continue;
    detail::set_hardware_rounding(hardware);
    SCOPED_TRACE(hardware ? "hardware rounding" : "portable rounding");
    check_all();
  }
  detail::set_hardware_rounding(initial);
}

// The result may be written over an operand, as the batch evaluator does.
TEST(ArithRows, InPlace) {
  if (!detail::avx2_rows()) GTEST_SKIP() << "no AVX2 on this CPU";
  const auto x = mixed(1001, 3), y = mixed(1001, 5);
  for (RowOp op : kOps) {
    std::vector<Interval> r = x, s = y;
    detail::arith_rows_avx2(op, r.data(), RowArg{r.data()}, RowArg{y.data()}, r.size());
    detail::arith_rows_avx2(op, s.data(), RowArg{x.data()}, RowArg{s.data()}, s.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      ASSERT_TRUE(same_raw_bits(r[i], reference(op, x[i], y[i]))) << i;
      ASSERT_TRUE(same_raw_bits(s[i], reference(op, x[i], y[i]))) << i;
    }
  }
}
