#pragma once
// TubeOriginals: the values of a run of a tube's slices and gates before a
// local contraction first covered them, to report at its end what shrank
// against them (a contraction that starts where the tube changed and grows
// its reach at either end: CtcDeriv::contract_local, CtcIncrement's and
// CtcHeading's). A caller keeps one per thread and tube (thread_local) and
// start()s it per contraction: its buffers are reused, with nothing to
// allocate per network run.
#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "sillage/cn/tube_changes.h"
#include "sillage/interval/interval.h"

namespace sillage::detail {

class TubeOriginals {
 public:
  // Records nothing yet of the tube whose slices and gates are s and g.
  void start(std::span<const Interval> s, std::span<const Interval> g) {
    sl_ = s, ga_ = g;
    s_.clear(), g_.clear();
  }
  // Records slices a..b and gates a..b+1 not recorded yet (the range grows at one end at a time).
  void cover(std::size_t a, std::size_t b) {
    if (s_.empty()) {
      base_ = a;
      s_.assign(sl_.begin() + a, sl_.begin() + b + 1);
      g_.assign(ga_.begin() + a, ga_.begin() + b + 2);
      return;
    }
    if (a < base_) {
      s_.insert(s_.begin(), sl_.begin() + a, sl_.begin() + base_);
      g_.insert(g_.begin(), ga_.begin() + a, ga_.begin() + base_);
      base_ = a;
    }
    const std::size_t end = base_ + s_.size();  // first slice not recorded
    if (b + 1 > end) {
      s_.insert(s_.end(), sl_.begin() + end, sl_.begin() + b + 1);
      g_.insert(g_.end(), ga_.begin() + end + 1, ga_.begin() + b + 2);
    }
  }
  // Records slice k (and its gates) if not yet, with a block that doubles
  // what is recorded (a sweep that goes on one slice at a time); n: the
  // number of slices.
  void reach(std::size_t k, std::size_t n) {
    if (s_.empty()) return cover(k, k);
    const std::size_t end = base_ + s_.size(), span = std::max<std::size_t>(s_.size(), 16);
    if (k < base_) cover(std::min(k, base_ > span ? base_ - span : 0), end - 1);
    else if (k >= end) cover(base_, std::max(k, std::min(n - 1, end - 1 + span)));
  }
  // Gate k's recorded value (covered).
  const Interval& gate(std::size_t k) const { return g_[k - base_]; }
  // Every covered slice and gate against its value now.
  void report(const TubeChanges& changes) const {
    for (std::size_t i = 0; i < s_.size(); ++i) changes.slice(base_ + i, s_[i], sl_[base_ + i]);
    for (std::size_t i = 0; i < g_.size(); ++i) changes.gate(base_ + i, g_[i], ga_[base_ + i]);
  }

 private:
  std::span<const Interval> sl_, ga_;  // the tube's arrays
  std::size_t base_ = 0;
  std::vector<Interval> s_, g_;  // slices base_.., gates base_.. as they were
};

}  // namespace sillage::detail
