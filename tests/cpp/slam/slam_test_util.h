#pragma once
// True trajectories with a known loop for the slam/ tests: g(t) = f(t) + f(2m - t)
// (f a kit::SineSum) is symmetric about m, so g(m - d) = g(m + d) exactly for
// every d; g' = f'(t) - f'(2m - t). Enclosures in interval arithmetic.
#include <random>

#include "sillage/testing/contractor_kit.h"

namespace sillage::slam_test {

struct LoopedSine {
  kit::SineSum f;
  double m;
  LoopedSine(std::mt19937_64& rng, double mid) : f(rng), m(mid) {}
  Interval x(const Interval& t) const { return f.x(t) + f.x(Interval(2.0) * Interval(m) - t); }
  Interval v(const Interval& t) const { return f.v(t) - f.v(Interval(2.0) * Interval(m) - t); }
  kit::Trajectory1 position() const {
    return [g = *this](const Interval& t) { return g.x(t); };
  }
  kit::Trajectory1 velocity() const {
    return [g = *this](const Interval& t) { return g.v(t); };
  }
};

}  // namespace sillage::slam_test
