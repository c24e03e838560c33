#pragma once
// The mission of the outlier tests on tubes: x(t) = (cos t, sin t) on
// [0, 10], unknown in [-10, 10]^2, known through its derivative +-0.01.
#include <cmath>
#include <memory>

#include "sillage/tube/tdomain.h"
#include "sillage/tube/tube_vector.h"

namespace sillage::test {

struct CircleMission {
  std::shared_ptr<TDomain> td = TDomain::create(0.0, 10.0, 0.05);
  TubeVector x{td, IntervalVector(2, Interval(-10, 10))};
  TubeVector v{td, "(-sin(t), cos(t))"};

  CircleMission() {
    for (std::size_t j = 0; j < 2; ++j) v[j] += Interval(-0.01, 0.01);
  }
};

// True when the tube holds (cos t, sin t) at t = 0, 0.01, ..., 10.
inline bool holds_circle(const TubeVector& x) {
  for (int k = 0; k <= 1000; ++k) {
    const double t = k / 100.0;
    if (!x(t).contains({std::cos(t), std::sin(t)})) return false;
  }
  return true;
}

}  // namespace sillage::test
