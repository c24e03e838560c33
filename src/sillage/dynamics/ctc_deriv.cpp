#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/deriv_sweep.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <string>
#include <type_traits>

#include "sillage/interval/rounding_policies.h"
#include "sillage/dynamics/slice_rule_x4.h"
#include "sillage/dynamics/polygon_hull_x8.h"
#include "sillage/interval/arith_rows.h"
#include "sillage/tube/slice_deriv.h"
#include "sillage/error.h"

namespace sillage {

namespace {

// Raw views of the arrays a sweep works on.
struct Arrays {
  const double* t;     // t_0 .. t_N
  Interval* s;         // slices of x
  Interval* g;         // gates of x
  const Interval* v;   // slices of v
};

// Writes [lo, hi] to dst; returns nonzero if a bit changed (no branch: the
// XOR of the bit patterns; a -0 replacing +0 counts as a change).
inline std::uint64_t store(Interval& dst, double lo, double hi) {
  const std::uint64_t diff = (std::bit_cast<std::uint64_t>(lo) ^ std::bit_cast<std::uint64_t>(dst.lb())) |
                             (std::bit_cast<std::uint64_t>(hi) ^ std::bit_cast<std::uint64_t>(dst.ub()));
  dst = Interval::from_bounds_unchecked(lo, hi);
  return diff;
}

// k = first .. last; the right gate of slice k is carried in registers to
// slice k+1. Returns false if something is empty; `changed` accumulates.
template <class R, bool kEnv>
bool forward_sweep(const Arrays& d, std::size_t first, std::size_t last, bool& changed) {
  double alo = d.g[first].lb(), ahi = d.g[first].ub();
  double t0 = d.t[first];
  bool ok = true;
  std::uint64_t ch = 0;
  for (std::size_t k = first; k <= last; ++k) {
    const double t1 = d.t[k + 1];
    double slo = d.s[k].lb(), shi = d.s[k].ub();
    double blo = d.g[k + 1].lb(), bhi = d.g[k + 1].ub();
    ok &= detail::contract_slice<R, true, false, kEnv>(alo, ahi, blo, bhi, slo, shi, d.v[k].lb(), d.v[k].ub(),
                                                      detail::width<R>(t0, t1));
    ch |= store(d.g[k], alo, ahi);
    if constexpr (kEnv) ch |= store(d.s[k], slo, shi);
    alo = blo;
    ahi = bhi;
    t0 = t1;
  }
  ch |= store(d.g[last + 1], alo, ahi);
  changed |= ch != 0;
  return ok;
}

// k = last .. first; the left gate of slice k is carried to slice k-1.
// kWiden: the gates are consistent both ways (after a forward sweep).
template <class R, bool kWiden>
bool backward_sweep(const Arrays& d, std::size_t first, std::size_t last, bool& changed) {
  double blo = d.g[last + 1].lb(), bhi = d.g[last + 1].ub();
  double t1 = d.t[last + 1];
  bool ok = true;
  std::uint64_t ch = 0;
  for (std::size_t k = last + 1; k-- > first;) {
    const double t0 = d.t[k];
    double slo = d.s[k].lb(), shi = d.s[k].ub();
    double alo = d.g[k].lb(), ahi = d.g[k].ub();
    ok &= detail::contract_slice<R, false, true, true, kWiden>(alo, ahi, blo, bhi, slo, shi, d.v[k].lb(), d.v[k].ub(),
                                                      detail::width<R>(t0, t1));
    ch |= store(d.g[k + 1], blo, bhi);
    ch |= store(d.s[k], slo, shi);
    blo = alo;
    bhi = ahi;
    t1 = t0;
  }
  ch |= store(d.g[first], blo, bhi);
  changed |= ch != 0;
  return ok;
}

constexpr std::size_t kBlock = 64;  // slices of a blocked sweep: they stay in L1 between its passes

// The hulls of slices first .. first+count-1 of a FWD_BWD sweep, their gates
// final: 8 at a time with hardware rounding (AVX-512F), 4 at a time on the
// portable path with AVX2, the rest by slice_hull. Nonzero if one changed.
template <class R>
std::uint64_t hulls(const Arrays& d, std::size_t first, std::size_t count) {
#if SILLAGE_HARD_ROUNDING
  if constexpr (std::is_same_v<R, detail::HardRounding>) {
    return detail::polygon_hulls_x8(d.t, d.s, d.g, d.v, first, count);
  } else
#endif
  {
    const std::size_t wide = count - count % 4;
    std::uint64_t ch = detail::polygon_hulls_x4(d.t, d.s, d.g, d.v, first, wide);
    for (std::size_t k = first + wide; k < first + count; ++k) {
      double slo = d.s[k].lb(), shi = d.s[k].ub();
      detail::slice_hull<R>(d.t[k], d.t[k + 1], d.g[k].lb(), d.g[k].ub(), d.g[k + 1].lb(), d.g[k + 1].ub(),
                            d.v[k].lb(), d.v[k].ub(), slo, shi);
      ch |= store(d.s[k], slo, shi);
    }
    return ch;
  }
}

// The forward sweep of FWD_BWD (no hulls) by blocks: δ[v] of the block
// first, then the chain of its gates. Bit for bit forward_sweep<R, false>.
template <class R>
bool forward_sweep_blocked(const Arrays& d, std::size_t first, std::size_t last, bool& changed) {
  double alo = d.g[first].lb(), ahi = d.g[first].ub();
  double plo[kBlock], phi[kBlock];
  bool ok = true;
  std::uint64_t ch = 0;
  for (std::size_t begin = first; begin <= last; begin += kBlock) {
    const std::size_t end = std::min(begin + kBlock, last + 1);
    detail::scale_slices<R>(d.t, d.v, begin, end - begin, plo, phi);
    for (std::size_t k = begin; k < end; ++k) {
      double slo = d.s[k].lb(), shi = d.s[k].ub();
      double blo = d.g[k + 1].lb(), bhi = d.g[k + 1].ub();
      ok &= detail::contract_slice_scaled<R, true, false, false>(alo, ahi, blo, bhi, slo, shi, d.v[k].lb(),
                                                                 d.v[k].ub(), plo[k - begin], phi[k - begin]);
      ch |= store(d.g[k], alo, ahi);
      alo = blo;
      ahi = bhi;
    }
  }
  ch |= store(d.g[last + 1], alo, ahi);
  changed |= ch != 0;
  return ok;
}

// The backward sweep of FWD_BWD by blocks of slices from the end: δ[v] of
// the block, the gates of the block by the scalar rule (a sequential chain),
// then the polygon hulls of the block several at a time (independent). Bit
// for bit the result of backward_sweep<R, true>: in FWD_BWD the gates
// already lie in their slices, so a slice's hull may come after the next
// gate is computed.
template <class R>
bool backward_sweep_blocked(const Arrays& d, std::size_t first, std::size_t last, bool& changed) {
  double blo = d.g[last + 1].lb(), bhi = d.g[last + 1].ub();
  double plo[kBlock], phi[kBlock];
  bool ok = true;
  std::uint64_t ch = 0;
  for (std::size_t end = last + 1; end > first;) {
    const std::size_t begin = end - first > kBlock ? end - kBlock : first;
    detail::scale_slices<R>(d.t, d.v, begin, end - begin, plo, phi);
    for (std::size_t k = end; k-- > begin;) {
      double slo = d.s[k].lb(), shi = d.s[k].ub();
      double alo = d.g[k].lb(), ahi = d.g[k].ub();
      ok &= detail::contract_slice_scaled<R, false, true, false>(alo, ahi, blo, bhi, slo, shi, d.v[k].lb(),
                                                                 d.v[k].ub(), plo[k - begin], phi[k - begin]);
      ch |= store(d.g[k + 1], blo, bhi);
      blo = alo;
      bhi = ahi;
    }
    ch |= store(d.g[begin], blo, bhi);
    ch |= hulls<R>(d, begin, end - begin);
    end = begin;
  }
  changed |= ch != 0;
  return ok;
}

// Whether R's FWD_BWD sweep goes by blocks here (its hulls several slices at a time).
template <class R>
bool blocked_sweeps() {
#if SILLAGE_HARD_ROUNDING
  if constexpr (std::is_same_v<R, detail::HardRounding>) return true;
#endif
  return detail::avx2_rows();
}

template <class R>
bool sweeps(TimePropag p, const Arrays& d, std::size_t first, std::size_t last, bool& changed) {
  switch (p) {
    case TimePropag::FORWARD:
      return forward_sweep<R, true>(d, first, last, changed);
    case TimePropag::BACKWARD:
      return backward_sweep<R, false>(d, first, last, changed);
    case TimePropag::FWD_BWD:
      break;
  }
  if (blocked_sweeps<R>())
    return forward_sweep_blocked<R>(d, first, last, changed) && backward_sweep_blocked<R>(d, first, last, changed);
  return forward_sweep<R, false>(d, first, last, changed) && backward_sweep<R, true>(d, first, last, changed);
}

template <class R>
bool one_sweep(detail::DerivSweep kind, const Arrays& d, std::size_t first, std::size_t last, bool& changed) {
  using K = detail::DerivSweep;
  const bool blocked = blocked_sweeps<R>();
  switch (kind) {
    case K::FwdBwdForward:
      return blocked ? forward_sweep_blocked<R>(d, first, last, changed) : forward_sweep<R, false>(d, first, last, changed);
    case K::FwdBwdBackward:
      return blocked ? backward_sweep_blocked<R>(d, first, last, changed) : backward_sweep<R, true>(d, first, last, changed);
  }
  return true;
}

// Contracts slices first..last (checked); sets x empty and returns false on emptiness.
bool run(TimePropag p, Tube& x, const Tube& v, std::size_t first, std::size_t last) {
  detail::check_real(x, "CtcDeriv::contract");
  // The rule reads v's slices only, but an empty gate of v leaves no
  // derivative at all: no x either (as a network with v as a domain finds).
  const auto vg = v.gates();
  for (std::size_t k = first; k <= last + 1; ++k) {
    if (vg[k].is_empty()) {
      x.set(Interval::empty());
      return false;
    }
  }
  Tube::Writer w = x.write();
  const Arrays d{x.tdomain()->times().data(), w.slices().data(), w.gates().data(), v.data().slices.data()};
  bool changed = false;
#if SILLAGE_HARD_ROUNDING
  const bool ok = detail::hardware_rounding() ? sweeps<detail::HardRounding>(p, d, first, last, changed)
                                             : sweeps<detail::SoftRounding>(p, d, first, last, changed);
#else
  const bool ok = sweeps<detail::SoftRounding>(p, d, first, last, changed);
#endif
  w.commit(ok && changed);
  if (!ok) {
    x.set(Interval::empty());
    return false;
  }
  return true;
}

void check_vectors(const TubeVector& x, const TubeVector& v, const char* where) {
  if (x.size() != v.size()) {
    throw DimensionError(std::string(where) + ": x has " + std::to_string(x.size()) + " components, v has " +
                         std::to_string(v.size()));
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i].tdomain() != v[i].tdomain()) {
      throw DimensionError(std::string(where) + ": component " + std::to_string(i) +
                           " of x and of v are not on the same TDomain");
    }
  }
}

