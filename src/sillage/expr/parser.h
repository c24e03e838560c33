#pragma once
// Text syntax of expressions:
//   sum     := product (('+' | '-') product)*
//   product := unary (('*' | '/') unary)*
//   unary   := ('-' | '+') unary | power
//   power   := primary ('^' unary)?          right-associative, above unary minus:
//                                             -x^2 = -(x^2), 2^-x = 2^(-x)
//   primary := number | '[' bound ',' bound ']' | 'pi' | variable
//            | name '(' sum (',' sum)* ')' | '(' sum ')'
// The whole text may be a vector "(e1, e2, ...)". Numbers (1, 1.5, 2e-3, .5)
// and interval bounds are enclosed rigorously (0.1 is not a double); bounds
// may be inf or oo, and "[empty]" is the empty set. Functions: sqr sqrt exp
// log pow(x, y) root(x, n) sin cos tan asin acos atan atan2(y, x) sinh cosh
// tanh abs min max sign. Errors throw ParseError naming what was expected and
// the (1-based) column.
#include <string>
#include <vector>

#include "sillage/expr/expr.h"

namespace sillage::detail {

// The output expressions of `text` (one for a scalar function, m for a vector).
std::vector<Expr> parse_exprs(const std::vector<std::string>& vars, const std::string& text);
// A scalar expression (a vector text is an error).
Expr parse_expr(const std::vector<std::string>& vars, const std::string& text);

// True for the names the syntax reserves (pi, inf, oo, nan, function names).
bool is_reserved_name(const std::string& name);

}  // namespace sillage::detail
