// Tube::eval(t, v) and Tube::inverse(y, v[, t]) run on the rounding policy
// of the process (hardware when the CPU has it, else the portable one): both
// give the same bounds bit for bit, zero signs included, on random tubes
// around a true trajectory and random times and values; so does CtcEval, and
// so do the portable path with AVX2 and without.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "sillage/dynamics/ctc_eval.h"
#include "sillage/interval/arith_rows.h"
#include "sillage/interval/hardware_rounding.h"
#include "sillage/tube/tube.h"

using namespace sillage;

namespace {

void expect_same_bits(const Interval& a, const Interval& b, int trial) {
  ASSERT_EQ(a.is_empty(), b.is_empty()) << trial;
  if (a.is_empty()) return;
  ASSERT_EQ(std::bit_cast<std::uint64_t>(a.lb()), std::bit_cast<std::uint64_t>(b.lb())) << trial;
  ASSERT_EQ(std::bit_cast<std::uint64_t>(a.ub()), std::bit_cast<std::uint64_t>(b.ub())) << trial;
}

// x(t) = sin(2t) + t/3 with x' = 2 cos(2t) + 1/3, widened at random.
struct Case {
  std::shared_ptr<TDomain> td;
  Tube x, v;
};

Case make_case(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> times{0.0};
  for (int k = 0; k < n; ++k) times.push_back(times.back() + 0.05 + 0.2 * u(rng));
  auto td = TDomain::create(times);
  Tube x(td), v(td);
  const auto f = [](double t) { return std::sin(2 * t) + t / 3; };
  for (int k = 0; k < n; ++k) {
    const auto s = static_cast<std::size_t>(k);
    const double a = times[s], b = times[s + 1];
    x.set(Interval(std::min(f(a), f(b)) - 0.6 * u(rng) - 0.5, std::max(f(a), f(b)) + 0.6 * u(rng) + 0.5), s);
    v.set(Interval(-2.0 + 1.0 / 3 - 0.1 * u(rng), 2.0 + 1.0 / 3 + 0.1 * u(rng)), s);
  }
  for (int k = 0; k <= n; ++k) {
    const double t = times[static_cast<std::size_t>(k)];
    x.set_gate(static_cast<std::size_t>(k), Interval(f(t) - 0.3 * u(rng), f(t) + 0.3 * u(rng)));
  }
  return {td, x, v};
}

// Tube::eval, Tube::inverse and CtcEval on random cases, run on path 0 and
// path 1 (`use(p)` selects path p): the same bits.
template <class Use>
void check_paths_agree(Use use) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 400; ++trial) {
    const Case c = make_case(rng, 1 + trial % 40);
    const double t0 = c.td->t0(), tf = c.td->tf();
    // A time inside, a degenerate one (a time point every third trial), an interval across slices.
    const double a = t0 + (tf - t0) * u(rng), b = std::min(tf, a + (tf - t0) * 0.3 * u(rng));
    const Interval t = trial % 3 == 0   ? Interval(c.td->times()[static_cast<std::size_t>(trial) % c.td->times().size()])
                       : trial % 3 == 1 ? Interval(a)
                                        : Interval(a, b);
    const double y0 = -1.5 + 3 * u(rng);
    const Interval y(y0, y0 + 0.5 * u(rng));
    Interval r[2][3];
    for (int path = 0; path < 2; ++path) {
      use(path);
      r[path][0] = c.x.eval(t, c.v);
      r[path][1] = c.x.inverse(y, c.v);
      r[path][2] = c.x.inverse(y, c.v, Interval(a, b));
    }
    for (int i = 0; i < 3; ++i) expect_same_bits(r[0][i], r[1][i], trial);
    // CtcEval on the same inputs, without sampling the TDomain (shared by both runs).
    Interval ts[2] = {t, t}, zs[2] = {y, y};
    Tube xs[2] = {c.x, c.x};
    bool ok[2];
    CtcEval ctc;
    ctc.enable_time_sampling(false);
    for (int path = 0; path < 2; ++path) {
      use(path);
      ok[path] = ctc.contract(ts[path], zs[path], xs[path], c.v);
    }
    ASSERT_EQ(ok[0], ok[1]) << trial;
    expect_same_bits(ts[0], ts[1], trial);
    expect_same_bits(zs[0], zs[1], trial);
    for (std::size_t k = 0; k < c.x.nb_slices(); ++k) {
      expect_same_bits(xs[0].slice(k), xs[1].slice(k), trial);
      expect_same_bits(xs[0].gate(k), xs[1].gate(k), trial);
    }
  }
}

}  // namespace

TEST(EvalDerivRounding, HardwareAndSoftwareAgree) {
  if (!detail::hardware_rounding_available()) GTEST_SKIP() << "no hardware static rounding";
  const bool saved = detail::hardware_rounding();
  check_paths_agree([](int path) { detail::set_hardware_rounding(path == 1); });
  detail::set_hardware_rounding(saved);
}

// The portable path with and without AVX2 (CtcEval's slice hulls 4 at a time).
TEST(EvalDerivRounding, Avx2AndOneAtATimeAgree) {
  if (!detail::avx2_rows_available()) GTEST_SKIP() << "no AVX2";
  const bool saved = detail::hardware_rounding();
  detail::set_hardware_rounding(false);
  check_paths_agree([](int path) { detail::set_avx2_rows(path == 1); });
  detail::set_avx2_rows(true);
  detail::set_hardware_rounding(saved);
}