// Runs f on every component; if one is found empty, all are set empty.
template <class F>
bool each_component(TubeVector& x, F f) {
  bool ok = true;
  for (std::size_t i = 0; i < x.size() && ok; ++i) ok = f(i);
  if (!ok) {
    for (std::size_t i = 0; i < x.size(); ++i) x[i].set(Interval::empty());
  }
  return ok;
}

}  // namespace

void detail::check_deriv_pair(const Tube& x, const Tube& v, const char* where) {
  if (x.tdomain() != v.tdomain()) {
    throw DimensionError(std::string(where) + ": x and v are not on the same TDomain (" +
                         std::to_string(x.nb_slices()) + " and " + std::to_string(v.nb_slices()) + " slices)");
  }
}

void detail::check_real(const Tube& x, const char* where) {
  // Its gates and slices may be written on different turns: real sweeps would lose the truth.
  if (x.is_angle()) throw Error(std::string(where) + ": x is an angle tube (values modulo 2 pi): use CtcDerivAngle");
}

void detail::check_deriv_range(std::size_t n, std::size_t first, std::size_t last, const char* where) {
  if (first > last || last >= n) {
    throw Error(std::string(where) + ": slice range [" + std::to_string(first) + ", " + std::to_string(last) +
                "] is not inside [0, " + std::to_string(n - 1) + "]");
  }
}

