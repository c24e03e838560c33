// Tape compilation and scalar (one box) forward evaluation.
#include "sillage/expr/tape.h"

#include <unordered_map>

#include "sillage/error.h"
#include "sillage/expr/op_eval.h"

namespace sillage::detail {

std::vector<Expr> topological_order(const std::vector<Expr>& roots) {
  std::vector<Expr> order;
  std::unordered_map<const ExprNode*, bool> state;  // false: open, true: done
  // Iterative post-order: deep expressions must not exhaust the stack.
  std::vector<std::pair<Expr, std::size_t>> stack;
  for (const Expr& r : roots) {
    if (state.count(r.get())) continue;
    stack.emplace_back(r, 0);
    state[r.get()] = false;
    while (!stack.empty()) {
      auto& [e, i] = stack.back();
      if (i < e.node().args.size()) {
        const Expr child = e.node().args[i++];
        if (!state.count(child.get())) {
          state[child.get()] = false;
          stack.emplace_back(child, 0);
        }
      } else {
        state[e.get()] = true;
        order.push_back(e);
        stack.pop_back();
      }
    }
  }
  return order;
}

Tape::Tape(const std::vector<Expr>& outputs, const std::vector<std::string>& vars) : nb_vars_(vars.size()) {
  std::unordered_map<const ExprNode*, std::uint32_t> slot;
  std::unordered_map<std::string, std::uint32_t> var_index;
  for (std::uint32_t i = 0; i < vars.size(); ++i) {
    var_index[vars[i]] = i;
    Instr in{Op::Var, 0, i, 0, Interval()};
    code_.push_back(in);
  }
  for (const Expr& e : topological_order(outputs)) {
    const ExprNode& node = e.node();
    if (node.op == Op::Var) {
      auto it = var_index.find(node.name);
      if (it == var_index.end()) throw Error("Function: the expression uses \"" + node.name + "\", which is not a declared variable");
      slot[e.get()] = it->second;
      continue;
    }
    Instr in{node.op, node.n, 0, 0, node.value};
    if (!node.args.empty()) in.a = slot.at(node.args[0].get());
    if (node.args.size() > 1) in.b = slot.at(node.args[1].get());
    slot[e.get()] = static_cast<std::uint32_t>(code_.size());
    code_.push_back(in);
  }
  for (const Expr& e : outputs) outputs_.push_back(slot.at(e.get()));
}

void Tape::forward(const Interval* x, Interval* v) const {
  const std::size_t n = code_.size();
  for (std::size_t k = 0; k < nb_vars_; ++k) v[k] = x[k];
  for (std::size_t k = nb_vars_; k < n; ++k) {
    const Instr& in = code_[k];
    v[k] = in.op == Op::Const ? in.value : eval_op(in.op, v[in.a], v[in.b], in.n);
  }
}

namespace {

bool strictly_signed(const Interval& a) { return a.lb() > 0 || a.ub() < 0; }

// The operation is continuous and (almost everywhere) differentiable with
// the derivative that diff builds, on the whole box of its operands.
bool in_domain(const Instr& in, const Interval& a, const Interval& b, const Interval& r) {
  if (r.is_empty()) return false;
  switch (in.op) {
    case Op::Div: return strictly_signed(b);
    case Op::Sqrt: return a.lb() >= 0;
    case Op::Log:
    case Op::Pow: return a.lb() > 0;
    case Op::PowInt: return in.n >= 0 || strictly_signed(a);
    case Op::Root: return in.n % 2 == 1 || a.lb() >= 0;
    case Op::Tan: return r.is_bounded();  // an enclosed pole makes tan unbounded
    case Op::Asin:
    case Op::Acos: return a.lb() >= -1 && a.ub() <= 1;
    case Op::Atan2: return strictly_signed(a) || b.lb() > 0;  // away from the cut y = 0, x <= 0
    case Op::Sign: return strictly_signed(a);
    default: return true;
  }
}

}  // namespace

bool Tape::forward_in_domain(const Interval* x, Interval* v) const {
  const std::size_t n = code_.size();
  bool ok = true;
  for (std::size_t k = 0; k < nb_vars_; ++k) v[k] = x[k];
  for (std::size_t k = nb_vars_; k < n; ++k) {
    const Instr& in = code_[k];
    if (in.op == Op::Const) {
      v[k] = in.value;
      continue;
    }
    v[k] = eval_op(in.op, v[in.a], v[in.b], in.n);
    ok = ok && in_domain(in, v[in.a], v[in.b], v[k]);
  }
  return ok;
}

}  // namespace sillage::detail
