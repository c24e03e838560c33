// CtcEval then CtcDeriv over the whole tube, on an unknown tube (partly
// infinite slices and gates) observed along a true trajectory x(t) = sin t:
// neither may declare the tube empty or remove the truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "dynamics/deriv_test_util.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"

using namespace sillage;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Hull of f over [a, b] by dense sampling, widened by m (f' bounded by 1).
template <class F>
Interval hull_of(F f, double a, double b, double m) {
  double lo = kInf, hi = -kInf;
  const int n = 400;
  for (int i = 0; i <= n; ++i) {
    const double v = f(a + (b - a) * i / n);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return Interval(lo - m, hi + m);
}

void expect_contains_sin(const Tube& y, const char* where) {
  const auto& td = y.tdomain();
  for (std::size_t k = 0; k <= td->nb_slices(); ++k)
    EXPECT_TRUE(y.gate(k).contains(std::sin(td->t(k)))) << where << " gate " << k << " " << y.gate(k);
  for (std::size_t k = 0; k < td->nb_slices(); ++k)
    for (int i = 0; i <= 20; ++i) {
      const double t = td->t(k) + (td->t(k + 1) - td->t(k)) * i / 20;
      EXPECT_TRUE(y.slice(k).contains(std::sin(t))) << where << " slice " << k << " " << y.slice(k);
    }
}

}  // namespace

void run_case(double dt, int y_case, int w_case, double vm, bool sampling) {
  auto td = TDomain::create(0.0, 10.0, dt);
  const std::size_t N = td->nb_slices();
  Tube y(td, Interval(-kInf, kInf));
  Tube w(td, Interval(-kInf, kInf));
  auto yinit = [&](std::size_t k) {
    switch (y_case) {
      case 0: return Interval(-kInf, kInf);
      case 1: return k < N / 2 ? Interval(-kInf, 3.0) : Interval(-2.0, kInf);
      default: return k % 3 == 0 ? Interval(-kInf, 1.5) : (k % 3 == 1 ? Interval(-1.5, kInf) : Interval(-kInf, kInf));
    }
  };
  auto winf = [&](std::size_t k) { return w_case == 1 && (k % 5 == 2); };
  for (std::size_t k = 0; k < N; ++k) {
    w.set(winf(k) ? Interval(-kInf, kInf) : (w_case == 2 && k % 4 == 1 ? Interval(-1.0 - vm, kInf) : hull_of([](double t) { return std::cos(t); }, td->t(k), td->t(k + 1), vm)), k);
    y.set(yinit(k), k);
  }
  for (std::size_t k = 0; k <= N; ++k) {
    w.set_gate(k, Interval(std::cos(td->t(k))) + Interval(-vm, vm));
    y.set_gate(k, yinit(k < N ? k : N - 1));
  }
  // the gates of w must be inside the adjacent slices' hull (consistent tube)
  for (std::size_t k = 0; k <= N; ++k) {
    Interval g = w.gate(k);
    if (k > 0) g = g | w.slice(k - 1);
    if (k < N) g = g | w.slice(k);
    w.set_gate(k, g);
  }
  CtcEval eval;
  eval.enable_time_sampling(sampling);
  const CtcDeriv deriv;
  const Interval times[] = {Interval(1.3, 1.7), Interval(td->t(N / 3)), Interval(6.1, 6.4),
                            Interval(7.55, 7.6), Interval(2.0, 3.05), Interval(td->t(N - 2)), Interval(0.05, 0.07), Interval(5.2345), Interval(8.0 + 1.0 / 3.0), Interval(3.7, 3.71)};
  for (const Interval& t0 : times) {
    Interval t = t0;
    Interval z = hull_of([](double s) { return std::sin(s); }, t0.lb(), t0.ub(), 1e-3);
    ASSERT_TRUE(eval.contract(t, z, y, w)) << t0;
    expect_contains_sin(y, "eval");
    ASSERT_TRUE(deriv.contract(y, w)) << t0;
    expect_contains_sin(y, "deriv");
  }
}

TEST(CtcEvalThenDeriv, UnknownTubeKeepsTheTruth) {
  for (double dt : {0.5, 0.1, 0.3, 0.07})
    for (int yc = 0; yc < 3; ++yc)
      for (int wc = 0; wc < 3; ++wc)
        for (double vm : {0.05, 1e-9, 0.0})
          for (bool sampling : {false, true}) {
          SCOPED_TRACE(testing::Message() << "dt " << dt << " y " << yc << " w " << wc << " vm " << vm << " sampling " << sampling);
          run_case(dt, yc, wc, vm, sampling);
          if (HasFatalFailure()) return;
        }
}

// The random unknown tubes of test_ctc_eval.cpp (degenerate [w] on some
// slices, irregular times, y unknown): CtcDeriv after CtcEval must not fail.
TEST(CtcEvalThenDeriv, RandomUnknownTubesStayConsistent) {
  std::mt19937 rng(14);
  for (int trial = 0; trial < 60; ++trial) {
    auto c = test::random_unknown_eval_case(rng);
    Tube y(c.td);
    Interval t = c.t, z = c.z;
    CtcEval ctc;
    ctc.enable_time_sampling(false);
    ASSERT_TRUE(ctc.contract(t, z, y, c.w)) << trial;
    const bool ok = CtcDeriv().contract(y, c.w);
    ASSERT_TRUE(ok) << "trial " << trial << " t " << t << " z " << z;
  }
}
