// Function: construction, natural and centered evaluation, HC4-revise.
#include "sillage/expr/function.h"

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <ostream>
#include <sstream>

#include "sillage/error.h"
#include "sillage/expr/diff.h"
#include "sillage/expr/parser.h"
#include "sillage/expr/function_impl.h"
#include "sillage/expr/hc4_rows.h"
#include "sillage/expr/tape.h"

namespace sillage {
namespace detail {

namespace {

std::shared_ptr<FunctionImpl> make_impl(std::vector<std::string> vars, std::vector<Expr> exprs) {
  if (exprs.empty()) throw DimensionError("Function: at least one output expression is needed");
  auto impl = std::make_shared<FunctionImpl>();
  for (const std::string& v : vars) {
    if (is_reserved_name(v)) throw Error("Function: \"" + v + "\" is a reserved name, not a variable name");
    impl->var_exprs.emplace_back(v);  // throws on an invalid name
  }
  for (std::size_t i = 0; i < vars.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (vars[i] == vars[j]) throw Error("Function: variable \"" + vars[i] + "\" declared twice");
  impl->vars = std::move(vars);
  impl->exprs = std::move(exprs);
  impl->tape = Tape(impl->exprs, impl->vars);
  return impl;
}

std::vector<std::string> names_of(const std::vector<ExprVar>& vars) {
  std::vector<std::string> names;
  for (const ExprVar& v : vars) names.push_back(v.name());
  return names;
}

// Per-thread scratch for one box: no shared mutable state between threads.
std::vector<Interval>& scratch(std::size_t n) {
  thread_local std::vector<Interval> buf;
  if (buf.size() < n) buf.resize(n);
  return buf;
}

}  // namespace
}  // namespace detail

using detail::FunctionImpl;

Function::Function(const std::vector<std::string>& vars, const std::string& expr)
    : impl_(detail::make_impl(vars, detail::parse_exprs(vars, expr))) {}

Function::Function(const std::vector<ExprVar>& vars, const Expr& expr)
    : impl_(detail::make_impl(detail::names_of(vars), {expr})) {}

Function::Function(const std::vector<ExprVar>& vars, const std::vector<Expr>& exprs)
    : impl_(detail::make_impl(detail::names_of(vars), exprs)) {}

std::size_t Function::nb_vars() const { return impl_->vars.size(); }
std::size_t Function::image_dim() const { return impl_->exprs.size(); }
const std::vector<std::string>& Function::var_names() const { return impl_->vars; }
const std::vector<Expr>& Function::exprs() const { return impl_->exprs; }
std::size_t Function::tape_size() const { return impl_->tape.size() - impl_->tape.nb_vars(); }

Function Function::operator[](std::size_t i) const {
  if (i >= image_dim())
    throw DimensionError("Function::operator[]: component " + std::to_string(i) + " of a function of dimension " +
                         std::to_string(image_dim()));
  return Function(impl_->var_exprs, impl_->exprs[i]);
}

static void check_box(const Function& f, const IntervalVector& x, const char* where) {
  if (x.size() != f.nb_vars())
    throw DimensionError(std::string(where) + ": expected a box of size " + std::to_string(f.nb_vars()) + ", got " +
                         std::to_string(x.size()));
}

IntervalVector Function::eval_vector(const IntervalVector& x) const {
  check_box(*this, x, "Function::eval_vector");
  const detail::Tape& t = impl_->tape;
  std::vector<Interval>& v = detail::scratch(t.size());
  t.forward(x.components().data(), v.data());
  IntervalVector y(t.outputs().size());
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = v[t.outputs()[i]];
  return y;
}

Interval Function::eval(const IntervalVector& x) const {
  if (image_dim() != 1)
    throw DimensionError("Function::eval: the function has dimension " + std::to_string(image_dim()) +
                         "; use eval_vector");
  check_box(*this, x, "Function::eval");
  const detail::Tape& t = impl_->tape;
  std::vector<Interval>& v = detail::scratch(t.size());
  t.forward(x.components().data(), v.data());
  return v[t.outputs()[0]];
}

bool Function::hc4_revise(IntervalVector& x, const IntervalVector& y) const {
  check_box(*this, x, "Function::hc4_revise");
  if (y.size() != image_dim())
    throw DimensionError("Function::hc4_revise: expected an image of size " + std::to_string(image_dim()) +
                         ", got " + std::to_string(y.size()));
  const detail::Tape& t = impl_->tape;
  std::vector<Interval>& v = detail::scratch(t.size());
  bool ok = !x.is_empty() && !y.is_empty();
  if (ok) {
    t.forward(x.components().data(), v.data());
    ok = t.backward(v.data(), y.components().data());
  }
  if (!ok) {
    x.set_empty();
    return false;
  }
  for (std::size_t i = 0; i < x.size(); ++i) x[i] &= v[i];
  return true;
}

void Function::hc4_revise_batch(std::span<Interval* const> xs, std::size_t count, const IntervalVector& y) const {
  if (xs.size() != nb_vars())
    throw DimensionError("Function::hc4_revise_batch: expected " + std::to_string(nb_vars()) +
                         " variable columns, got " + std::to_string(xs.size()));
  if (y.size() != image_dim())
    throw DimensionError("Function::hc4_revise_batch: expected an image of size " + std::to_string(image_dim()) +
                         ", got " + std::to_string(y.size()));
  const detail::Hc4Rows hc(*this);
  const std::size_t n = nb_vars();
  std::uint8_t ok[detail::Hc4Rows::kMaxBoxes];
  for (std::size_t start = 0; start < count; start += detail::Hc4Rows::kMaxBoxes) {
    const std::size_t cnt = std::min(detail::Hc4Rows::kMaxBoxes, count - start);
    for (std::size_t i = 0; i < n; ++i) std::copy(xs[i] + start, xs[i] + start + cnt, hc.var_row(i, cnt));
    hc.contract(cnt, y, ok);
    for (std::size_t i = 0; i < n; ++i) {
      const Interval* const r = hc.var_row(i, cnt);
      for (std::size_t j = 0; j < cnt; ++j) xs[i][start + j] = ok[j] ? xs[i][start + j] & r[j] : Interval::empty();
    }
  }
}

bool Function::hc4_revise(IntervalVector& x, const Interval& y) const {
  if (image_dim() != 1)
    throw DimensionError("Function::hc4_revise: a scalar image for a function of dimension " +
                         std::to_string(image_dim()));
  return hc4_revise(x, IntervalVector{y});
}

Function Function::diff() const {
  std::call_once(impl_->diff_once, [this] {
    impl_->diff = detail::make_impl(impl_->vars, detail::jacobian_exprs(impl_->exprs, impl_->var_exprs));
  });
  return Function(impl_->diff);
}

IntervalVector Function::jacobian_vector(const IntervalVector& x) const {
  check_box(*this, x, "Function::jacobian_vector");
  return diff().eval_vector(x);
}

IntervalVector Function::centered_eval(const IntervalVector& x) const {
  check_box(*this, x, "Function::centered_eval");
  const detail::Tape& t = impl_->tape;
  const std::size_t m = image_dim(), n = nb_vars();
  IntervalVector natural(m);
  bool smooth = false;
  {
    std::vector<Interval>& v = detail::scratch(t.size());
    smooth = !x.is_empty() && t.forward_in_domain(x.components().data(), v.data());
    for (std::size_t i = 0; i < m; ++i) natural[i] = v[t.outputs()[i]];
  }
  if (!smooth || x.is_unbounded() || n == 0) return natural;
  // Mean-value theorem along the segment from the midpoint: the box is in
  // the domain of every operation, where f is continuous and Lipschitz.
  const Vector mid = x.mid();
  const IntervalVector c = IntervalVector::from_point(mid);
  const IntervalVector fc = eval_vector(c);
  const IntervalVector jac = jacobian_vector(x);
  IntervalVector result(m);
  for (std::size_t i = 0; i < m; ++i) {
    Interval s = fc[i];
    bool usable = !s.is_empty();
    for (std::size_t j = 0; j < n && usable; ++j) {
      if (x[j].is_degenerate()) continue;  // x_j - c_j = 0: the segment keeps x_j fixed
      const Interval& d = jac[i * n + j];
      // Empty: f is defined but its derivative formula is not (sqrt at 0);
      // unbounded: the form brings nothing. The natural form stays valid.
      usable = !d.is_empty() && d.is_bounded();
      s += d * (x[j] - c[j]);
    }
    result[i] = usable ? s & natural[i] : natural[i];
  }
  return result;
}

std::vector<IntervalVector> Function::eval_batch(const std::vector<IntervalVector>& xs) const {
  const std::size_t n = nb_vars(), m = image_dim(), count = xs.size();
  for (const IntervalVector& x : xs) check_box(*this, x, "Function::eval_batch");
  std::vector<IntervalVector> ys(count, IntervalVector(m));
  constexpr std::size_t kChunk = 256;  // rows stay in cache
  std::vector<Interval> in(n * kChunk), out(m * kChunk);
  std::vector<const Interval*> in_cols(n);
  std::vector<Interval*> out_cols(m);
  for (std::size_t start = 0; start < count; start += kChunk) {
    const std::size_t c = std::min(kChunk, count - start);
    for (std::size_t j = 0; j < n; ++j) {
      for (std::size_t k = 0; k < c; ++k) in[j * c + k] = xs[start + k][j];
      in_cols[j] = in.data() + j * c;
    }
    for (std::size_t i = 0; i < m; ++i) out_cols[i] = out.data() + i * c;
    eval_batch(in_cols, c, out_cols);
    for (std::size_t k = 0; k < c; ++k)
      for (std::size_t i = 0; i < m; ++i) ys[start + k][i] = out[i * c + k];
  }
  return ys;
}

void Function::eval_batch(std::span<const Interval* const> xs, std::size_t count,
                          std::span<Interval* const> out) const {
  if (xs.size() != nb_vars())
    throw DimensionError("Function::eval_batch: expected " + std::to_string(nb_vars()) + " input columns, got " +
                         std::to_string(xs.size()));
  if (out.size() != image_dim())
    throw DimensionError("Function::eval_batch: expected " + std::to_string(image_dim()) +
                         " output columns, got " + std::to_string(out.size()));
  if (count == 0) return;
  const detail::Tape& t = impl_->tape;
  thread_local std::vector<Interval> rows;
  constexpr std::size_t kChunk = 256;
  const std::size_t c = std::min(kChunk, count);
  if (rows.size() < t.size() * c) rows.resize(t.size() * c);
  std::vector<const Interval*> x(xs.size());
  std::vector<Interval*> y(out.size());
  for (std::size_t start = 0; start < count; start += kChunk) {
    const std::size_t cnt = std::min(kChunk, count - start);
    for (std::size_t j = 0; j < x.size(); ++j) x[j] = xs[j] + start;
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = out[i] + start;
    t.forward_batch(x.data(), cnt, rows.data(), y.data());
  }
}

std::string Function::expr_str() const {
  std::ostringstream os;
  print_exprs(os, impl_->exprs, image_dim() != 1, impl_->vars);  // one set of let-bindings for all outputs
  return os.str();
}

std::string Function::str() const {
  std::ostringstream os;
  os << '(';
  for (std::size_t i = 0; i < nb_vars(); ++i) os << (i ? ", " : "") << impl_->vars[i];
  os << ") -> " << expr_str();
  return os.str();
}

std::ostream& operator<<(std::ostream& os, const Function& f) { return os << f.str(); }

}  // namespace sillage
