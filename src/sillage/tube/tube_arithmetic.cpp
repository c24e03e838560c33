#include "sillage/tube/tube_arithmetic.h"

#include <string>

#include "sillage/error.h"
#include "sillage/expr/batch_kernels.h"
#include "sillage/interval/trig_batch.h"
#include "sillage/tube/chunks.h"

namespace sillage {

namespace {

// run(y, begin, end) over the pieces [begin, end) of x's slices and of its
// gates (y their array), by chunks (tube/chunks.h): on several threads from
// parallel_from elements on. Each element computed from itself alone: the
// same bits for any number of threads.
template <class Run>
void each_chunk(Tube& x, std::size_t parallel_from, const Run& run) {
  Tube::Writer w = x.write();
  for (const std::span<Interval> v : {w.slices(), w.gates()}) {
    Interval* y = v.data();
    detail::for_chunks(v.size(), [&](std::size_t b, std::size_t e) { run(y, b, e); }, parallel_from);
  }
}

// x := f(x) slice- and gate-wise.
template <class F>
Tube& unary_inplace(Tube& x, F f, std::size_t parallel_from = detail::kParallelCopyFrom) {
  each_chunk(x, parallel_from, [&](Interval* y, std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) y[i] = f(y[i]);
  });
  return x;
}

template <class F>
Tube unary(const Tube& x, F f, std::size_t parallel_from = detail::kParallelCopyFrom) {
  Tube z(x);
  unary_inplace(z, f, parallel_from);
  return z;
}

// f over the slices and the gates as rows (interval/trig_batch.h: in place,
// end point values by a vectorised kernel).
Tube unary_rows(const Tube& x, void (*f)(const Interval*, Interval*, std::size_t)) {
  Tube z(x);
  each_chunk(z, detail::kParallelFrom, [&](Interval* y, std::size_t b, std::size_t e) { f(y + b, y + b, e - b); });
  return z;
}

// x := f(x, y) slice- and gate-wise, same TDomain.
template <class F>
[[gnu::flatten]] void binary_inplace(Tube& x, const Tube& y, F f, const char* where) {
  if (x.tdomain() != y.tdomain()) {
    throw DimensionError(std::string(where) + ": the two tubes are not on the same TDomain");
  }
  Tube::Writer w = x.write();
  const std::span<Interval> s = w.slices(), g = w.gates();
  const TubeData& e = y.data();
  for (std::size_t k = 0; k < s.size(); ++k) s[k] = f(s[k], e.slices[k]);
  for (std::size_t k = 0; k < g.size(); ++k) g[k] = f(g[k], e.gates[k]);
}

// binary_inplace with the operation `op` of the rounding policy in use
// (batch_kernels.h: the results of interval.h, the rounding inlined).
template <class Op>
void rounded_inplace(Tube& x, const Tube& y, Op op, const char* where) {
  detail::with_rounded_ops([&](auto ops) {
    binary_inplace(x, y, [&](const Interval& a, const Interval& b) { return op(ops, a, b); }, where);
  });
}

template <class F>
Tube binary(const Tube& x, const Tube& y, F f, const char* where) {
  if (x.tdomain() != y.tdomain()) {
    throw DimensionError(std::string(where) + ": the two tubes are not on the same TDomain");
  }
  Tube z(x);
  binary_inplace(z, y, f, where);
  return z;
}

const auto kAdd = [](auto ops, const Interval& a, const Interval& b) { return ops.add(a, b); };
const auto kSub = [](auto ops, const Interval& a, const Interval& b) { return ops.sub(a, b); };
const auto kMul = [](auto ops, const Interval& a, const Interval& b) { return ops.mul(a, b); };
const auto kDiv = [](const Interval& a, const Interval& b) { return a / b; };

template <class Op>
Tube rounded(const Tube& x, const Tube& y, Op op, const char* where) {
  Tube z(x);  // rounded_inplace checks the TDomains
  rounded_inplace(z, y, op, where);
  return z;
}

}  // namespace

Tube& Tube::operator+=(const Tube& y) { rounded_inplace(*this, y, kAdd, "Tube::operator+="); return *this; }
Tube& Tube::operator-=(const Tube& y) { rounded_inplace(*this, y, kSub, "Tube::operator-="); return *this; }
Tube& Tube::operator*=(const Tube& y) { rounded_inplace(*this, y, kMul, "Tube::operator*="); return *this; }
Tube& Tube::operator/=(const Tube& y) { binary_inplace(*this, y, kDiv, "Tube::operator/="); return *this; }

