#pragma once
// Function: a (vector) real function f : IR^n -> IR^m given by an expression
// (thesis 2.2.3). It is compiled once into a tape (the expression DAG sorted
// topologically, each shared sub-expression evaluated once) and offers the
// natural inclusion function, the centered (mean-value) form, batch evaluation
// over arrays of boxes, symbolic derivatives and the HC4-revise contractor
// (thesis 2.3.1). Every result encloses the exact real result.
//
// A Function is an immutable value, cheap to copy (shared, read-only tape);
// every const method is thread-safe (scratch space is thread-local).
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "sillage/expr/expr.h"
#include "sillage/interval/interval_vector.h"

namespace sillage {

class IntervalMatrix;

namespace detail {
struct FunctionImpl;
class Hc4Rows;
}

class Function {
 public:
  // Parse: variable names (each scalar) and an expression text. A vector
  // function is "(e1, e2, ...)". Throws ParseError on a malformed text.
  Function(const std::vector<std::string>& vars, const std::string& expr);
  // From the C++ builder: Function({x1, x2}, sqrt(sqr(x1 - 1) + sqr(x2 - 2))).
  Function(const std::vector<ExprVar>& vars, const Expr& expr);
  // A vector function (e1, ..., em) of the builder variables vars.
  Function(const std::vector<ExprVar>& vars, const std::vector<Expr>& exprs);

  std::size_t nb_vars() const;     // input dimension n
  std::size_t image_dim() const;   // output dimension m (1 for a scalar function)
  // The names of the n variables, in order.
  const std::vector<std::string>& var_names() const;
  const std::vector<Expr>& exprs() const;  // the m output expressions
  Function operator[](std::size_t i) const;  // the i-th component, a scalar function of the same variables
  std::size_t tape_size() const;             // number of distinct nodes in the DAG

  // Natural inclusion function [f]([x]), size m.
  IntervalVector eval_vector(const IntervalVector& x) const;
  // Scalar functions only (Error otherwise).
  Interval eval(const IntervalVector& x) const;

  // HC4-revise: contract x so that f(x) in y (y.size() == m); one
  // forward-backward pass. Returns false (and x set empty) when proven
  // inconsistent. Never removes a point p of x with f(p) in y.
  bool hc4_revise(IntervalVector& x, const IntervalVector& y) const;
  // Scalar shortcut: f(x) in y.
  bool hc4_revise(IntervalVector& x, const Interval& y) const;
  // hc4_revise on `count` boxes at once, same results box by box: xs[i]
  // points to the `count` intervals of variable i (n pointers), contracted in
  // place; a box proven inconsistent becomes empty in every variable. Both
  // passes walk the tape once per chunk of boxes.
  void hc4_revise_batch(std::span<Interval* const> xs, std::size_t count, const IntervalVector& y) const;

  // Symbolic derivative: for m = 1 the gradient (a vector function of size
  // n); otherwise the Jacobian flattened row-major (size m*n).
  Function diff() const;
  // Jacobian enclosure over the box, m x n.
  IntervalMatrix jacobian(const IntervalVector& x) const;
  // Jacobian enclosure over the box, row-major, size m*n.
  IntervalVector jacobian_vector(const IntervalVector& x) const;
  // Mean-value form f(mid) + J([x])([x] - mid), intersected with the natural
  // one. Falls back to the natural form when [x] leaves the domain of some
  // operation (there the mean-value theorem does not apply), and for an
  // output whose Jacobian row has an empty or unbounded entry (sqrt at 0).
  IntervalVector centered_eval(const IntervalVector& x) const;

  // Batch evaluation: one tape walk, inner loops over the boxes.
  std::vector<IntervalVector> eval_batch(const std::vector<IntervalVector>& xs) const;
  // Structure-of-arrays batch: xs[i] points to `count` intervals of variable
  // i (n pointers); out[k] to `count` intervals of output k (m pointers).
  void eval_batch(std::span<const Interval* const> xs, std::size_t count,
                  std::span<Interval* const> out) const;

  // "(x1, x2) -> sqrt((x1 - 1)^2 + (x2 - 2)^2)"
  std::string str() const;
  // The expression alone, re-parsable with the same variables.
  std::string expr_str() const;

 private:
  friend class detail::Hc4Rows;  // the HC4 on rows the caller fills (internal)
  explicit Function(std::shared_ptr<const detail::FunctionImpl> impl) : impl_(std::move(impl)) {}
  std::shared_ptr<const detail::FunctionImpl> impl_;
};

std::ostream& operator<<(std::ostream& os, const Function& f);

}  // namespace sillage
