// Batch forward evaluation: one walk of the tape, and for each instruction a
// tight loop over the boxes (structure of arrays: one row of `count`
// intervals per instruction, variables read in place from their columns).
#include <algorithm>
#include <vector>

#include "sillage/expr/batch_kernels.h"
#include "sillage/expr/op_eval.h"
#include "sillage/expr/tape.h"
#include "sillage/interval/trig_batch.h"

namespace sillage::detail {

namespace {

// flatten: the interval operations and their rounding kernels are inlined
// into the loop (no call per box).
template <class F>
[[gnu::flatten]] void unary_loop(Interval* r, const Interval* a, std::size_t count, F f) {
  for (std::size_t i = 0; i < count; ++i) r[i] = f(a[i]);
}

template <class F>
[[gnu::flatten]] void binary_loop(Interval* r, const Interval* a, const Interval* b, std::size_t count, F f) {
  for (std::size_t i = 0; i < count; ++i) r[i] = f(a[i], b[i]);
}

// Row k of the batch; + − × ÷ x² √ by the kernels of the rounding policy (Ops,
// batch_kernels.h), sin and cos by the vectorised rows of trig_batch.h.
template <class Ops>
void eval_row(const Instr& in, Interval* r, const Interval* a, const Interval* b, std::size_t cnt) {
  using I = const Interval&;
  switch (in.op) {
    case Op::Add: return binary_loop(r, a, b, cnt, [](I x, I y) { return Ops::add(x, y); });
    case Op::Sub: return binary_loop(r, a, b, cnt, [](I x, I y) { return Ops::sub(x, y); });
    case Op::Mul: return binary_loop(r, a, b, cnt, [](I x, I y) { return Ops::mul(x, y); });
    case Op::Div: return binary_loop(r, a, b, cnt, [](I x, I y) { return Ops::div(x, y); });
    case Op::Neg: return unary_loop(r, a, cnt, [](I x) { return -x; });
    case Op::Sqr: return unary_loop(r, a, cnt, [](I x) { return Ops::sqr(x); });
    case Op::PowInt:
      if (in.n == 2) return unary_loop(r, a, cnt, [](I x) { return Ops::sqr(x); });
      return unary_loop(r, a, cnt, [n = in.n](I x) { return pow_int(x, n); });
    case Op::Sqrt: return unary_loop(r, a, cnt, [](I x) { return Ops::sqrt(x); });
    case Op::Exp: return unary_loop(r, a, cnt, [](I x) { return exp(x); });
    case Op::Sin: return sin_rows(a, r, cnt);
    case Op::Cos: return cos_rows(a, r, cnt);
    default:  // the rarer operations share the generic switch
      if (op_arity(in.op) == 2) {
        for (std::size_t i = 0; i < cnt; ++i) r[i] = eval_op(in.op, a[i], b[i], in.n);
      } else {
        for (std::size_t i = 0; i < cnt; ++i) r[i] = eval_op(in.op, a[i], a[i], in.n);
      }
  }
}

// Tape::forward_batch with the interval operations Ops.
template <class Ops>
void forward_rows(const Tape& t, const Interval* const* xs, std::size_t count, Interval* rows, Interval* const* out) {
  thread_local std::vector<const Interval*> row;
  thread_local std::vector<Interval*> dest;  // where row k is written: an output column or the rows
  row.assign(t.code().size(), nullptr);
  dest.assign(t.code().size(), nullptr);
  for (std::size_t k = 0; k < t.nb_vars(); ++k) row[k] = xs[k];
  if (out) {  // an output computed by an instruction goes straight to its column (no copy)
    for (std::size_t o = 0; o < t.outputs().size(); ++o) {
      const std::uint32_t k = t.outputs()[o];
      if (k >= t.nb_vars() && !dest[k]) dest[k] = out[o];
    }
  }
  for (std::size_t k = t.nb_vars(); k < t.code().size(); ++k) {
    const Instr& in = t.code()[k];
    Interval* r = dest[k] ? dest[k] : rows + k * count;
    row[k] = r;
    if (in.op == Op::Const) {
      std::fill(r, r + count, in.value);
    } else {
      eval_row<Ops>(in, r, row[in.a], row[in.b], count);
    }
  }
  if (!out) return;
  for (std::size_t o = 0; o < t.outputs().size(); ++o)
    if (row[t.outputs()[o]] != out[o]) std::copy(row[t.outputs()[o]], row[t.outputs()[o]] + count, out[o]);
}

}  // namespace

void Tape::forward_batch(const Interval* const* xs, std::size_t count, Interval* rows,
                         Interval* const* out) const {
  with_rounded_ops([&](auto ops) { forward_rows<decltype(ops)>(*this, xs, count, rows, out); });
}

}  // namespace sillage::detail
