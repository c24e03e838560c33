#pragma once
// Helpers of the dynamics tests: run a test under both rounding policies of
// the slice rule (software emulation, hardware static rounding when the CPU
// has it), and random trajectories with their exact derivative (from the
// contractor test kit).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "sillage/testing/contractor_kit.h"
#include "sillage/interval/rounding_policies.h"
#include "sillage/interval/elementary.h"
#include "sillage/tube/tube.h"

namespace sillage::test {

// Parameter: true = hardware rounding (skipped when not available).
class BothRoundings : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    if (GetParam() && !detail::hardware_rounding_available()) GTEST_SKIP() << "no hardware static rounding";
    saved_ = detail::hardware_rounding();
    detail::set_hardware_rounding(GetParam());
  }
  void TearDown() override { detail::set_hardware_rounding(saved_); }

 private:
  bool saved_ = false;
};

inline std::string rounding_name(const ::testing::TestParamInfo<bool>& p) { return p.param ? "Hardware" : "Software"; }

// A true trajectory and its derivative, and random time domains: the
// contractor test kit's (sillage/testing/contractor_kit.h).
using kit::random_tdomain;
using kit::SineSum;

// A TDomain on [0, 10] with irregular steps in [0.3, 1.5].
inline std::shared_ptr<TDomain> random_tdomain(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.3, 1.5);
  std::vector<double> ts{0.0};
  while (ts.back() < 10.0 - 1.5) ts.push_back(ts.back() + u(rng));
  ts.push_back(10.0);
  return TDomain::create(ts);
}

// An observation of a tube y known nowhere, with a random derivative tube
// [w] (degenerate on some slices; a gate of [w] is the hull of its two slices,
// as a derivative may jump there), a random [t] (degenerate one time in five)
// and a random [z].
struct UnknownEvalCase {
  std::shared_ptr<TDomain> td;
  Tube w;
  Interval t, z;
};

inline UnknownEvalCase random_unknown_eval_case(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  auto td = random_tdomain(rng);
  std::vector<Interval> ws;
  for (std::size_t k = 0; k < td->nb_slices(); ++k) {
    const double a = 4 * u(rng) - 2, b = u(rng) < 0.3 ? a : a + 2 * u(rng);
    ws.emplace_back(a, b);
  }
  Tube w(td, ws);
  for (std::size_t k = 0; k <= td->nb_slices(); ++k)
    w.set_gate(k, k == 0 ? ws[0] : (k == ws.size() ? ws.back() : ws[k - 1] | ws[k]));
  const double ta = 10 * u(rng), tb = std::min(10.0, ta + (u(rng) < 0.2 ? 0.0 : 4 * u(rng)));
  const double zc = 4 * u(rng) - 2;
  return {td, w, Interval(ta, tb), Interval(zc, zc + u(rng))};
}

}  // namespace sillage::test
