// Taylor coefficients by the recursive rules of automatic differentiation.
#include "sillage/expr/taylor.h"

#include <cstdlib>
#include <string>

#include "sillage/error.h"
#include "sillage/interval/elementary.h"

namespace sillage::detail {

namespace {

using detail::Instr;

// Series of an operation kept beside its own: cos for sin, 1 + tan² for
// tan, the powers a², ..., a^|n| for an integer power, ...
std::size_t aux_series(const Instr& in) {
  switch (in.op) {
    case Op::Sin: case Op::Cos: case Op::Sinh: case Op::Cosh: case Op::Tan: case Op::Atan: case Op::Tanh:
    case Op::Asin: case Op::Acos: case Op::Atan2:
      return 1;
    case Op::Pow:  // log a, then b·log a
      return 2;
    case Op::PowInt:
      return std::abs(in.n) >= 2 ? static_cast<std::size_t>(std::abs(in.n) - 1) : 0;
    default:
      return 0;
  }
}

// Every operation has one; abs, min, max and sign only where they are
// smooth (their operands away from the kink over the whole box).
bool has_taylor_rule(Op op) {
  switch (op) {
    case Op::Const: case Op::Var: case Op::Add: case Op::Sub: case Op::Mul: case Op::Div: case Op::Neg:
    case Op::Sqr: case Op::Sqrt: case Op::PowInt: case Op::Pow: case Op::Root: case Op::Exp: case Op::Log:
    case Op::Sin: case Op::Cos: case Op::Tan: case Op::Asin: case Op::Acos: case Op::Atan: case Op::Atan2:
    case Op::Sinh: case Op::Cosh: case Op::Tanh: case Op::Abs: case Op::Min: case Op::Max: case Op::Sign:
      return true;
  }
  return false;
}

void check_rules(const detail::Tape& tape) {
  for (const Instr& in : tape.code()) {
    if (!has_taylor_rule(in.op)) {
      throw Error(std::string("TaylorOde: the operation \"") + op_name(in.op) + "\" has no Taylor rule");
    }
  }
}

// The partner of sin is cos (sinh: cosh) and back: the pair recurrence
// computes both series at once.
bool is_pair_op(Op op) { return op == Op::Sin || op == Op::Cos || op == Op::Sinh || op == Op::Cosh; }
Op pair_partner(Op op) {
  switch (op) {
    case Op::Sin: return Op::Cos;
    case Op::Cos: return Op::Sin;
    case Op::Sinh: return Op::Cosh;
    default: return Op::Sinh;
  }
}

}  // namespace

// twin[s]: the earlier node whose companion series is node s's own (cos x
// after sin x, both in f and its Jacobian), kNoTwin if none.
std::vector<std::uint32_t> pair_twins(const detail::Tape& tape) {
  const std::vector<Instr>& code = tape.code();
  std::vector<std::uint32_t> twin(code.size(), kNoTwin);
  for (std::size_t s = 0; s < code.size(); ++s) {
    if (!is_pair_op(code[s].op)) continue;
    for (std::size_t r = 0; r < s; ++r) {
      if (code[r].op == pair_partner(code[s].op) && code[r].a == code[s].a && twin[r] == kNoTwin) {
        twin[s] = static_cast<std::uint32_t>(r);
        break;
      }
    }
  }
  return twin;
}

std::vector<std::uint8_t> scaled_operands(const detail::Tape& tape, const std::vector<std::uint32_t>& twin) {
  const std::vector<Instr>& code = tape.code();
  std::vector<std::uint8_t> scaled(code.size(), 0);
  for (std::size_t s = 0; s < code.size(); ++s) {
    const Op op = code[s].op;
    if ((op == Op::Exp || op == Op::Tan || op == Op::Tanh || is_pair_op(op)) && twin[s] == kNoTwin) scaled[code[s].a] = 1;
  }
  return scaled;
}

namespace {

// Σ_{j=1}^{k} da_j b_{k-j} / k with da_j = j a_j: order k of w when w' = a'·b.
Interval dconv_scaled(const Interval* da, const Interval* b, std::size_t k) {
  Interval s(0.0);
  for (std::size_t j = 1; j <= k; ++j) s += da[j] * b[k - j];
  return s / Interval(static_cast<double>(k));
}

// Σ_{j=lo}^{hi} a_j b_{k-j}
Interval conv(const Interval* a, const Interval* b, std::size_t k, std::size_t lo, std::size_t hi) {
  Interval s(0.0);
  for (std::size_t j = lo; j <= hi; ++j) s += a[j] * b[k - j];
  return s;
}

// Σ_{j=1}^{k} j a_j b_{k-j} / k: order k of w when w' = a'·b.
Interval dconv(const Interval* a, const Interval* b, std::size_t k) {
  Interval s(0.0);
  for (std::size_t j = 1; j <= k; ++j) s += Interval(static_cast<double>(j)) * a[j] * b[k - j];
  return s / Interval(static_cast<double>(k));
}

// Order k of a², tighter than conv (each cross product once, doubled).
Interval sqr_series(const Interval* a, std::size_t k) {
  if (k == 0) return sqr(a[0]);
  Interval s(0.0);
  for (std::size_t j = 0; 2 * j < k; ++j) s += a[j] * a[k - j];
  s = Interval(2.0) * s;
  if (k % 2 == 0) s += sqr(a[k / 2]);
  return s;
}

// Order k of 1/b (w_0..w_{k-1} known); false when b_0 contains 0.
bool recip_series(Interval* w, const Interval* b, std::size_t k) {
  if (k == 0) {
    if (b[0].contains(0.0) || b[0].is_empty()) return false;
    w[0] = Interval(1.0) / b[0];
    return true;
  }
  w[k] = -conv(w, b, k, 0, k - 1) / b[0];
  // conv sums w_j b_{k-j} for j < k: the terms of b_1..b_k
  return true;
}

// Order k ≥ 1 of w when q·w' = r' with the series of q and r known to
// order k (w to k - 1): k q_0 w_k = k r_k - Σ_{i=1}^{k-1} (k - i) q_i w_{k-i}.
Interval quotient_rule(const Interval* w, const Interval* q, const Interval& k_r_k, std::size_t k) {
  Interval s(0.0);
  for (std::size_t i = 1; i < k; ++i) s += q[i] * Interval(static_cast<double>(k - i)) * w[k - i];
  return (k_r_k - s) / (Interval(static_cast<double>(k)) * q[0]);
}

// Order k ≥ 1 of w = a^c (c a constant), from a·w' = c·a'·w:
// k a_0 w_k = Σ_{j=1}^{k} (c j - (k - j)) a_j w_{k-j}.
Interval power_rule(const Interval* w, const Interval* a, const Interval& c, std::size_t k) {
  Interval s(0.0);
  for (std::size_t j = 1; j <= k; ++j) {
    s += (c * Interval(static_cast<double>(j)) - Interval(static_cast<double>(k - j))) * a[j] * w[k - j];
  }
  return s / (Interval(static_cast<double>(k)) * a[0]);
}

}  // namespace

TaylorOde::TaylorOde(const Function& f) : f_(f), n_(f.image_dim()) {
  if (f.nb_vars() < n_) {
    throw DimensionError("TaylorOde: f has " + std::to_string(f.nb_vars()) + " variables for " +
                         std::to_string(n_) + " outputs; expected the n states then the inputs");
  }
  m_ = f.nb_vars() - n_;
  tape_ = detail::Tape(f.exprs(), f.var_names());
  check_rules(tape_);
  std::vector<Expr> outs = f.exprs();
  const std::vector<Expr>& jac = f.diff().exprs();
  for (std::size_t i = 0; i < n_; ++i) {
    for (std::size_t j = 0; j < n_; ++j) outs.push_back(jac[i * f.nb_vars() + j]);
  }
  var_tape_ = detail::Tape(outs, f.var_names());
  check_rules(var_tape_);
  twins_ = pair_twins(tape_);
  var_twins_ = pair_twins(var_tape_);
  scaled_ = scaled_operands(tape_, twins_);
  var_scaled_ = scaled_operands(var_tape_, var_twins_);
}

bool TaylorOde::coefficients(std::vector<Interval>& x, const Interval* u, int order, double sign) const {
  return run(tape_, twins_, scaled_, x, nullptr, u, order, sign);
}

bool TaylorOde::coefficients(std::vector<Interval>& x, std::vector<Interval>& v, const Interval* u, int order,
                             double sign) const {
  return run(var_tape_, var_twins_, var_scaled_, x, &v, u, order, sign);
}

bool TaylorOde::run(const detail::Tape& tape, const std::vector<std::uint32_t>& twin,
                    const std::vector<std::uint8_t>& scaled, std::vector<Interval>& x, std::vector<Interval>* v, const Interval* u,
                    int order, double sign) const {
  const std::size_t n = n_;
  const std::size_t top = static_cast<std::size_t>(order);
  x.resize((top + 1) * n);
  if (v) {
    v->assign((top + 1) * n * n, Interval(0.0));
    for (std::size_t i = 0; i < n; ++i) (*v)[i * n + i] = Interval(1.0);
  }
  if (top == 0) return true;
  const std::vector<Instr>& code = tape.code();
  const std::size_t K = top;  // node orders 0..top-1 give the solution's orders 1..top
  std::vector<std::size_t> aux(code.size());
  std::size_t total = code.size() * K;
  for (std::size_t s = 0; s < code.size(); ++s) {
    aux[s] = total;
    if (twin[s] == kNoTwin) total += aux_series(code[s]) * K;
  }
  std::vector<std::size_t> scaled_at(code.size());  // da_j = j·a_j of the operands of w' = a'·b rules
  for (std::size_t s = 0; s < code.size(); ++s) {
    scaled_at[s] = total;
    if (scaled[s]) total += K;
  }
  thread_local std::vector<Interval> store;
  store.assign(total, Interval(0.0));
  Interval* c = store.data();
  const Interval sg(sign);
  for (std::size_t k = 0; k < K; ++k) {
    for (std::size_t s = 0; s < code.size(); ++s) {
      const Instr& in = code[s];
      Interval* w = c + s * K;
      const Interval* a = c + in.a * K;
      const Interval* b = c + in.b * K;
      Interval* q = c + aux[s];
      const Interval* da = c + scaled_at[in.a];  // meaningful when scaled[in.a]
      const Interval kk(static_cast<double>(k));
      switch (in.op) {
        case Op::Var:
          w[k] = in.a < n ? x[k * n + in.a] : (k == 0 ? u[in.a - n] : Interval(0.0));
          break;
        case Op::Const:
          w[k] = k == 0 ? in.value : Interval(0.0);
          break;
        case Op::Add: w[k] = a[k] + b[k]; break;
        case Op::Sub: w[k] = a[k] - b[k]; break;
        case Op::Neg: w[k] = -a[k]; break;
        case Op::Mul: w[k] = conv(a, b, k, 0, k); break;
        case Op::Sqr: w[k] = sqr_series(a, k); break;
        case Op::Div:
          if (k == 0) {
            if (b[0].contains(0.0) || b[0].is_empty()) return false;
            w[0] = a[0] / b[0];
          } else {
            w[k] = (a[k] - conv(w, b, k, 0, k - 1)) / b[0];
          }
          break;
        case Op::Sqrt:
          if (k == 0) {
            if (!(a[0].lb() > 0.0)) return false;
            w[0] = sqrt(a[0]);
          } else {
            w[k] = (a[k] - conv(w, w, k, 1, k - 1)) / (Interval(2.0) * w[0]);
          }
          break;
        case Op::Exp:
          w[k] = k == 0 ? exp(a[0]) : dconv_scaled(da, w, k);
          break;
        case Op::Log:
          if (k == 0) {
            if (!(a[0].lb() > 0.0)) return false;
            w[0] = log(a[0]);
          } else {
            Interval s2(0.0);
            for (std::size_t j = 1; j < k; ++j) s2 += Interval(static_cast<double>(j)) * w[j] * a[k - j];
            w[k] = (a[k] - s2 / kk) / a[0];
          }
          break;
        case Op::Sin: case Op::Cos: case Op::Sinh: case Op::Cosh: {
          // w and its companion q: sin/cos (q' = -w a' for sin... ), sinh/cosh
          if (twin[s] != kNoTwin) {  // the companion of an earlier node on the same operand
            w[k] = c[aux[twin[s]] + k];
            break;
          }
          const bool trig = in.op == Op::Sin || in.op == Op::Cos;
          if (k == 0) {
            if (in.op == Op::Sin) { w[0] = sin(a[0]); q[0] = cos(a[0]); }
            if (in.op == Op::Cos) { w[0] = cos(a[0]); q[0] = sin(a[0]); }
            if (in.op == Op::Sinh) { w[0] = sinh(a[0]); q[0] = cosh(a[0]); }
            if (in.op == Op::Cosh) { w[0] = cosh(a[0]); q[0] = sinh(a[0]); }
          } else {
            const Interval dw = dconv_scaled(da, q, k), dq = dconv_scaled(da, w, k);
            // sin' = cos a', cos' = -sin a'; sinh' = cosh a', cosh' = sinh a'
            if (in.op == Op::Sin) { w[k] = dw; q[k] = -dq; }
            if (in.op == Op::Cos) { w[k] = -dw; q[k] = dq; }
            if (!trig) { w[k] = dw; q[k] = dq; }
          }
          break;
        }
        case Op::Tan:  // w' = a'·q with q = 1 + w²
          if (k == 0) {
            w[0] = tan(a[0]);
            if (w[0].is_empty() || w[0].is_unbounded()) return false;
          } else {
            w[k] = dconv_scaled(da, q, k);
          }
          q[k] = sqr_series(w, k) + (k == 0 ? Interval(1.0) : Interval(0.0));
          break;
        case Op::Atan:  // q·w' = a' with q = 1 + a²
          q[k] = sqr_series(a, k) + (k == 0 ? Interval(1.0) : Interval(0.0));
          w[k] = k == 0 ? atan(a[0]) : quotient_rule(w, q, kk * a[k], k);
          break;
        case Op::Asin: case Op::Acos: {  // q·w' = ±a' with q = sqrt(1 - a²)
          const Interval s2 = (k == 0 ? Interval(1.0) : Interval(0.0)) - sqr_series(a, k);
          if (k == 0) {
            if (!(s2.lb() > 0.0)) return false;
            q[0] = sqrt(s2);
            w[0] = in.op == Op::Asin ? asin(a[0]) : acos(a[0]);
          } else {
            q[k] = (s2 - conv(q, q, k, 1, k - 1)) / (Interval(2.0) * q[0]);
            w[k] = quotient_rule(w, q, (in.op == Op::Asin ? kk : -kk) * a[k], k);
          }
          break;
        }
        case Op::Tanh:  // w' = a'·q with q = 1 - w²
          if (k == 0) {
            w[0] = tanh(a[0]);
          } else {
            w[k] = dconv_scaled(da, q, k);
          }
          q[k] = (k == 0 ? Interval(1.0) : Interval(0.0)) - sqr_series(w, k);
          break;
        case Op::Atan2: {  // w = atan2(a, b): q·w' = b·a' - a·b' with q = a² + b²
          if (k == 0) {
            // smooth away from the cut (b ≤ 0, a = 0) and the origin
            if (a[0].contains(0.0) && !(b[0].lb() > 0.0)) return false;
            w[0] = atan2(a[0], b[0]);
          }
          q[k] = sqr_series(a, k) + sqr_series(b, k);
          if (k > 0) {
            Interval r(0.0);
            for (std::size_t j = 1; j <= k; ++j) r += Interval(static_cast<double>(j)) * (b[k - j] * a[j] - a[k - j] * b[j]);
            w[k] = quotient_rule(w, q, r, k);
          }
          break;
        }
        case Op::Pow: {  // w = exp(b·log a), a > 0: L = log a in q, P = b·L in q + K
          Interval* L = q;
          Interval* P = q + K;
          if (k == 0) {
            if (!(a[0].lb() > 0.0)) return false;
            L[0] = log(a[0]);
          } else {
            Interval s2(0.0);
            for (std::size_t j = 1; j < k; ++j) s2 += Interval(static_cast<double>(j)) * L[j] * a[k - j];
            L[k] = (a[k] - s2 / kk) / a[0];
          }
          P[k] = conv(b, L, k, 0, k);
          w[k] = k == 0 ? pow(a[0], b[0]) & exp(P[0]) : dconv(P, w, k);
          if (w[k].is_empty()) return false;
          break;
        }
        case Op::Root:  // w = a^(1/n): a·w' = (1/n)·a'·w, a away from 0
          if (k == 0) {
            if (a[0].contains(0.0) || a[0].is_empty()) return false;
            w[0] = root(a[0], in.n);
            if (w[0].is_empty()) return false;
          } else {
            w[k] = power_rule(w, a, Interval(1.0) / Interval(static_cast<double>(in.n)), k);
          }
          break;
        case Op::Abs:  // ±a where a keeps its sign
          if (k == 0 && (a[0].contains(0.0) || a[0].is_empty())) return false;
          w[k] = a[0].lb() > 0.0 ? a[k] : -a[k];
          break;
        case Op::Sign:  // constant where a keeps its sign
          if (k == 0 && (a[0].contains(0.0) || a[0].is_empty())) return false;
          w[k] = k == 0 ? Interval(a[0].lb() > 0.0 ? 1.0 : -1.0) : Interval(0.0);
          break;
        case Op::Min: case Op::Max: {  // one operand where they do not cross
          if (k == 0 && !(a[0].ub() < b[0].lb() || b[0].ub() < a[0].lb())) return false;
          const bool a_below = a[0].ub() < b[0].lb();
          w[k] = (in.op == Op::Min) == a_below ? a[k] : b[k];
          break;
        }
        case Op::PowInt: {
          const int e = std::abs(in.n);
          if (e == 0) { w[k] = k == 0 ? Interval(1.0) : Interval(0.0); break; }
          // powers P_2..P_e in q (P_1 = a), each a product with a
          const Interval* prev = a;
          for (int p = 2; p <= e; ++p) {
            Interval* cur = q + static_cast<std::size_t>(p - 2) * K;
            cur[k] = p == 2 ? sqr_series(a, k) : conv(prev, a, k, 0, k);
            prev = cur;
          }
          if (in.n > 0) {
            w[k] = prev[k];
          } else if (!recip_series(w, prev, k)) {
            return false;
          }
          break;
        }
      }
      if (scaled[s] && k > 0) c[scaled_at[s] + k] = kk * w[k];
    }
    const Interval next(static_cast<double>(k + 1));
    const std::vector<std::uint32_t>& out = tape.outputs();
    for (std::size_t i = 0; i < n; ++i) x[(k + 1) * n + i] = sg * c[out[i] * K + k] / next;
    if (v) {
      // V_{k+1} = s·Σ_{j=0}^{k} J_j V_{k-j} / (k+1)
      std::vector<Interval>& V = *v;
      for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t l = 0; l < n; ++l) {
          Interval s2(0.0);
          for (std::size_t j = 0; j <= k; ++j) {
            for (std::size_t p = 0; p < n; ++p) {
              s2 += c[out[n + i * n + p] * K + j] * V[(k - j) * n * n + p * n + l];
            }
          }
          V[(k + 1) * n * n + i * n + l] = sg * s2 / next;
        }
      }
    }
  }
  for (const Interval& xi : x) {
    if (xi.is_empty()) return false;
  }
  return true;
}

}  // namespace sillage::detail
