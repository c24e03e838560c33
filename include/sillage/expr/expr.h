#pragma once
// Expression DAG (thesis 2.2.3, 2.3.1): immutable nodes shared through Expr
// handles. Nodes are hash-consed: building the same sub-expression twice
// gives the same node, so a compiled Function evaluates it once and HC4
// intersects the projections that reach it.
//
// Builder: ExprVar x1("x1"), x2("x2"); Expr e = sqrt(sqr(x1 - 1) + sqr(x2 - 2));
// Constants are intervals (a double d is the degenerate [d, d]); expr_pi() is
// a rigorous enclosure of pi. Two constant operands are folded at build time
// with interval arithmetic (rigorous).
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "sillage/interval/interval.h"

namespace sillage {

// The operation of an expression node.
enum class Op : std::uint8_t {
  Const, Var,
  Add, Sub, Mul, Div, Neg,
  Sqr, Sqrt, PowInt, Pow, Root, Exp, Log,
  Sin, Cos, Tan, Asin, Acos, Atan, Atan2,
  Sinh, Cosh, Tanh, Abs, Min, Max, Sign,
};

// Name of the operation as written in expressions ("+", "sin", ...).
const char* op_name(Op op);
// Number of operands (0, 1 or 2).
int op_arity(Op op);

class ExprNode;

class Expr {
 public:
  Expr(double c);                       // NOLINT: the constant [c, c]
  Expr(const Interval& c);              // NOLINT: an interval constant
  explicit Expr(std::shared_ptr<const ExprNode> node) : node_(std::move(node)) {}

  const ExprNode& node() const { return *node_; }
  const ExprNode* get() const { return node_.get(); }
  // The operation of the root node.
  Op op() const;
  // True when the expression has no variable.
  bool is_const() const;
  // Same node (hash-consing makes this structural equality).
  bool operator==(const Expr& y) const { return node_ == y.node_; }
  bool operator!=(const Expr& y) const { return node_ != y.node_; }
  std::string str() const;

 private:
  std::shared_ptr<const ExprNode> node_;
};

// A scalar variable, known by its name.
class ExprVar : public Expr {
 public:
  // The scalar variable called name.
  explicit ExprVar(const std::string& name);
  // The variable's name.
  const std::string& name() const;
};

using Variable = ExprVar;

class ExprNode {
 public:
  ExprNode() = default;
  ExprNode(ExprNode&&) = default;
  ExprNode& operator=(ExprNode&&) = default;
  // Releases the operands iteratively: a long chain of nodes must not
  // exhaust the stack by recursive destruction.
  ~ExprNode();

  Op op = Op::Const;
  int n = 0;                  // integer exponent (PowInt) or root order (Root)
  Interval value;             // Const
  std::string name;           // Var
  std::vector<Expr> args;     // operands
  std::size_t hash = 0;
};

// Makes (or finds) the node op(args) with the given parameters; no folding.
Expr make_node(Op op, std::vector<Expr> args, int n = 0);

Expr operator+(const Expr& x, const Expr& y);
Expr operator-(const Expr& x, const Expr& y);
Expr operator*(const Expr& x, const Expr& y);
Expr operator/(const Expr& x, const Expr& y);
Expr operator-(const Expr& x);
inline Expr operator+(const Expr& x) { return x; }
Expr& operator+=(Expr& x, const Expr& y);
Expr& operator-=(Expr& x, const Expr& y);
Expr& operator*=(Expr& x, const Expr& y);
Expr& operator/=(Expr& x, const Expr& y);

// A rigorous enclosure of pi, as a constant expression.
Expr expr_pi();
// The expression x^2.
Expr sqr(const Expr& x);
// The expression sqrt(x).
Expr sqrt(const Expr& x);
// The expression x^n, n an integer.
Expr pow(const Expr& x, int n);
Expr pow(const Expr& x, double y);       // so that pow(x, 0.5) does not convert 0.5 to int
Expr pow(const Expr& x, const Expr& y);  // real exponent (integer constants give pow(x, n))
// The expression root(x, n), the n-th root.
Expr root(const Expr& x, int n);
// The expression exp(x).
Expr exp(const Expr& x);
// The expression log(x) (natural logarithm).
Expr log(const Expr& x);
// The expression sin(x).
Expr sin(const Expr& x);
// The expression cos(x).
Expr cos(const Expr& x);
// The expression tan(x).
Expr tan(const Expr& x);
// The expression asin(x).
Expr asin(const Expr& x);
// The expression acos(x).
Expr acos(const Expr& x);
// The expression atan(x).
Expr atan(const Expr& x);
// The expression atan2(y, x), y first.
Expr atan2(const Expr& y, const Expr& x);
// The expression sinh(x).
Expr sinh(const Expr& x);
// The expression cosh(x).
Expr cosh(const Expr& x);
// The expression tanh(x).
Expr tanh(const Expr& x);
// The expression abs(x).
Expr abs(const Expr& x);
// The expression min(x, y).
Expr min(const Expr& x, const Expr& y);
// The expression max(x, y).
Expr max(const Expr& x, const Expr& y);
// The expression sign(x).
Expr sign(const Expr& x);

// Infix text that parse_expr reads back into the same DAG; a shared
// sub-expression of more than a few characters is printed once, named by a
// let-binding ("let a = x * x + 1; b = a * a + 1 in b * b + 1"): the text is
// linear in the size of the DAG.
std::ostream& operator<<(std::ostream& os, const Expr& e);
// The same for several expressions sharing their bindings, "(e1, e2, ...)"
// when as_vector (else separated by ", "); no binding is named as one of
// `taken` (the variables of a Function, used or not).
void print_exprs(std::ostream& os, const std::vector<Expr>& es, bool as_vector,
                 const std::vector<std::string>& taken = {});

}  // namespace sillage
