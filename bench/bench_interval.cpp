// Time per interval operation, sillage side by side with Boost.Interval (its
// rigorous policy: the rounding mode is switched and restored around every
// operation, transcendental functions from libm under directed rounding) and
// MPFI (MPFR-based, 53-bit precision). Same pre-generated random inputs for
// the three; every result goes through benchmark::DoNotOptimize.
// Run: bench_interval --benchmark_counters_tabular=true ; the per_op column is
// the time of one operation.
//
// Two operand sets. "Predictable" (BM_<op>_<library>): 1024 pairs of plain
// random intervals replayed in a cycle, so the branch predictor learns every
// data-dependent branch; the figure most libraries publish. "Unpredictable"
// (BM_<op>_sillage_mix): 2^20 distinct pairs drawn from a mix of signs,
// magnitudes, zero-straddling, unbounded and empty intervals, the shape of
// real contractor work; no branch on the data can be learnt. The pairs come
// from two pools of 4096 intervals (cache resident, as operands are in a
// contractor sweep), the k-th pair being x[k mod 4096] with
// y[(k + 1237 floor(k / 4096)) mod 4096]: 256 different partners per x.
// SILLAGE_ROUNDING=portable in the environment measures the portable path.
// BM_<op>_kernel_mix: the same mix through the internal kernels inlined into
// the loop, as the library's own hot loops may call them; the difference with
// BM_<op>_sillage_mix is the cost of calling the out-of-line operator.
// BM_<op>_rows_mix: the same pairs through the AVX2 rows of the batch
// evaluator (interval/arith_rows.h; portable path's bits), rows of 4096.
#include <benchmark/benchmark.h>

#include <boost/numeric/interval.hpp>
#include <cstdint>
#include <random>
#include <vector>

#include "sillage/interval/arith_kernels.h"
#include "sillage/interval/arith_rows.h"
#include "sillage/interval/elementary.h"
#include "sillage/interval/interval.h"

#ifdef SILLAGE_BENCH_MPFI
#include <mpfi.h>
#endif

namespace {

using sillage::Interval;
namespace bi = boost::numeric::interval_lib;
using BoostInterval =
    boost::numeric::interval<double, bi::policies<bi::save_state<bi::rounded_transc_std<double>>,
                                                  bi::checking_base<double>>>;

constexpr std::size_t kN = 1024;

struct Bounds {
  std::vector<double> lo, hi;
};

// kN random intervals with lower bounds in [a, b) and widths in [0, w).
Bounds bounds(double a, double b, double w, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> pos(a, b), width(0, w);
  Bounds r;
  for (std::size_t i = 0; i < kN; ++i) {
    const double lo = pos(rng);
    r.lo.push_back(lo);
    r.hi.push_back(lo + width(rng));
  }
  return r;
}

// Operand sets: x for every operation, y the second operand (kept away from 0
// for the division), p positive (sqrt, log), s small arguments for exp and sin.
const Bounds& xs() { static const Bounds b = bounds(-10, 10, 1, 1); return b; }
const Bounds& ys() { static const Bounds b = bounds(0.5, 10, 1, 2); return b; }
const Bounds& ps() { static const Bounds b = bounds(0.01, 100, 1, 3); return b; }
const Bounds& ss() { static const Bounds b = bounds(-10, 10, 0.1, 4); return b; }

// n operations per iteration.
void report(benchmark::State& state, std::size_t n = kN) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
  state.counters["per_op"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate |
                                                      benchmark::Counter::kInvert);
}

// ---- sillage and Boost: value types, one template ----

template <class I>
std::vector<I> make(const Bounds& b) {
  std::vector<I> v;
  for (std::size_t i = 0; i < kN; ++i) v.push_back(I(b.lo[i], b.hi[i]));
  return v;
}