Tube& Tube::operator+=(const Interval& y) { return unary_inplace(*this, [&](const Interval& a) { return a + y; }); }
Tube& Tube::operator-=(const Interval& y) { return unary_inplace(*this, [&](const Interval& a) { return a - y; }); }
Tube& Tube::operator*=(const Interval& y) { return unary_inplace(*this, [&](const Interval& a) { return a * y; }); }
Tube& Tube::operator/=(const Interval& y) { return unary_inplace(*this, [&](const Interval& a) { return a / y; }); }

Tube operator-(const Tube& x) { return unary(x, [](const Interval& a) { return -a; }); }

Tube operator+(const Tube& x, const Tube& y) { return rounded(x, y, kAdd, "operator+(Tube, Tube)"); }
Tube operator-(const Tube& x, const Tube& y) { return rounded(x, y, kSub, "operator-(Tube, Tube)"); }
Tube operator*(const Tube& x, const Tube& y) { return rounded(x, y, kMul, "operator*(Tube, Tube)"); }
Tube operator/(const Tube& x, const Tube& y) { return binary(x, y, kDiv, "operator/(Tube, Tube)"); }

Tube operator+(const Tube& x, const Interval& y) { return unary(x, [&](const Interval& a) { return a + y; }); }
Tube operator-(const Tube& x, const Interval& y) { return unary(x, [&](const Interval& a) { return a - y; }); }
Tube operator*(const Tube& x, const Interval& y) { return unary(x, [&](const Interval& a) { return a * y; }); }
Tube operator/(const Tube& x, const Interval& y) { return unary(x, [&](const Interval& a) { return a / y; }); }

Tube operator+(const Interval& x, const Tube& y) { return unary(y, [&](const Interval& b) { return x + b; }); }
Tube operator-(const Interval& x, const Tube& y) { return unary(y, [&](const Interval& b) { return x - b; }); }
Tube operator*(const Interval& x, const Tube& y) { return unary(y, [&](const Interval& b) { return x * b; }); }
Tube operator/(const Interval& x, const Tube& y) { return unary(y, [&](const Interval& b) { return x / b; }); }

Tube operator&(const Tube& x, const Tube& y) { Tube z(x); z &= y; return z; }
Tube operator|(const Tube& x, const Tube& y) { Tube z(x); z |= y; return z; }

#define SILLAGE_TUBE_UNARY(name) \
  Tube name(const Tube& x) { return unary(x, [](const Interval& a) { return name(a); }, detail::kParallelFrom); }
SILLAGE_TUBE_UNARY(sqr)
SILLAGE_TUBE_UNARY(sqrt)
SILLAGE_TUBE_UNARY(abs)
SILLAGE_TUBE_UNARY(sign)
SILLAGE_TUBE_UNARY(exp)
SILLAGE_TUBE_UNARY(log)
SILLAGE_TUBE_UNARY(tan)
SILLAGE_TUBE_UNARY(asin)
SILLAGE_TUBE_UNARY(acos)
SILLAGE_TUBE_UNARY(atan)
SILLAGE_TUBE_UNARY(sinh)
SILLAGE_TUBE_UNARY(cosh)
SILLAGE_TUBE_UNARY(tanh)
#undef SILLAGE_TUBE_UNARY
Tube sin(const Tube& x) { return unary_rows(x, detail::sin_rows); }
Tube cos(const Tube& x) { return unary_rows(x, detail::cos_rows); }

Tube pow(const Tube& x, int n) { return unary(x, [n](const Interval& a) { return pow(a, n); }); }
Tube pow(const Tube& x, double p) { return unary(x, [p](const Interval& a) { return pow(a, p); }); }
Tube pow(const Tube& x, const Interval& p) { return unary(x, [&p](const Interval& a) { return pow(a, p); }); }
Tube pow(const Tube& x, const Tube& p) {
  return binary(x, p, [](const Interval& a, const Interval& b) { return pow(a, b); }, "pow(Tube, Tube)");
}
Tube root(const Tube& x, int n) { return unary(x, [n](const Interval& a) { return root(a, n); }); }

Tube atan2(const Tube& y, const Tube& x) {
  return binary(y, x, [](const Interval& a, const Interval& b) { return atan2(a, b); }, "atan2(Tube, Tube)");
}
Tube atan2(const Tube& y, const Interval& x) {
  return unary(y, [&x](const Interval& a) { return atan2(a, x); });
}
Tube atan2(const Interval& y, const Tube& x) {
  return unary(x, [&y](const Interval& b) { return atan2(y, b); });
}
Tube min(const Tube& x, const Tube& y) {
  return binary(x, y, [](const Interval& a, const Interval& b) { return min(a, b); }, "min(Tube, Tube)");
}
Tube max(const Tube& x, const Tube& y) {
  return binary(x, y, [](const Interval& a, const Interval& b) { return max(a, b); }, "max(Tube, Tube)");
}

}  // namespace sillage
