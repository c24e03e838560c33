#pragma once
// CtcHeadingWindow: the displacement of a planar vehicle over a window of
// consecutive slices [t_a, t_b] (t_b − t_a ≥ the window length, the least such
// b), against the heading at its middle gate c:
//   p(t_b) − p(t_a) = ∫ s(τ) (cos φ(τ), sin φ(τ)) dτ,  ∫ over slice j of s = d_j,
//   s ≥ 0,  φ − ψ ∈ [−track, track],
//   ψ(t_{j+1}) − ψ(t_j) ∈ [Δψ](j) (the gyro increments with their bias),
//   ψ' ∈ [w](j),  |ψ''| ≤ turn_accel (the turn inside a slice),
// with p the position (2 components), ψ the heading, d the distance per slice
// and Δψ the heading increment per slice (the slices of tubes: odometry).
// The heading relative to ψ(t_c) on slice j lies in
//   R_j = (sum of the increments from c to j) + T_j,
//   T_j = ([Δψ](j) + [−1, 1] mag([w](j)) δ_j) / 2  ∩  (0 ∪ [Δψ](j)) + [−1, 1] turn_accel δ_j² / 8
// (ψ within turn_accel δ²/8 of the chord between its gates), so (s ≥ 0)
//   p(t_b) − p(t_a) ∈ Rot(ψ(t_c)) V,  V = Σ_j [d](j) (cos, sin)(R_j + [−track, track]).
// Both ways, for every window (one starts every `stride` slices):
//   heading:   [ψ](t_c) is cut into cells (at least 0.01 rad, at most 128); a
//              cell θ whose Rot(θ) V misses Δ = [p](t_b) − [p](t_a) is removed.
//              When Δ excludes 0, ψ(t_c) also lies in dir(Δ) − dir(v) (mod 2π;
//              ψ is an unwrapped angle), dir(v) from the box V and, when all
//              the R_j ± track lie in an arc narrower than π, from that arc
//              (a positive sum of vectors in the arc points into it);
//   positions: [p](t_b) ∩= [p](t_a) + the hull of Rot(θ) V over the cells kept,
//              [p](t_a) ∩= [p](t_b) − the same.
// In a network, only the windows holding an atom that changed are run again.
// Unlike CtcHeading (one slice), a window holds the relative heading over
// many slices while the path grows to many metres: the heading comes out of
// position boxes much wider than one slice's step. The reference at the
// middle halves the gyro drift accumulated over the window.
// Outward rounded throughout (Interval operations). One pass over the windows.
//
// Empty: an input is empty or a gate becomes empty; p and psi are then set empty
// and contract returns false.
// In a ContractorNetwork: cn.add(ctc, {p, psi, d, dpsi, w}) with p a 2-d tube
// vector (or two tubes), psi, d, dpsi and w tubes, all on one TDomain.
#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/network_ctc.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

class CtcHeadingWindow : public NetworkCtc {
 public:
  // window > 0 (s), track >= 0 (rad), turn_accel > 0 (rad/s², +inf: the turn
  // rate alone bounds the turn inside a slice), stride >= 1 (slices); all
  // finite except turn_accel; Error otherwise.
  explicit CtcHeadingWindow(double window, double track = 0.0, double turn_accel = INFINITY, std::size_t stride = 1);
  // The length of the windows, in seconds.
  double window() const { return window_; }
  // The bound on the angle between the direction of travel and the heading.
  double track() const { return track_; }
  // The bound on |psi''| (rad/s^2; inf: none).
  double turn_accel() const { return turn_accel_; }
  // A window starts every `stride` slices, counted from the TDomain's first
  // slice ever (TDomain::nb_forgotten): online, the windows stay those of
  // the whole mission as the past is forgotten.
  std::size_t stride() const { return stride_; }
  std::string name() const override { return "CtcHeadingWindow"; }
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override;

  // Contracts p (2 components) and psi; d, dpsi and w are read only.
  // DimensionError if p has not 2 components or the tubes are not on one TDomain.
  bool contract(TubeVector& p, Tube& psi, const Tube& d, const Tube& dpsi, const Tube& w) const;
  // The same on component tubes (the network's form).
  bool contract(Tube& px, Tube& py, Tube& psi, const Tube& d, const Tube& dpsi, const Tube& w) const;

 private:
  double window_, track_, turn_accel_;
  std::size_t stride_;
};

}  // namespace sillage