template <class I, class F>
void unary(benchmark::State& state, const Bounds& bx, F f) {
  const std::vector<I> x = make<I>(bx);
  for (auto _ : state)
    for (std::size_t i = 0; i < kN; ++i) benchmark::DoNotOptimize(f(x[i]));
  report(state);
}

template <class I, class F>
void binary(benchmark::State& state, const Bounds& bx, const Bounds& by, F f) {
  const std::vector<I> x = make<I>(bx), y = make<I>(by);
  for (auto _ : state)
    for (std::size_t i = 0; i < kN; ++i) benchmark::DoNotOptimize(f(x[i], y[i]));
  report(state);
}

#define SILLAGE_BENCH_BOTH(name, call)                                                                \
  void BM_##name##_sillage(benchmark::State& s) { call(Interval, sillage::); }                        \
  void BM_##name##_boost(benchmark::State& s) { call(BoostInterval, boost::numeric::); }              \
  BENCHMARK(BM_##name##_sillage);                                                                     \
  BENCHMARK(BM_##name##_boost);

#define ADD(I, ns) binary<I>(s, xs(), ys(), [](const I& a, const I& b) { return a + b; })
#define MUL(I, ns) binary<I>(s, xs(), ys(), [](const I& a, const I& b) { return a * b; })
#define DIV(I, ns) binary<I>(s, xs(), ys(), [](const I& a, const I& b) { return a / b; })
#define SQRT(I, ns) unary<I>(s, ps(), [](const I& a) { return ns sqrt(a); })
#define EXP(I, ns) unary<I>(s, ss(), [](const I& a) { return ns exp(a); })
#define LOG(I, ns) unary<I>(s, ps(), [](const I& a) { return ns log(a); })
#define SIN(I, ns) unary<I>(s, ss(), [](const I& a) { return ns sin(a); })

SILLAGE_BENCH_BOTH(add, ADD)
SILLAGE_BENCH_BOTH(mul, MUL)
SILLAGE_BENCH_BOTH(div, DIV)
SILLAGE_BENCH_BOTH(sqrt, SQRT)
SILLAGE_BENCH_BOTH(exp, EXP)
SILLAGE_BENCH_BOTH(log, LOG)
SILLAGE_BENCH_BOTH(sin, SIN)

// ---- the unpredictable mix (sillage only) ----

constexpr std::size_t kPool = 4096;
constexpr std::size_t kPairs = std::size_t{1} << 20;

// One interval of the mix: 2 % empty, 3 % unbounded, 3 % degenerate, 2 % with
// a zero bound, the rest [v, v + w] with v and w over 40 binades, v of either
// sign (a third of them straddle 0).
Interval mixed(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> kind(0, 99);
  std::uniform_real_distribution<double> binade(-20, 20), unit(0, 1);
  auto magnitude = [&] { return std::exp2(binade(rng)); };
  auto signed_magnitude = [&] { return unit(rng) < 0.5 ? -magnitude() : magnitude(); };
  const int k = kind(rng);
  const double inf = sillage::rounding::kInf;
  if (k < 2) return Interval::empty();
  if (k < 3) return Interval::all_reals();
  if (k < 4) return {-inf, signed_magnitude()};
  if (k < 5) return {signed_magnitude(), inf};
  if (k < 8) return Interval(signed_magnitude());
  if (k < 9) return {0.0, magnitude()};
  if (k < 10) return {-magnitude(), 0.0};
  const double v = signed_magnitude();
  return {v, sillage::rounding::add_up(v, magnitude())};
}

std::vector<Interval> pool(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Interval> v;
  for (std::size_t i = 0; i < kPool; ++i) v.push_back(mixed(rng));
  return v;
}

const std::vector<Interval>& mix_x() { static const auto v = pool(11); return v; }
const std::vector<Interval>& mix_y() { static const auto v = pool(12); return v; }

template <class F>
void binary_mix(benchmark::State& state, F f) {
  const Interval* x = mix_x().data();
  const Interval* y = mix_y().data();
  for (auto _ : state)
    for (std::size_t k = 0; k < kPairs; ++k)
      benchmark::DoNotOptimize(f(x[k % kPool], y[(k + 1237 * (k / kPool)) % kPool]));
  report(state, kPairs);
}

template <class F>
void unary_mix(benchmark::State& state, F f) {
  const Interval* x = mix_x().data();
  for (auto _ : state)
    for (std::size_t k = 0; k < kPairs; ++k) benchmark::DoNotOptimize(f(x[k % kPool]));
  report(state, kPairs);
}

void BM_add_sillage_mix(benchmark::State& s) { binary_mix(s, [](const Interval& a, const Interval& b) { return a + b; }); }
void BM_sub_sillage_mix(benchmark::State& s) { binary_mix(s, [](const Interval& a, const Interval& b) { return a - b; }); }
void BM_mul_sillage_mix(benchmark::State& s) { binary_mix(s, [](const Interval& a, const Interval& b) { return a * b; }); }
void BM_div_sillage_mix(benchmark::State& s) { binary_mix(s, [](const Interval& a, const Interval& b) { return a / b; }); }
void BM_sqr_sillage_mix(benchmark::State& s) { unary_mix(s, [](const Interval& a) { return sillage::sqr(a); }); }
void BM_sqrt_sillage_mix(benchmark::State& s) { unary_mix(s, [](const Interval& a) { return sillage::sqrt(a); }); }
BENCHMARK(BM_add_sillage_mix);
BENCHMARK(BM_sub_sillage_mix);
BENCHMARK(BM_mul_sillage_mix);
BENCHMARK(BM_div_sillage_mix);
BENCHMARK(BM_sqr_sillage_mix);
BENCHMARK(BM_sqrt_sillage_mix);

#define SILLAGE_BENCH_KERNEL(op, kernel)                                                             \
  void BM_##op##_kernel_mix(benchmark::State& s) {                                                   \
    binary_mix(s, [](const Interval& a, const Interval& b) {                                         \
      const auto r = sillage::detail::with_rounding(                                                 \
          [&]<class R>(R) { return sillage::detail::kernel<R>(a.lb(), a.ub(), b.lb(), b.ub()); });   \
      return Interval::from_bounds_unchecked(r.lo, r.hi);                                            \
    });                                                                                              \
  }                                                                                                  \
  BENCHMARK(BM_##op##_kernel_mix);

SILLAGE_BENCH_KERNEL(add, add_bounds)
SILLAGE_BENCH_KERNEL(sub, sub_bounds)
SILLAGE_BENCH_KERNEL(mul, mul_bounds)
SILLAGE_BENCH_KERNEL(div, div_bounds)

// The pairs of binary_mix by rows of kPool: block b pairs x with y rotated by
// 1237 b, a contiguous window of y written twice.
void rows_mix(benchmark::State& state, sillage::detail::RowOp op) {
  using namespace sillage::detail;
  if (!avx2_rows()) {
    state.SkipWithError("no AVX2 on this CPU");
    return;
  }
  const std::vector<Interval>& x = mix_x();
  std::vector<Interval> yy = mix_y(), out(kPool);
  yy.insert(yy.end(), mix_y().begin(), mix_y().end());
  for (auto _ : state) {
    for (std::size_t b = 0; b < kPairs / kPool; ++b) {
      arith_rows_avx2(op, out.data(), RowArg{x.data()}, RowArg{yy.data() + (1237 * b) % kPool}, kPool);
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
  }
  report(state, kPairs);
}

void BM_add_rows_mix(benchmark::State& s) { rows_mix(s, sillage::detail::RowOp::Add); }
void BM_sub_rows_mix(benchmark::State& s) { rows_mix(s, sillage::detail::RowOp::Sub); }
void BM_mul_rows_mix(benchmark::State& s) { rows_mix(s, sillage::detail::RowOp::Mul); }
void BM_div_rows_mix(benchmark::State& s) { rows_mix(s, sillage::detail::RowOp::Div); }
void BM_sqr_rows_mix(benchmark::State& s) { rows_mix(s, sillage::detail::RowOp::Sqr); }
void BM_sqrt_rows_mix(benchmark::State& s) { rows_mix(s, sillage::detail::RowOp::Sqrt); }
BENCHMARK(BM_add_rows_mix);
BENCHMARK(BM_sub_rows_mix);
BENCHMARK(BM_mul_rows_mix);
BENCHMARK(BM_div_rows_mix);
BENCHMARK(BM_sqr_rows_mix);
BENCHMARK(BM_sqrt_rows_mix);

#ifdef SILLAGE_BENCH_MPFI
// ---- MPFI: C structs, results into one preallocated interval ----

struct MpfiArray {
  explicit MpfiArray(const Bounds& b) : v(kN) {
    for (std::size_t i = 0; i < kN; ++i) {
      mpfi_init2(&v[i], 53);
      mpfi_interv_d(&v[i], b.lo[i], b.hi[i]);
    }
  }
  ~MpfiArray() {
    for (auto& x : v) mpfi_clear(&x);
  }
  MpfiArray(const MpfiArray&) = delete;
  MpfiArray& operator=(const MpfiArray&) = delete;
  std::vector<__mpfi_struct> v;
};

template <class F>
void mpfi_run(benchmark::State& state, const Bounds& bx, const Bounds& by, F f) {
  MpfiArray x(bx), y(by);
  mpfi_t r;
  mpfi_init2(r, 53);
  for (auto _ : state)
    for (std::size_t i = 0; i < kN; ++i) {
      f(r, &x.v[i], &y.v[i]);
      benchmark::DoNotOptimize(r);
    }
  mpfi_clear(r);
  report(state);
}

void BM_add_mpfi(benchmark::State& s) { mpfi_run(s, xs(), ys(), [](mpfi_ptr r, mpfi_srcptr a, mpfi_srcptr b) { mpfi_add(r, a, b); }); }
void BM_mul_mpfi(benchmark::State& s) { mpfi_run(s, xs(), ys(), [](mpfi_ptr r, mpfi_srcptr a, mpfi_srcptr b) { mpfi_mul(r, a, b); }); }
void BM_div_mpfi(benchmark::State& s) { mpfi_run(s, xs(), ys(), [](mpfi_ptr r, mpfi_srcptr a, mpfi_srcptr b) { mpfi_div(r, a, b); }); }
void BM_sqrt_mpfi(benchmark::State& s) { mpfi_run(s, ps(), ps(), [](mpfi_ptr r, mpfi_srcptr a, mpfi_srcptr) { mpfi_sqrt(r, a); }); }
void BM_exp_mpfi(benchmark::State& s) { mpfi_run(s, ss(), ss(), [](mpfi_ptr r, mpfi_srcptr a, mpfi_srcptr) { mpfi_exp(r, a); }); }
void BM_log_mpfi(benchmark::State& s) { mpfi_run(s, ps(), ps(), [](mpfi_ptr r, mpfi_srcptr a, mpfi_srcptr) { mpfi_log(r, a); }); }
void BM_sin_mpfi(benchmark::State& s) { mpfi_run(s, ss(), ss(), [](mpfi_ptr r, mpfi_srcptr a, mpfi_srcptr) { mpfi_sin(r, a); }); }
BENCHMARK(BM_add_mpfi);
BENCHMARK(BM_mul_mpfi);
BENCHMARK(BM_div_mpfi);
BENCHMARK(BM_sqrt_mpfi);
BENCHMARK(BM_exp_mpfi);
BENCHMARK(BM_log_mpfi);
BENCHMARK(BM_sin_mpfi);
#endif

}  // namespace

BENCHMARK_MAIN();
