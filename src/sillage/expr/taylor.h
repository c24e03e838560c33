#pragma once
// TaylorOde: Taylor coefficients of the solutions of x' = s·f(x, u) by
// automatic differentiation on the expression DAG (Moore's recursive rules:
// order k of every node from the orders < k of its operands, never a
// symbolic derivative), in interval arithmetic.
//
// f is a Function of (x_1..x_n, u_1..u_m) with n outputs; u is held constant
// (the caller bounds what a varying input changes, dynamics/ivp_step.h);
// s = ±1 runs time forward or backward. With the variational equation
// V' = s·J_x(x)·V, V(0) = I (J_x = ∂f/∂x as a DAG of the same tape), the
// coefficients V_k are the derivatives of the x_k with respect to x(0).
//
// Over a box X of initial states every result encloses the coefficients of
// every solution starting in X. Operations outside their domain of
// smoothness (sqrt or log of a non-positive, division by an interval
// containing 0, abs of an interval containing 0, ...) make the call return
// false: there is nothing to enclose rigorously.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sillage/expr/function.h"
#include "sillage/expr/tape.h"
#include "sillage/interval/interval.h"

namespace sillage::detail {

// No earlier node shares the series (pair_twins).
inline constexpr std::uint32_t kNoTwin = 0xffffffffu;
// For each node of the tape, the earlier sin/cos (sinh/cosh) node of the
// same operand whose companion series it is, or kNoTwin: sin x and cos x
// (f and its Jacobian) then cost one pair recurrence, not two.
std::vector<std::uint32_t> pair_twins(const detail::Tape& tape);
// scaled[s]: node s is the operand a of a rule w' = a'·b (exp, sin, cos,
// sinh, cosh, tan, tanh; twins excluded), whose series j·a_j is then kept
// once instead of being recomputed at every order.
std::vector<std::uint8_t> scaled_operands(const detail::Tape& tape, const std::vector<std::uint32_t>& twin);

class TaylorOde {
 public:
  // n = f.image_dim() states, m = f.nb_vars() - n inputs. DimensionError if
  // f has fewer variables than outputs; Error naming the operation if f
  // uses one with no Taylor rule (every operation of expr.h has one today;
  // abs, sign, min and max only where their operands stay off the kink,
  // atan2 off its cut, pow of a positive, root of a non-zero: elsewhere
  // coefficients() returns false).
  explicit TaylorOde(const Function& f);

  std::size_t nb_states() const { return n_; }
  std::size_t nb_inputs() const { return m_; }
  const Function& function() const { return f_; }

  // x[k*n + i] (k = 0..order) := coefficient k of x_i, from x[0..n) (the
  // initial box) and u (m intervals). False if f is not smooth there.
  bool coefficients(std::vector<Interval>& x, const Interval* u, int order, double sign) const;
  // The same, and v[k*n*n + i*n + j] := ∂x_k,i / ∂x_0,j (k = 0..order).
  bool coefficients(std::vector<Interval>& x, std::vector<Interval>& v, const Interval* u, int order,
                    double sign) const;

 private:
  bool run(const detail::Tape& tape, const std::vector<std::uint32_t>& twin,
           const std::vector<std::uint8_t>& scaled, std::vector<Interval>& x, std::vector<Interval>* v, const Interval* u,
           int order, double sign) const;

  Function f_;
  std::size_t n_ = 0, m_ = 0;
  detail::Tape tape_;      // the n outputs of f
  detail::Tape var_tape_;  // f, then J_x row-major (n*n outputs)
  std::vector<std::uint32_t> twins_, var_twins_;  // pair_twins of each tape
  std::vector<std::uint8_t> scaled_, var_scaled_;  // scaled_operands of each tape
};

}  // namespace sillage::detail
