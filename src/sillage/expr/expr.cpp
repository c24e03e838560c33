// Expression nodes: hash-consing table, builder operators, constant folding.
#include "sillage/expr/expr.h"

#include <bit>
#include <cctype>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <mutex>

#include "sillage/expr/op_eval.h"

namespace sillage {

const char* op_name(Op op) {
  switch (op) {
    case Op::Const: return "const";
    case Op::Var: return "var";
    case Op::Add: return "+";
    case Op::Sub: return "-";
    case Op::Mul: return "*";
    case Op::Div: return "/";
    case Op::Neg: return "-";
    case Op::Sqr: return "sqr";
    case Op::Sqrt: return "sqrt";
    case Op::PowInt: return "^";
    case Op::Pow: return "pow";
    case Op::Root: return "root";
    case Op::Exp: return "exp";
    case Op::Log: return "log";
    case Op::Sin: return "sin";
    case Op::Cos: return "cos";
    case Op::Tan: return "tan";
    case Op::Asin: return "asin";
    case Op::Acos: return "acos";
    case Op::Atan: return "atan";
    case Op::Atan2: return "atan2";
    case Op::Sinh: return "sinh";
    case Op::Cosh: return "cosh";
    case Op::Tanh: return "tanh";
    case Op::Abs: return "abs";
    case Op::Min: return "min";
    case Op::Max: return "max";
    case Op::Sign: return "sign";
  }
  return "?";
}

int op_arity(Op op) {
  switch (op) {
    case Op::Const:
    case Op::Var: return 0;
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::Pow:
    case Op::Atan2:
    case Op::Min:
    case Op::Max: return 2;
    default: return 1;
  }
}

namespace {

std::size_t mix(std::size_t h, std::size_t v) {
  return h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
}

std::size_t bits(double d) { return d == 0 ? 0 : std::bit_cast<std::uint64_t>(d); }  // -0 == +0

bool same_key(const ExprNode& a, const ExprNode& b) {
  if (a.op != b.op || a.n != b.n || a.name != b.name || a.args.size() != b.args.size()) return false;
  if (a.op == Op::Const && !(a.value == b.value)) return false;
  for (std::size_t i = 0; i < a.args.size(); ++i)
    if (a.args[i] != b.args[i]) return false;
  return true;
}

// Global table of live nodes: open addressing with linear probing (one cache
// line per probe, large DAGs build in linear time). Weak references: a node
// dies with its last Expr; dead slots are reused or dropped on rehash.
class NodeTable {
 public:
  std::shared_ptr<const ExprNode> intern(ExprNode&& node) {
    std::size_t h = mix(static_cast<std::size_t>(node.op), static_cast<std::size_t>(node.n));
    if (node.op == Op::Const) h = mix(mix(h, bits(node.value.lb())), bits(node.value.ub()));
    if (node.op == Op::Var) h = mix(h, std::hash<std::string>{}(node.name));
    for (const Expr& a : node.args) h = mix(h, std::hash<const void*>{}(a.get()));
    node.hash = h;
    const std::size_t key = finalize(h);
    std::lock_guard<std::mutex> lock(mutex_);
    if (2 * (used_ + 1) > slots_.size()) rehash();
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = key & mask, reuse = slots_.size();
    for (; slots_[i].used; i = (i + 1) & mask) {
      if (slots_[i].hash == h) {
        if (auto p = slots_[i].node.lock(); p && same_key(*p, node)) return p;
      }
      if (reuse == slots_.size() && slots_[i].node.expired()) reuse = i;
    }
    auto p = std::make_shared<const ExprNode>(std::move(node));
    if (reuse != slots_.size()) {
      slots_[reuse].hash = h;  // a dead slot keeps the probe chains intact
      slots_[reuse].node = p;
    } else {
      slots_[i] = {h, true, p};
      ++used_;
    }
    return p;
  }

