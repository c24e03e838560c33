#pragma once
// A small synthetic SLAM for the slam/ tests: a 2-D robot on a figure eight
// p*(t) = (10 sin(t - 1/2), 5 sin(2t - 1)), t ∈ [0, 5] (one self-crossing, at
// the origin, t1 = 1/2, t2 = 1/2 + π: soon after a well-known start, then
// after a long drift), velocities known to ±0.2, the start to ±0.05, and a
// scalar field z = g(p) = sin(p1/3) + cos(p2/4) + p1/10 sensed to ±0.01
// (plus an optional constant bias). The map g is never given to the
// contractors: only the tube z(·).
#include <algorithm>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/tube_vector.h"

namespace sillage::slam_test {

struct SmallSlam {
  std::shared_ptr<TDomain> td;
  TubeVector p, w, z;
  std::vector<Trajectory> truth;

  explicit SmallSlam(double dt = 0.01, const std::string& bias = "0")
      : td(TDomain::create(0.0, 5.0, dt)),
        p(td, 2),
        w(std::vector<Tube>{Tube(td, "10*cos(t - 0.5) + [-0.2,0.2]"), Tube(td, "10*cos(2*t - 1) + [-0.2,0.2]")}),
        z(std::vector<Tube>{Tube(td, "sin(10*sin(t - 0.5)/3) + cos(5*sin(2*t - 1)/4) + sin(t - 0.5) + [-0.01,0.01] + " + bias)}),
        truth{Trajectory("10*sin(t - 0.5)", td->t0_tf()), Trajectory("5*sin(2*t - 1)", td->t0_tf())} {
    p.set_gate(0, IntervalVector{Interval(-4.85, -4.75), Interval(-4.26, -4.16)});
    CtcDeriv().contract(p, w);  // dead reckoning
  }
};

// Tubes of two SmallSlams live on two TDomains (== and is_subset ask for one):
// compare their slices and gates.
inline bool same_values(const TubeVector& a, const TubeVector& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!std::ranges::equal(a[i].slices(), b[i].slices()) || !std::ranges::equal(a[i].gates(), b[i].gates())) {
      return false;
    }
  }
  return true;
}
inline bool subset_values(const TubeVector& a, const TubeVector& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t k = 0; k < a[i].nb_slices(); ++k) {
      if (!a[i].slice(k).is_subset(b[i].slice(k)) || !a[i].gate(k).is_subset(b[i].gate(k))) return false;
    }
  }
  return true;
}

}  // namespace sillage::slam_test
