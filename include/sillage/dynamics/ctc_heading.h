#pragma once
// CtcHeading: the displacement of a planar vehicle over each slice from the
// distance travelled and the heading,
//   p(t_{k+1}) − p(t_k) = ∫ s(τ) (cos φ(τ), sin φ(τ)) dτ,  d_k = ∫ s(τ) dτ,
//   s ≥ 0,  φ(τ) − ψ(τ) ∈ [−track, track],  ψ' ∈ [w],
// with p the position (2 components), ψ the heading, d the distance per slice
// (the slices of a tube: odometry) and track the angle between the direction
// of travel and the heading (side slip). Both ways, slice by slice:
//   forward (positions):  [p](t_{k+1}) ∩= [p](t_k) + I_k, [p](t_k) ∩= [p](t_{k+1}) − I_k,
//     I_k = [d](k) (cos, sin)([ψ](k) + [−track, track]) (s ≥ 0: the integral
//     lies in d times the hull of the directions);
//   backward (heading): with Δ = [p](t_{k+1}) − [p](t_k) not holding 0 and
//     A = δ_k mag([w](k)) (the spread of ψ over the closed slice) such that
//     A + 2 track < π, the direction of Δ lies in the directions taken
//     (an arc narrower than π), so every ψ(τ) on the slice, its two gates
//     included, lies in atan2(Δ) + [−A − track, A + track] (mod 2π).
// Outward rounded throughout (Interval operations). One call sweeps the
// positions forward and backward and then the heading, repeated while the
// heading shrinks by more than 1 % (at most 5 times). In a network, after
// its first run, the node contracts from where its tubes changed
// (contract_local).
//
// Empty: a gate or a slice becomes empty, or d is empty; every domain
// contracted is then set empty and contract returns false.
// In a ContractorNetwork: cn.add(ctc, {p, psi, d, w}) with p a 2-d tube
// vector (or two tubes), psi, d and w tubes, all on one TDomain.
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/network_ctc.h"
#include "sillage/cn/tube_changes.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

class CtcHeading : public NetworkCtc {
 public:
  // track >= 0 (rad), else Error.
  explicit CtcHeading(double track = 0.0);
  // The bound on the angle between the direction of travel and the heading.
  double track() const { return track_; }
  std::string name() const override { return "CtcHeading"; }
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override;

  // Contracts p (2 components) and psi; d and w are read only. DimensionError
  // if p has not 2 components or the tubes are not on one TDomain.
  bool contract(TubeVector& p, Tube& psi, const Tube& d, const Tube& w) const;
  // The same on component tubes (the network's form).
  bool contract(Tube& px, Tube& py, Tube& psi, const Tube& d, const Tube& w) const;
  // The same after a change in slices first..last of the five tubes (and
  // their gates first..last+1) when they were a fixed point of contract()
  // before: each pass starts where the steps changed, sweeps the positions
  // while their gates move and bounds the heading next to the gates that
  // moved, with contract()'s result bit for bit (the network's node uses it
  // after its first run). The changes receive what shrank. Error if
  // first > last or last >= N.
  bool contract_local(Tube& px, Tube& py, Tube& psi, const Tube& d, const Tube& w, std::size_t first,
                      std::size_t last, const TubeChanges& px_changes = {}, const TubeChanges& py_changes = {},
                      const TubeChanges& psi_changes = {}) const;

 private:
  double track_;
};

}  // namespace sillage
