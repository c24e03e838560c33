#pragma once
// CtcIvp: the contractor of x' = f(x, u) on a tube [x](·) by validated
// integration (docs/ivp.md). From each gate whose box is bounded the flow is
// enclosed by a Taylor method of order p with Lohner's QR wrapping
// (dynamics/ivp_step.h) over the slices that follow (FORWARD) or precede
// (BACKWARD, x' = -f backward in time); every slice and gate is intersected
// with the enclosure, and the integration starts again from a gate that
// the tube knows better than the enclosure.
//
// f: a Function of (x_1..x_n, u_1..u_m) with n outputs (m inputs, possibly
// none). An input u is a tube with bounded uncertainty: over a slice, u(t)
// is any function in the slice [u](k) (a differential inclusion); the
// enclosure covers them all.
//
// Steps never cross a gate: a slice is crossed in steps of adaptive length
// (the Taylor terms of order p and p+1 at the centre below `tolerance`).
// If no enclosure can be validated (a blow-up, f not smooth there) the
// integration stops and starts again at the next bounded gate: nothing is
// contracted in between, nothing is lost.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "sillage/budget.h"
#include "sillage/cn/network_ctc.h"
#include "sillage/dynamics/time_propag.h"
#include "sillage/expr/function.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

namespace detail {
class TaylorOde;  // expr/taylor.h (internal)
struct IvpMemory;  // dynamics/ivp_memory.h (internal)
}  // namespace detail

class CtcIvp : public NetworkCtc {
 public:
  // DimensionError if f's variables are not its outputs plus nb_inputs;
  // Error if order is not in [1, 60]. Every operation has a Taylor rule;
  // the non-smooth ones (abs, sign, min, max) only where they are smooth
  // over a step: elsewhere the integration stops there (nothing lost).
  explicit CtcIvp(const Function& f, std::size_t nb_inputs = 0, int order = 20,
                  TimePropag propag = TimePropag::FWD_BWD);

  std::string name() const override { return "CtcIvp"; }
  // cn.add(ctc, {x}) or cn.add(ctc, {x, u}): tubes or tube vectors.
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override;

  // Number of states n.
  std::size_t nb_states() const;
  // Number of inputs m.
  std::size_t nb_inputs() const;
  // The Taylor order p.
  int order() const { return order_; }
  // The directions of integration.
  TimePropag time_propag() const { return propag_; }
  // The Function f.
  const Function& function() const;
  // The bound of the last Taylor terms that sets the step (default 1e-16).
  double tolerance() const { return tol_; }
  // Sets the step tolerance (positive).
  void set_tolerance(double tol);
  // The largest number of pieces a wide set is cut into (default 1: none).
  std::size_t max_pieces() const { return max_pieces_; }
  // Subdivision of wide sets (docs/ivp.md): up to m pieces carried side by
  // side (gates and slices get their hull); a piece is bisected at a gate
  // when its box has grown twice as wide since it was made, and a piece
  // that fails is retried as the two halves of its box. Error if m is 0.
  void set_max_pieces(std::size_t m);

  // Contracts x in place (the versions of what changed step); false if x is now empty
  // (then every slice and gate is empty). DimensionError on wrong sizes or
  // TDomains. `cancel` is checked at every integration step (a few
  // microseconds): once cancelled, Cancelled is thrown and x is still an
  // enclosure (contracted as far as the integration got). A network passes
  // its own token.
  bool contract(Tube& x, const CancelToken& cancel = {}) const;
  // Contracts the tube vector x in place; returns false if x is now empty.
  bool contract(TubeVector& x, const CancelToken& cancel = {}) const;
  // With the input tube u (any u(t) in it); returns false if x is now empty.
  bool contract(Tube& x, const Tube& u, const CancelToken& cancel = {}) const;
  // With the input tube vector u; returns false if x is now empty.
  bool contract(TubeVector& x, const TubeVector& u, const CancelToken& cancel = {}) const;
  // The same (u null without inputs), remembering the run in `memory`: the
  // next call re-integrates only from the first gate or slice of x or u
  // that changed since (the network node's way; internal type).
  bool contract(TubeVector& x, const TubeVector* u, detail::IvpMemory& memory, const CancelToken& cancel = {}) const;

 private:
  void check(const TubeVector& x, const TubeVector* u) const;
  bool contract_impl(TubeVector& x, const TubeVector* u, detail::IvpMemory* memory, const CancelToken& cancel) const;
  bool sweep(TubeVector& x, const TubeVector* u, double sign, detail::IvpMemory* memory,
             const CancelToken& cancel) const;
  bool sweep_pieces(TubeVector& x, const TubeVector* u, double sign, const CancelToken& cancel) const;

  std::shared_ptr<const detail::TaylorOde> ode_;
  int order_;
  TimePropag propag_;
  double tol_ = 1e-16;
  std::size_t max_pieces_ = 1;
};

}  // namespace sillage
