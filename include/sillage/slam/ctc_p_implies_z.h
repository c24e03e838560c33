#pragma once
// CtcPImpliesZ: the inter-temporal implication contractor C_{p⇒z} of thesis
// (7.9), Alg. 13 (accurate) and Alg. 14 (fast):
//   p(t1) = p(t2) ⇒ z(t1) = z(t2),  p' = w.
// One iteration:
//  1. 𝕋_p: the loop detections of the t-plane on (p, w) with the inclusion
//     function (7.28) (TPlane::compute_detections), its components Ω_i;
//  2. the existence test 𝒯 (topological degree) on each complete Ω_i, on
//     Ω_i as detected: BEFORE the intersection with 𝕋_z, whose boundary may
//     hold zeros of f_p (the degree needs none on ∂Ω_i);
//  3. for each proven Ω_i: Ω_i ∩ 𝕋_z, with 𝕋_z the outer kernel SIVIA of
//     (7.17) [f_z]([t1], [t2]) = [z]([t1]) - [z]([t2]) run on the boxes of
//     Ω_i (z of any dimension). The true loop of Ω_i is in 𝕋_z (the
//     implication), so an empty Ω_i ∩ 𝕋_z proves p inconsistent;
//  4. C_Ω on Ω_i ∩ 𝕋_z (accurate) or on its hull [b] (fast).
// The proven components are contracted in parallel (oneTBB), each against
// the tube as it was at the start of the iteration, and their hulls are
// intersected into p afterwards: the result never depends on the thread
// count. Iterations go on until p no longer shrinks by more than `ratio` on
// any gate or slice (or max_iterations).
//
// p is 2-D (the t-plane's loop tests are planar, thesis ch. 6) or 1-D (then
// the pieces of scalar_loops.h and their sign-change test replace steps 1-2):
// DimensionError otherwise. w on p's TDomain; z's time domain must cover p's.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "sillage/budget.h"
#include "sillage/cn/tube_contractor.h"
#include "sillage/slam/slam_row.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// The inter-temporal implication contractor C_{p=>z} (thesis (7.9), Alg. 13, fast=true: Alg. 14):
// p(t1) = p(t2) => z(t1) = z(t2), p' = w. contract(p, w, z) contracts the 2-D (or 1-D) TubeVector p
// to a fixed point and returns one SlamRow per iteration; ContractorNetwork.add(CtcPImpliesZ(eps), [p, w, z])
// binds it.
class CtcPImpliesZ
    : public TubeContractor<CtcPImpliesZ, std::vector<SlamRow>(TubeVector&, const TubeVector&, const TubeVector&)> {
 public:
  // eps > 0: the width of the t-boxes (seconds; below the time step δ it
  // gains nothing, thesis footnote 5). Error otherwise.
  explicit CtcPImpliesZ(double eps, bool fast = false);

  std::string name() const override { return fast_ ? "CtcPImpliesZ(fast)" : "CtcPImpliesZ"; }
  // cn.add(CtcPImpliesZ(eps), {p, w, z}): p contracted, w and z read; p and
  // w 2-D or 1-D (3 or 4 tubes in all: 1-D, 5 or more: 2-D).
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override;
  // The same with p, w and z given as three arguments of their own
  // dimensions (what ContractorNetwork::add calls).
  std::shared_ptr<const CnNode> make_node_for(const std::vector<DomainRef>& refs,
                                              const std::vector<BoundDomain>& args) const override;

  // The width of the t-boxes.
  double eps() const { return eps_; }
  // Alg. 14 (the hull of each component) or Alg. 13.
  bool fast() const { return fast_; }
  void set_ratio(double ratio);  // in [0, 1), default 1e-3
  double ratio() const { return ratio_; }
  void set_max_iterations(std::size_t n);  // >= 1, default 50
  std::size_t max_iterations() const { return max_iterations_; }

  // Contracts p to a fixed point; returns one row per iteration (the last
  // one contracted nothing more, or p became empty: then p is empty).
  // `cancel` is checked at every box of the t-plane, of the degree tests, of
  // 𝕋_z and of C_Ω: once cancelled, Cancelled is thrown and p is left as the
  // last complete iteration made it. A network passes its own token.
  std::vector<SlamRow> contract(TubeVector& p, const TubeVector& w, const TubeVector& z,
                                const CancelToken& cancel = {}) const;
  // The same with a scalar observation Tube z.
  std::vector<SlamRow> contract(TubeVector& p, const TubeVector& w, const Tube& z,
                                const CancelToken& cancel = {}) const;
  // One iteration of C_{p⇒z} on p (2-D or 1-D); `row` (a SlamRow, filled in
  // place) receives its detections, proofs and atoms touched (iteration,
  // times and contractions are left to the caller). Returns true if p shrank
  // by more than ratio somewhere. Cancelled as contract() (p unchanged).
  bool iterate(TubeVector& p, const TubeVector& w, const TubeVector& z, SlamRow& row,
               const CancelToken& cancel = {}) const;

 private:
  double eps_;
  bool fast_;
  double ratio_ = 1e-3;
  std::size_t max_iterations_ = 50;
};

namespace detail {
// Sum over components of the widths of x (∞ if unbounded, 0 if empty).
double width_sum(const IntervalVector& x);
// 1 - width_sum(after) / width_sum(before) (0 when before has no width).
double contraction(const IntervalVector& before, const IntervalVector& after);
}  // namespace detail

}  // namespace sillage