bool detail::deriv_sweep(DerivSweep kind, const double* t, Interval* s, Interval* g, const Interval* v,
                         std::size_t first, std::size_t last, bool& changed) {
  const Arrays d{t, s, g, v};
#if SILLAGE_HARD_ROUNDING
  if (detail::hardware_rounding()) return one_sweep<detail::HardRounding>(kind, d, first, last, changed);
#endif
  return one_sweep<detail::SoftRounding>(kind, d, first, last, changed);
}

bool CtcDeriv::contract(Tube& x, const Tube& v) const {
  detail::check_deriv_pair(x, v, "CtcDeriv::contract(x, v)");
  return run(propag_, x, v, 0, x.nb_slices() - 1);
}

bool CtcDeriv::contract(Tube& x, const Tube& v, std::size_t first, std::size_t last) const {
  detail::check_deriv_pair(x, v, "CtcDeriv::contract(x, v, first, last)");
  detail::check_deriv_range(x.nb_slices(), first, last, "CtcDeriv::contract(x, v, first, last)");
  return run(propag_, x, v, first, last);
}

bool CtcDeriv::contract(Tube& x, const Tube& v, const Interval& t) const {
  const char* where = "CtcDeriv::contract(x, v, t)";
  detail::check_deriv_pair(x, v, where);
  if (t.is_empty()) return true;
  std::size_t first = 0, last = 0;
  slice_range(*x.tdomain(), t, first, last, where);
  return run(propag_, x, v, first, last);
}

bool CtcDeriv::contract(TubeVector& x, const TubeVector& v) const {
  check_vectors(x, v, "CtcDeriv::contract(TubeVector x, TubeVector v)");
  return each_component(x, [&](std::size_t i) { return run(propag_, x[i], v[i], 0, x.nb_slices() - 1); });
}

bool CtcDeriv::contract(TubeVector& x, const TubeVector& v, std::size_t first, std::size_t last) const {
  const char* where = "CtcDeriv::contract(TubeVector x, TubeVector v, first, last)";
  check_vectors(x, v, where);
  detail::check_deriv_range(x.nb_slices(), first, last, where);
  return each_component(x, [&](std::size_t i) { return run(propag_, x[i], v[i], first, last); });
}

bool CtcDeriv::contract(TubeVector& x, const TubeVector& v, const Interval& t) const {
  const char* where = "CtcDeriv::contract(TubeVector x, TubeVector v, t)";
  check_vectors(x, v, where);
  if (t.is_empty()) return true;
  std::size_t first = 0, last = 0;
  slice_range(*x.tdomain(), t, first, last, where);
  return each_component(x, [&](std::size_t i) { return run(propag_, x[i], v[i], first, last); });
}

}  // namespace sillage
