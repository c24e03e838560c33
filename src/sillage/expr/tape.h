#pragma once
// Tape: an expression DAG compiled to an array of instructions in topological
// order (operands before their users), each distinct node once. Evaluation
// walks the array once over a scratch array of intervals (one per
// instruction); the first nb_vars instructions load the variables.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sillage/expr/expr.h"
#include "sillage/interval/interval.h"

namespace sillage::detail {

struct Instr {
  Op op;
  int n = 0;               // PowInt exponent, Root order
  std::uint32_t a = 0;     // operand slots (a: variable index for Var)
  std::uint32_t b = 0;
  Interval value;          // Const
};

// The distinct nodes reachable from `roots`, operands first.
std::vector<Expr> topological_order(const std::vector<Expr>& roots);

class Tape {
 public:
  Tape() = default;
  // Throws Error if an expression uses a variable that is not in `vars`.
  Tape(const std::vector<Expr>& outputs, const std::vector<std::string>& vars);

  std::size_t size() const { return code_.size(); }
  std::size_t nb_vars() const { return nb_vars_; }
  const std::vector<Instr>& code() const { return code_; }
  const std::vector<std::uint32_t>& outputs() const { return outputs_; }

  // v[k] = value of instruction k on the box x (v has size() slots).
  void forward(const Interval* x, Interval* v) const;
  // forward, and tells whether every operation's operands lie in its domain
  // where it is continuous and differentiable (the mean-value form applies).
  bool forward_in_domain(const Interval* x, Interval* v) const;
  // Backward pass of HC4 over v filled by forward: intersects output k with
  // y[k], then projects each slot onto its operands, down to the variables.
  // False if a slot empties. Slots whose projection provably changes nothing
  // are skipped (hc4.cpp); skip_idle = false projects them all, for tests.
  bool backward(Interval* v, const Interval* y, bool skip_idle = true) const;
  // backward on `count` boxes laid out as by forward_batch, variables
  // included: slot k of box j at rows[k * count + j]. ok[j] (in: box j is to
  // be contracted) is cleared where a slot of box j empties.
  void backward_batch(Interval* rows, std::size_t count, const Interval* y, std::uint8_t* ok,
                      bool skip_idle = true) const;
  // Batch: xs[i] are columns of `count` intervals; rows (size() * count
  // intervals) receives row k = instruction k for k >= nb_vars(); out[k]
  // (if out is not null, not overlapping xs) receives output k, and then the
  // row of an instruction that is an output is written there, not in rows.
  void forward_batch(const Interval* const* xs, std::size_t count, Interval* rows, Interval* const* out) const;

 private:
  std::vector<Instr> code_;
  std::vector<std::uint32_t> outputs_;
  std::size_t nb_vars_ = 0;
};

}  // namespace sillage::detail
