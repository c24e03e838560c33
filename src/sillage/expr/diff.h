#pragma once
// Symbolic differentiation over the DAG (forward mode, one sweep of the
// topological order per variable). Derivatives are expressions in the same
// DAG, so they share nodes with the function (cos(x) in d sin(x), exp(x) in
// d exp(x)); trivial terms are simplified away (0*e = 0, 1*e = e, e+0 = e).
#include <vector>

#include "sillage/expr/expr.h"

namespace sillage::detail {

// d e / d v.
Expr diff(const Expr& e, const ExprVar& v);
// The Jacobian of (e_1, ..., e_m) with respect to (v_1, ..., v_n), row-major:
// element i*n + j is d e_i / d v_j.
std::vector<Expr> jacobian_exprs(const std::vector<Expr>& es, const std::vector<ExprVar>& vars);

}  // namespace sillage::detail
