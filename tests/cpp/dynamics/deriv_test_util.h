#pragma once
// Helpers of the dynamics tests: run a test under both rounding policies of
// the slice rule (software emulation, hardware static rounding when the CPU
// has it), and random trajectories with their exact derivative (from the
// contractor test kit).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "kit/contractor_kit.h"
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
// contractor test kit's (kit/contractor_kit.h).
using kit::random_tdomain;
using kit::SineSum;

}  // namespace sillage::test
