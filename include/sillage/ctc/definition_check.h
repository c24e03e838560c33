#pragma once
// DefinitionCheck: proves that a Function is defined at every point of a box.
// Set-based evaluation silently ignores the points where an operation is
// undefined (sqrt of negatives, log of non-positives, division by zero, ...);
// an inner contractor that trusts it would claim such points satisfy the
// constraint. The check collects the partial operations of the DAG and, on a
// box, encloses their arguments and tests them against the operation's domain.
#include <vector>

#include "sillage/expr/function.h"

namespace sillage {

class DefinitionCheck {
 public:
  // A check of where f is defined (proofs by interval evaluation of its partial operations).
  explicit DefinitionCheck(const Function& f);
  // True when every operation of f is proven defined on the whole box x
  // (an empty box is trivially fine). False means "not proven".
  bool defined_on(const IntervalVector& x) const;
  // True when f uses no partial operation (then defined_on is always true).
  bool is_total() const { return conditions_.empty(); }

 private:
  struct Condition {
    Op op;
    int n;
    std::vector<Function> args;  // the operands, as functions of f's variables
  };
  std::vector<Condition> conditions_;
};

}  // namespace sillage
