#pragma once
// temporal_slam: thesis Alg. 15 on the network (7.27):
//   v = f(x, u),  x' = v,  p = h(x),  w = h(v) (7.26),  C_{p⇒z}(p, w, z),
// applied as
//   1. C_f:     v ∩= f(x, u), x ∩= its backward HC4 pass (slice- and gate-wise; u read only)
//   2. C_d/dt:  x, v                     (CtcDeriv)
//   3. C_h:     p = h(x), w = h(v)        (h linear, as (7.25): then dh/dx·v = h(v))
//   4. C_{p⇒z}(p, w, z, eps)             (to its fixed point)
//   5. C_h:     x ∩= h⁻¹(p)               (HC4 on each slice and gate)
// repeated while C_{p⇒z} still contracts. The fast algorithm (Alg. 14) is
// run to its fixed point first, then the accurate one (Alg. 13), as the
// thesis does (7.3.2); each may be run alone.
#include <cstddef>
#include <functional>
#include <vector>

#include "sillage/budget.h"
#include "sillage/outcome.h"
#include "sillage/slam/slam_row.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

class Function;

// What TemporalSlamOptions::on_iteration calls: (row, p).
using SlamIterationCallback = std::function<void(const SlamRow&, const TubeVector&)>;

// Options of temporal_slam.
struct TemporalSlamOptions {
  double eps = 0.1;       // width of the t-boxes (about the time step)
  bool fast = true;       // run Alg. 14 to its fixed point
  bool accurate = true;   // then Alg. 13 to its fixed point
  std::size_t max_rounds = 20;  // cap on the rounds 1-5 per algorithm
  // Called after every iteration of C_{p⇒z} with its row and the contracted
  // p = h(x) (2-D or 1-D, as h): to check the truth at every gate, or to keep
  // snapshots. Not timed (the row's seconds exclude it). In Python any
  // callable(row, p), or None.
  SlamIterationCallback on_iteration;
  // Another thread may cancel it: temporal_slam then throws Cancelled within
  // tens of milliseconds, x and v left as enclosures (Python: Ctrl-C), and
  // temporal_slam_run returns Cancelled.
  CancelToken cancel;
  // Called after every iteration of C_{p⇒z} (outcome.h: round and work are
  // the iterations so far), for tracing and progress; none by default.
  ProgressHook progress;
};

// A temporal SLAM run: its rows and how it ended. x and v, contracted in
// place, are enclosures of the trajectory whatever the status: every step
// only shrinks them.
struct TemporalSlamResult {
  // One row per iteration of C_{p⇒z} done.
  std::vector<SlamRow> rows;
  // Converged: every algorithm run reached its fixed point. Stopped: one
  // ran max_rounds rounds without reaching it (reason names it). Cancelled:
  // options.cancel was set. NoSolution: x emptied (reason says at which step:
  // the data contradict the model). work counts the iterations of C_{p⇒z}.
  Summary summary;
};

// x (n-D) and v (n-D) are contracted in place; u the inputs (any size, may
// be empty: then f has the n variables of x only), z the observations (any
// size); f: (x, u) -> v, n outputs; h: x -> p, 2 outputs (or 1: scalar_loops.h), linear. Every tube
// on x's TDomain (z may cover a larger time domain). Returns one row per
// iteration of C_{p⇒z}, numbered over the whole run; contractions of p(t_f)
// and p(t_0) relative to dead reckoning (h(x) after the first C_d/dt). DimensionError / Error on sizes,
// TDomains, eps or an option with nothing to run.
// Throws Cancelled when cancelled; a run stopped by max_rounds returns its
// rows, as one that converged.
std::vector<SlamRow> temporal_slam(TubeVector& x, TubeVector& v, const TubeVector& u, const TubeVector& z,
                                   const Function& f, const Function& h, const TemporalSlamOptions& options = {});
// The same, saying how it ended instead of throwing Cancelled (errors on the
// input are still thrown).
TemporalSlamResult temporal_slam_run(TubeVector& x, TubeVector& v, const TubeVector& u, const TubeVector& z,
                                     const Function& f, const Function& h, const TemporalSlamOptions& options = {});

}  // namespace sillage
