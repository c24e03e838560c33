#pragma once
// Helpers of the dynamics tests: run a test under both rounding policies of
// the slice rule (software emulation, hardware static rounding when the CPU
// has it), and random trajectories with their exact derivative.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "sillage/dynamics/deriv_rounding.h"
#include "sillage/interval/elementary.h"
#include "sillage/tube/tube.h"

namespace sillage::test {

// Parameter: true = hardware rounding (skipped when not available).
class BothRoundings : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    if (GetParam() && !deriv::hardware_rounding_available()) GTEST_SKIP() << "no hardware static rounding";
    saved_ = deriv::hardware_rounding();
    deriv::set_hardware_rounding(GetParam());
  }
  void TearDown() override { deriv::set_hardware_rounding(saved_); }

 private:
  bool saved_ = false;
};

inline std::string rounding_name(const ::testing::TestParamInfo<bool>& p) { return p.param ? "Hardware" : "Software"; }

// x(t) = sum of a_i sin(w_i t + p_i), with x' = sum of a_i w_i cos(w_i t + p_i),
// evaluated in interval arithmetic: X(t) and V(t) contain the exact values
// (and, for an interval t, the exact ranges).
struct SineSum {
  std::vector<double> a, w, p;

  explicit SineSum(std::mt19937_64& rng, int terms = 3) {
    std::uniform_real_distribution<double> ua(-1.5, 1.5), uw(0.3, 3.0), up(-3.0, 3.0);
    for (int i = 0; i < terms; ++i) {
      a.push_back(ua(rng));
      w.push_back(uw(rng));
      p.push_back(up(rng));
    }
  }
  Interval x(const Interval& t) const {
    Interval r(0.0);
    for (std::size_t i = 0; i < a.size(); ++i) r += Interval(a[i]) * sin(Interval(w[i]) * t + Interval(p[i]));
    return r;
  }
  Interval v(const Interval& t) const {
    Interval r(0.0);
    for (std::size_t i = 0; i < a.size(); ++i) {
      r += Interval(a[i]) * Interval(w[i]) * cos(Interval(w[i]) * t + Interval(p[i]));
    }
    return r;
  }
};

// Random increasing time points from 0, n slices of widths in [0.05, 0.5].
inline std::shared_ptr<TDomain> random_tdomain(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> d(0.05, 0.5);
  std::vector<double> ts{0.0};
  for (int i = 0; i < n; ++i) ts.push_back(ts.back() + d(rng));
  return TDomain::create(ts);
}

}  // namespace sillage::test
