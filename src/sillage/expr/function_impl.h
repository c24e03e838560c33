#pragma once
// What a Function holds (internal header of the expression layer): its
// variables, expressions and compiled tape.
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "sillage/expr/expr.h"
#include "sillage/expr/tape.h"

namespace sillage::detail {

struct FunctionImpl {
  std::vector<std::string> vars;
  std::vector<ExprVar> var_exprs;
  std::vector<Expr> exprs;
  Tape tape;
  // The derivative, built on first use (call_once: thread-safe).
  mutable std::once_flag diff_once;
  mutable std::shared_ptr<const FunctionImpl> diff;
};

}  // namespace sillage::detail
