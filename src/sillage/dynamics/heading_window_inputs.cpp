#include "sillage/dynamics/heading_window_inputs.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "sillage/interval/arith_rows.h"
#include "sillage/interval/elementary.h"
#include "sillage/interval/trig_batch.h"

namespace sillage::detail {

namespace {

// The same bits (zero signs included): what was computed from a is what b gives.
bool same_bits(const Interval& a, const Interval& b) {
  return std::bit_cast<std::uint64_t>(a.lb()) == std::bit_cast<std::uint64_t>(b.lb()) &&
         std::bit_cast<std::uint64_t>(a.ub()) == std::bit_cast<std::uint64_t>(b.ub());
}

}  // namespace

void WindowInputs::compute_turn(const TDomain& td, std::size_t j) {
  const Interval delta = td.slice_width(j);
  turn_[j] = w_[j].is_unbounded() ? Interval::all_reals() : Interval(-1, 1) * Interval(w_[j].mag()) * delta;
  bend_[j] = std::isfinite(accel_) ? Interval(-1, 1) * Interval(accel_) * sqr(delta) / Interval(8.0) : Interval::all_reals();
}

void WindowInputs::compute_slice(std::size_t j) {
  dist_[j] = d_[j] & Interval::pos_reals();
  Interval r = Interval::all_reals();
  // |ψ'| <= ω: ψ − ψ(t_j) <= min(ω τ, inc + ω (δ − τ)) <= (inc + ω δ) / 2, and below likewise.
  if (!w_[j].is_unbounded()) r &= (dpsi_[j] + turn_[j]) / Interval(2.0);
  // |ψ''| <= α: ψ within α τ (δ − τ) / 2 <= α δ² / 8 of the chord ψ(t_j) + λ inc, λ in [0, 1].
  if (std::isfinite(accel_)) r &= (Interval(0.0) | dpsi_[j]) + bend_[j];
  spread_[j] = r + Interval(-1, 1) * Interval(track_);
}

bool WindowInputs::update(const TDomain& td, const TubeData& d, const TubeData& dpsi, const TubeData& w, double accel,
                          double track) {
  const auto ts = td.times();
  const std::size_t n = d.slices.size();
  const auto same_time = [](double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); };
  // The times known are those of the domain or the start of them (it grew at its end: online estimation).
  const bool same_start = !times_.empty() && times_.size() <= ts.size() &&
                          std::equal(times_.begin(), times_.end(), ts.begin(), same_time) &&
                          same_time(accel, accel_) && same_time(track, track_);
  const std::size_t old = same_start ? times_.size() - 1 : 0;  // the slices known
  if (!same_start) {
    accel_ = accel, track_ = track;
    sums_.assign(n + 1, Entry{});
  }
  if (!same_start || old < n) {  // the new slices, computed
    times_.assign(ts.begin(), ts.end());
    d_.resize(old), dpsi_.resize(old), w_.resize(old);
    d_.insert(d_.end(), d.slices.begin() + static_cast<std::ptrdiff_t>(old), d.slices.end());
    dpsi_.insert(dpsi_.end(), dpsi.slices.begin() + static_cast<std::ptrdiff_t>(old), dpsi.slices.end());
    w_.insert(w_.end(), w.slices.begin() + static_cast<std::ptrdiff_t>(old), w.slices.end());
    dist_.resize(n), spread_.resize(n), turn_.resize(n), bend_.resize(n);
    sums_.resize(n + 1);
    for (std::size_t j = old; j < n; ++j) compute_turn(td, j), compute_slice(j);
  }
  if (old > 0) {
    // The windows over a changed slice lose their sums: the first changed slice after each start.
    std::vector<std::size_t> next_change(old + 1, n);
    for (std::size_t j = old; j-- > 0;) {
      next_change[j] = next_change[j + 1];
      const bool same_w = same_bits(w_[j], w.slices[j]);
      if (same_bits(d_[j], d.slices[j]) && same_bits(dpsi_[j], dpsi.slices[j]) && same_w) continue;
      d_[j] = d.slices[j], dpsi_[j] = dpsi.slices[j], w_[j] = w.slices[j];
      if (!same_w) compute_turn(td, j);
      compute_slice(j);
      next_change[j] = j;
    }
    for (std::size_t a = 0; a < old; ++a) {
      if (sums_[a].valid && next_change[a] < sums_[a].b) sums_[a].valid = false;
    }
  }
  for (const Interval& x : dist_)
    if (x.is_empty()) return false;
  return true;
}

const WindowSum& WindowInputs::sum(std::size_t a, std::size_t b, std::size_t c) {
  Entry& e = sums_[a];
  if (e.valid && e.b == b && e.c == c) return e.s;
  // The directions of the slices a..b−1, their cosines and sines by the batch rows, then the sums.
  thread_local std::vector<Interval> dir, co, si;
  const std::size_t m = b - a;
  dir.resize(m), co.resize(m), si.resize(m);
  Interval rel(0.0);  // ψ(t_j) − ψ(t_c)
  for (std::size_t j = c; j < b; ++j) {
    dir[j - a] = rel + spread_[j];
    rel += dpsi_[j];
  }
  rel = Interval(0.0);
  for (std::size_t j = c; j-- > a;) {
    rel -= dpsi_[j];
    dir[j - a] = rel + spread_[j];
  }
  cos_rows(dir.data(), co.data(), m);
  sin_rows(dir.data(), si.data(), m);
  // The terms [d](j) (cos, sin)(dir_j), by the AVX2 rows where they run (the operators' bits).
  if (avx2_rows_for(m)) {
    arith_rows_avx2(RowOp::Mul, co.data(), RowArg{dist_.data() + a}, RowArg{co.data()}, m);
    arith_rows_avx2(RowOp::Mul, si.data(), RowArg{dist_.data() + a}, RowArg{si.data()}, m);
  } else {
    for (std::size_t i = 0; i < m; ++i) co[i] = dist_[a + i] * co[i], si[i] = dist_[a + i] * si[i];
  }
  Interval vx(0.0), vy(0.0), cone = Interval::empty();
  const auto add = [&](std::size_t j) {
    vx += co[j - a], vy += si[j - a];
    cone |= dir[j - a];
  };
  for (std::size_t j = c; j < b; ++j) add(j);
  for (std::size_t j = c; j-- > a;) add(j);
  e = {b, c, true, {vx, vy, cone}};
  return e.s;
}

}  // namespace sillage::detail