 private:
  struct Slot {
    std::size_t hash = 0;
    bool used = false;
    std::weak_ptr<const ExprNode> node;
  };

  static std::size_t finalize(std::size_t h) {  // splitmix64: good low bits for the mask
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebULL;
    return h ^ (h >> 31);
  }

  // Drops the dead entries and grows to keep the load below 1/4 after it.
  void rehash() {
    std::vector<Slot> old;
    old.swap(slots_);
    std::size_t live = 0;
    for (const Slot& s : old) live += s.used && !s.node.expired();
    std::size_t cap = 64;
    while (cap < 4 * (live + 1)) cap *= 2;
    slots_.assign(cap, Slot{});
    used_ = 0;
    for (Slot& s : old) {
      if (!s.used || s.node.expired()) continue;
      std::size_t i = finalize(s.hash) & (cap - 1);
      while (slots_[i].used) i = (i + 1) & (cap - 1);
      slots_[i] = std::move(s);
      ++used_;
    }
  }

  std::mutex mutex_;
  std::vector<Slot> slots_;
  std::size_t used_ = 0;
};

NodeTable& table() {
  static NodeTable* t = new NodeTable;  // never destroyed: Exprs may outlive static destruction
  return *t;
}

Expr make_const(const Interval& c) {
  ExprNode n;
  n.op = Op::Const;
  n.value = c;
  return Expr(table().intern(std::move(n)));
}

// Operations on constants are folded with interval arithmetic (rigorous).
Expr fold_or_make(Op op, std::vector<Expr> args, int n = 0) {
  bool all_const = true;
  for (const Expr& a : args) all_const = all_const && a.is_const();
  if (all_const) {
    const Interval a = args[0].node().value;
    const Interval b = args.size() > 1 ? args[1].node().value : Interval(0.0);
    return make_const(detail::eval_op(op, a, b, n));
  }
  return make_node(op, std::move(args), n);
}

// An integer in int range held by a degenerate constant, for pow(x, 3).
bool const_int(const Expr& e, int& n) {
  if (!e.is_const()) return false;
  const Interval& v = e.node().value;
  if (!v.is_degenerate() || std::fabs(v.lb()) > std::numeric_limits<int>::max() || v.lb() != std::floor(v.lb()))
    return false;
  n = static_cast<int>(v.lb());
  return true;
}

}  // namespace

ExprNode::~ExprNode() {
  // The outermost destructor drains a local list; nested ones (reached from
  // it) only append their operands to it. A raw thread_local pointer has no
  // destructor, so this also works during static destruction.
  thread_local std::vector<Expr>* pending = nullptr;
  if (pending) {
    for (Expr& a : args) pending->push_back(std::move(a));
    return;
  }
  if (args.empty()) return;
  std::vector<Expr> list(std::make_move_iterator(args.begin()), std::make_move_iterator(args.end()));
  pending = &list;
  while (!list.empty()) {
    Expr last = std::move(list.back());
    list.pop_back();
  }  // `last` dies here; its node, if unshared, appends its operands to `list`
  pending = nullptr;
}

Expr make_node(Op op, std::vector<Expr> args, int n) {
  ExprNode node;
  node.op = op;
  node.n = n;
  node.args = std::move(args);
  return Expr(table().intern(std::move(node)));
}

Expr::Expr(double c) : Expr(Interval(c)) {}
Expr::Expr(const Interval& c) : node_(make_const(c).node_) {}
Op Expr::op() const { return node_->op; }
bool Expr::is_const() const { return node_->op == Op::Const; }

static bool valid_identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

static std::shared_ptr<const ExprNode> var_node(const std::string& name) {
  if (!valid_identifier(name)) throw Error("ExprVar: invalid variable name \"" + name + "\"");
  ExprNode n;
  n.op = Op::Var;
  n.name = name;
  return table().intern(std::move(n));
}

ExprVar::ExprVar(const std::string& name) : Expr(var_node(name)) {}
const std::string& ExprVar::name() const { return node().name; }

Expr operator+(const Expr& x, const Expr& y) { return fold_or_make(Op::Add, {x, y}); }
Expr operator-(const Expr& x, const Expr& y) { return fold_or_make(Op::Sub, {x, y}); }
Expr operator*(const Expr& x, const Expr& y) { return fold_or_make(Op::Mul, {x, y}); }
Expr operator/(const Expr& x, const Expr& y) { return fold_or_make(Op::Div, {x, y}); }
Expr operator-(const Expr& x) { return fold_or_make(Op::Neg, {x}); }
Expr& operator+=(Expr& x, const Expr& y) { return x = x + y; }
Expr& operator-=(Expr& x, const Expr& y) { return x = x - y; }
Expr& operator*=(Expr& x, const Expr& y) { return x = x * y; }
Expr& operator/=(Expr& x, const Expr& y) { return x = x / y; }

Expr expr_pi() { return Expr(Interval::pi()); }
Expr sqr(const Expr& x) { return fold_or_make(Op::Sqr, {x}); }
Expr sqrt(const Expr& x) { return fold_or_make(Op::Sqrt, {x}); }
Expr pow(const Expr& x, int n) {
  if (n == 1) return x;
  if (n == 2) return sqr(x);
  return fold_or_make(Op::PowInt, {x}, n);
}
Expr pow(const Expr& x, double y) { return pow(x, Expr(y)); }
Expr pow(const Expr& x, const Expr& y) {
  int n = 0;
  if (const_int(y, n)) return pow(x, n);
  // An integer beyond the int range stays an integer power (x < 0 allowed):
  // x^(2m) = (x^2)^m, x^(2m+1) = x * x^(2m), all exact in binary64.
  if (y.is_const() && y.node().value.is_degenerate()) {
    const double v = y.node().value.lb();
    if (v == std::trunc(v)) return std::fmod(v, 2.0) == 0 ? pow(sqr(x), Expr(v / 2)) : x * pow(x, Expr(v - 1));
  }
  return fold_or_make(Op::Pow, {x, y});
}
Expr root(const Expr& x, int n) {
  if (n < 1) throw Error("root: the order must be >= 1, got " + std::to_string(n));
  if (n == 1) return x;
  if (n == 2) return sqrt(x);
  return fold_or_make(Op::Root, {x}, n);
}
Expr exp(const Expr& x) { return fold_or_make(Op::Exp, {x}); }
Expr log(const Expr& x) { return fold_or_make(Op::Log, {x}); }
Expr sin(const Expr& x) { return fold_or_make(Op::Sin, {x}); }
Expr cos(const Expr& x) { return fold_or_make(Op::Cos, {x}); }
Expr tan(const Expr& x) { return fold_or_make(Op::Tan, {x}); }
Expr asin(const Expr& x) { return fold_or_make(Op::Asin, {x}); }
Expr acos(const Expr& x) { return fold_or_make(Op::Acos, {x}); }
Expr atan(const Expr& x) { return fold_or_make(Op::Atan, {x}); }
Expr atan2(const Expr& y, const Expr& x) { return fold_or_make(Op::Atan2, {y, x}); }
Expr sinh(const Expr& x) { return fold_or_make(Op::Sinh, {x}); }
Expr cosh(const Expr& x) { return fold_or_make(Op::Cosh, {x}); }
Expr tanh(const Expr& x) { return fold_or_make(Op::Tanh, {x}); }
Expr abs(const Expr& x) { return fold_or_make(Op::Abs, {x}); }
Expr min(const Expr& x, const Expr& y) { return fold_or_make(Op::Min, {x, y}); }
Expr max(const Expr& x, const Expr& y) { return fold_or_make(Op::Max, {x, y}); }
Expr sign(const Expr& x) { return fold_or_make(Op::Sign, {x}); }

}  // namespace sillage
