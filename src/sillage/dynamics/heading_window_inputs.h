#pragma once
// What the windows of CtcHeadingWindow read, and the sum V of each window,
// remembered from one contraction to the next. In a network the inputs (the
// distances, the gyro increments, the turn rate: data) rarely change while the
// positions and the heading do, so a node keeps one of these (behind a mutex)
// and a run recomputes only the slices whose inputs changed, bit for bit, and
// the sums of the windows over them. The trigonometry of the sums is most of
// the contractor's work.
#include <cstddef>
#include <vector>

#include "sillage/interval/interval.h"
#include "sillage/tube/tdomain.h"

namespace sillage::detail {

// V = Σ_j [d](j) (cos, sin)(R_j ± track) over the slices of a window, R_j
// relative to its middle gate, and the hull `cone` of the R_j ± track.
struct WindowSum {
  Interval vx, vy, cone;
};

class WindowInputs {
 public:
  // Brings the per-slice values up to date with the slices of d, Δψ and w
  // (all of them when the times, accel or track changed; only the new ones
  // when the domain grew at its end) and forgets the sums of the windows
  // over a changed slice. False if some [d](j) ∩ [0, ∞)
  // is empty.
  bool update(const TDomain& td, const TubeData& d, const TubeData& dpsi, const TubeData& w, double accel,
              double track);
  // V and the cone of the window of slices a..b−1 relative to gate c
  // (a <= c <= b <= N), remembered when none of its slices changed.
  const WindowSum& sum(std::size_t a, std::size_t b, std::size_t c);

 private:
  // The terms of slice j's spread that depend on its width and w only (not on Δψ, which changes
  // with the bias of the gyro), then the spread and distance of slice j.
  void compute_turn(const TDomain& td, std::size_t j);
  void compute_slice(std::size_t j);

  std::vector<double> times_;
  double accel_ = 0, track_ = -1;
  // Per slice j, as read at the last update: the inputs, and what every
  // window reads from them: [d](j) ∩ [0, ∞) and the spread of the direction
  // of travel about ψ(t_j) (the turn inside the slice plus the track error).
  std::vector<Interval> d_, dpsi_, w_, dist_, spread_;
  // Per slice j: [−1, 1] ω δ_j (the turn at the rate bound) and [−1, 1] α δ_j² / 8 (the bend).
  std::vector<Interval> turn_, bend_;
  // Per window start a: its sum, valid while none of its slices changed.
  struct Entry {
    std::size_t b = 0, c = 0;
    bool valid = false;
    WindowSum s;
  };
  std::vector<Entry> sums_;
};

}  // namespace sillage::detail
