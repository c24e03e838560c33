#pragma once
// Dead reckoning (thesis 3.4) for CtcIvp, shared by examples/cpp/dead_reckoning.cpp,
// bench/bench_ivp.cpp and tests/cpp/dynamics/test_ctc_ivp_dead_reckoning.cpp.
// State (x1, x2, x3, x4, τ), inputs (n1, n2) = the noise of (3.16): the
// nominal inputs are smooth functions of τ (τ' = 1), so the Taylor series
// see them; only the noise, not differentiable, is an input tube.
#include "sillage/dynamics/ctc_ivp.h"

namespace dead_reckoning {

using namespace sillage;

// Order 10, forward only (x(0) is the only bounded gate before the run).
inline CtcIvp ivp_contractor() {
  return CtcIvp(Function({"x1", "x2", "x3", "x4", "tau", "n1", "n2"},
                         "(x4*cos(x3), x4*sin(x3), -9/20*cos(tau/5) + n1, 1/10 + sin(tau/4) + n2, 1)"),
                2, 10, TimePropag::FORWARD);
}

// The noise bound of (3.16): n(t) ∈ [-1/1000, 1/1000]².
inline Interval ivp_noise() { return Interval(-1, 1) / Interval(1000); }

// x(0) of (3.17) with τ(0) = 0.
inline IntervalVector ivp_initial_gate() {
  const Interval c = Interval(-1, 1) / Interval(100);
  return IntervalVector{Interval(-1, 1), Interval(-1, 1), Interval::half_pi() + c, c, Interval(0.0)};
}

}  // namespace dead_reckoning
