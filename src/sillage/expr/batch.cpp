// Batch forward evaluation: one walk of the tape, and for each instruction a
// tight loop over the boxes (structure of arrays: one row of `count`
// intervals per instruction, variables read in place from their columns).
#include <algorithm>
#include <vector>

#include "sillage/expr/batch_kernels.h"
#include "sillage/expr/op_eval.h"
#include "sillage/expr/tape.h"
#include "sillage/interval/arith_rows.h"
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

// + − × ÷: their rows read a constant operand once (ca, cb: the constant
// instruction of operand a or b, or null), not from a filled row.
bool reads_constant_once(Op op) { return op == Op::Add || op == Op::Sub || op == Op::Mul || op == Op::Div; }

// The row of + − × ÷ x² √ by the AVX2 rows (the same bits as either path)
// where the CPU has AVX2 and the row is not short; false where it does not
// apply. On the AVX-512 path too: four lanes of error-free transformations
// cost less per interval than the scalar kernels with embedded rounding
// (BM_EvalBatchColumns 0.69 -> 0.48 ms). Not in the HC4's backward rows,
// where they did not gain (hc4.cpp).
template <class Ops>
bool avx2_row(const Instr& in, const Instr* ca, const Instr* cb, Interval* r, const Interval* a, const Interval* b,
              std::size_t cnt) {
  if (!avx2_rows_for(cnt)) return false;
  RowOp op{};
  switch (in.op) {
    case Op::Add: op = RowOp::Add; break;
    case Op::Sub: op = RowOp::Sub; break;
    case Op::Mul: op = RowOp::Mul; break;
    case Op::Div: op = RowOp::Div; break;
    case Op::Sqr: op = RowOp::Sqr; break;
    case Op::PowInt:
      if (in.n != 2) return false;
      op = RowOp::Sqr;
      break;
    case Op::Sqrt: op = RowOp::Sqrt; break;
    default: return false;
  }
  if (op_arity(in.op) != 2) b = a;
  arith_rows_avx2(op, r, ca ? RowArg{&ca->value, true} : RowArg{a}, cb ? RowArg{&cb->value, true} : RowArg{b}, cnt);
  return true;
}

// Row k of the batch; + − × ÷ x² √ by the kernels of the rounding policy (Ops,
// batch_kernels.h), sin and cos by the vectorised rows of trig_batch.h.
template <class Ops>
void eval_row(const Instr& in, const Instr* ca, const Instr* cb, Interval* r, const Interval* a, const Interval* b,
              std::size_t cnt) {
  if (avx2_row<Ops>(in, ca, cb, r, a, b, cnt)) return;
  using I = const Interval&;
  const auto arith = [&](auto f) {
    if (cb) return unary_loop(r, a, cnt, [c = cb->value, f](I x) { return f(x, c); });
    if (ca) return unary_loop(r, b, cnt, [c = ca->value, f](I y) { return f(c, y); });
    binary_loop(r, a, b, cnt, f);
  };
  switch (in.op) {
    case Op::Add: return arith([](I x, I y) { return Ops::add(x, y); });
    case Op::Sub: return arith([](I x, I y) { return Ops::sub(x, y); });
    case Op::Mul: return arith([](I x, I y) { return Ops::mul(x, y); });
    case Op::Div: return arith([](I x, I y) { return Ops::div(x, y); });
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
  const std::vector<Instr>& code = t.code();
  thread_local std::vector<const Interval*> row;
  thread_local std::vector<Interval*> dest;  // where row k is written: an output column or the rows
  thread_local std::vector<std::uint8_t> filled;  // constant k needs its row filled
  row.assign(code.size(), nullptr);
  dest.assign(code.size(), nullptr);
  // The HC4 (out null) reads and contracts every row afterwards; an
  // evaluation needs a constant's row only where an operation reads it.
  filled.assign(code.size(), out ? 0 : 1);
  const auto is_const = [&](std::uint32_t k) { return code[k].op == Op::Const; };
  for (std::size_t k = t.nb_vars(); k < code.size(); ++k) {
    const Instr& in = code[k];
    if (in.op == Op::Const) continue;
    const bool once = reads_constant_once(in.op);
    if (!once || (is_const(in.a) && is_const(in.b))) filled[in.a] = 1;
    if (op_arity(in.op) == 2 && !(once && is_const(in.b))) filled[in.b] = 1;
  }
  for (std::size_t k = 0; k < t.nb_vars(); ++k) row[k] = xs[k];
  if (out) {  // an output computed by an instruction goes straight to its column (no copy)
    for (std::size_t o = 0; o < t.outputs().size(); ++o) {
      const std::uint32_t k = t.outputs()[o];
      filled[k] = 1;
      if (k >= t.nb_vars() && !dest[k]) dest[k] = out[o];
    }
  }
  for (std::size_t k = t.nb_vars(); k < code.size(); ++k) {
    const Instr& in = code[k];
    Interval* r = dest[k] ? dest[k] : rows + k * count;
    row[k] = r;
    if (in.op == Op::Const) {
      if (filled[k]) std::fill(r, r + count, in.value);
    } else {
      const bool once = reads_constant_once(in.op);
      const Instr* cb = once && is_const(in.b) ? &code[in.b] : nullptr;
      const Instr* ca = once && !cb && is_const(in.a) ? &code[in.a] : nullptr;
      eval_row<Ops>(in, ca, cb, r, row[in.a], row[in.b], count);
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
