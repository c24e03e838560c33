#pragma once
// OnlineEstimator: where the robot is now, while it moves (docs/online.md).
// The same network and contractors as a batch solve, on a time domain that
// grows as time advances and forgets the past beyond a window W, so that
// memory is O(W / δ) whatever the mission's length.
//
//   OnlineEstimator est(t0, {.window = 60});
//   est.add_state("p", 2, IntervalVector{{-0.1, 0.1}, {-0.1, 0.1}});  // p(t0)
//   est.add_input("v", 2);            // given per period by advance()
//   est.add_deriv("p", "v");          // p' = v
//   est.advance(t1, {{"v", v01}});    // the period [t0, t1]
//   est.observe(t_meas, "p", range_ctc, {beacon, range});  // g(p(t)) for t in t_meas
//   IntervalVector p_now = est.now("p");
//
// The model (tubes and constraints) is declared first; the first advance()
// creates the time domain [t0, t1] and the network. Each advance() appends
// the slice [now, t] to every tube, writes the inputs into it and contracts
// what that reaches; each observe() adds an evaluation contractor (CtcEval,
// the time of the measurement uncertain) and the measurement's contractor,
// and contracts what they reach (ContractorNetwork::update). Every estimate
// is a guaranteed enclosure, as in batch: with W infinite and all the data
// given, a final network().contract() is the batch solve.
//
// Forgetting: once the past beyond W reaches forget_every seconds, the
// slices before now - W are dropped (the gate at the new start keeps what
// the past proved) and the observations whose time began before the new
// start are retired, their information already folded into the window.
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sillage/cn/contractor_network.h"
#include "sillage/expr/function.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// How the estimator keeps its window and contracts.
struct OnlineOptions {
  // W: seconds of past kept behind now (infinity: everything, online smoothing).
  double window = std::numeric_limits<double>::infinity();
  // Past beyond W accumulated before it is dropped, in seconds (0: W / 8);
  // dropping moves every tube's arrays and shifts every node (a pass over
  // the network), so it is done in batches.
  double forget_every = 0.0;
  // The network's shrink ratio (ContractorNetwork::set_ratio).
  double ratio = 0.01;
};

// What the estimator costs and holds (stats()).
struct OnlineStats {
  std::size_t updates = 0;        // advance() and observe() calls that contracted
  double last_seconds = 0.0;      // wall-clock time of the last one
  double total_seconds = 0.0;     // of all of them
  std::size_t slices = 0;         // slices in memory (the window), per tube
  std::size_t forgotten = 0;      // slices dropped so far
  std::size_t observations = 0;   // observations in the window
  std::size_t pending = 0;        // observations held until time passes their [t]
  std::size_t retired = 0;        // observations retired so far
  std::size_t contractors = 0;    // contractors in the network
  std::size_t contractor_runs = 0;  // runs of all updates
  std::size_t relayouts = 0;      // layouts of the network followed (every advance)
  double layout_seconds = 0.0;    // the part of total_seconds spent laying the network out
};

class OnlineEstimator {
 public:
  // An estimator whose time starts at t0 (finite; Error otherwise).
  explicit OnlineEstimator(double t0, OnlineOptions options = {});
  ~OnlineEstimator();
  OnlineEstimator(const OnlineEstimator&) = delete;
  OnlineEstimator& operator=(const OnlineEstimator&) = delete;

  // The model, declared before the first advance() (Error after it, or on a
  // name already used, or dim == 0). Names are the tubes' in every query.
  //
  // A state: unknown but for x0, its value at t0 (default: unknown).
  void add_state(const std::string& name, std::size_t dim, const IntervalVector& x0 = {});
  // An input: given per period by advance(); unknown where not given.
  void add_input(const std::string& name, std::size_t dim);
  // A tube bounded by `value` at every time (a speed limit, a turn rate).
  void add_bounded(const std::string& name, const IntervalVector& value);
  // A tube bounded by bound(t), a function of the one variable t whose image
  // has the tube's dimension ("[-oo, oo]" leaves a component free), evaluated
  // on each new slice and gate; x0 its value at t0 (default: the bound's).
  // E.g. Function({"t"}, "(-9/20*cos(t/5) + [-0.001, 0.001], [-oo, oo])").
  void add_bounded(const std::string& name, const Function& bound, const IntervalVector& x0 = {});
  // x' = v between two declared tubes of one dimension (CtcDeriv per component).
  void add_deriv(const std::string& x, const std::string& v);
  // A box contractor applied at every time to the concatenation of the tubes
  // (the vector's components in order; "v[0]" names one component), e.g.
  // v[0] - speed*cos(psi) = 0.
  void add(std::shared_ptr<const Ctc> ctc, const std::vector<std::string>& tubes);
  // A contractor on whole tubes (CtcIncrement, CtcSecondDeriv, ...), named as above.
  void add(std::shared_ptr<const NetworkCtc> ctc, const std::vector<std::string>& tubes);

  // Time advances to t > now(): every tube gains the slice [now, t], each
  // input named in `inputs` is that period's value there (the others stay
  // unknown), then the network contracts what changed. Error (and nothing
  // changed) if t is not finite or not after now, if an input is unknown or
  // of another dimension, NaN or empty.
  void advance(double t, const std::vector<std::pair<std::string, IntervalVector>>& inputs = {});
  // A measurement of the state `state` at a time t in [t] (uncertain): ctc
  // acts on (x(t), extras...), e.g. a range to a beacon; the extras are
  // intervals or boxes. When [t] reaches past now() the observation is held
  // (pending()) until time has passed its end, then applied: its time may
  // lie a little ahead of the last advance, and none of it is cut off.
  // Error, with nothing changed, if [t] is empty, begins after now() (the
  // future), begins before the window's start (too old), the state has no
  // derivative declared, or ctc's dimension is not the arguments'. Returns
  // the observation's number (0, 1, ... in arrival order).
  std::size_t observe(const Interval& t, const std::string& state, std::shared_ptr<const Ctc> ctc,
                      const std::vector<DomainRef>& extras = {});
  // The same for several states at one time t in [t]: ctc acts on
  // (x1(t), x2(t), ..., extras...), e.g. a clock's reading and a range taken
  // together (h(t) = tau, y(t) = z).
  std::size_t observe(const Interval& t, const std::vector<std::string>& states, std::shared_ptr<const Ctc> ctc,
                      const std::vector<DomainRef>& extras = {});
  // Observations held until time passes the end of their [t].
  std::size_t pending() const;

  // The current time (t0 before the first advance).
  double now() const { return now_; }
  // The start of the window (t0 until something is forgotten).
  double window_start() const;
  // The box of the tube `name` at now(): the filtering estimate.
  IntervalVector now(const std::string& name) const;
  // The tube `name` over the window: the smoothing estimate within it
  // (shared with the network: do not resize it). Error before the first advance().
  std::shared_ptr<TubeVector> tube(const std::string& name) const;
  // The cost and size so far.
  OnlineStats stats() const;
  // What the last advance() or observe() contraction did: its summary says
  // Converged, or NoSolution with the contractor and the time that proved the
  // data inconsistent (the estimate is then empty and stays so).
  const ContractStats& last_update() const;
  // The network (e.g. its budget, or a final contract() for the batch fixed point).
  ContractorNetwork& network();
  // The options, forget_every resolved (W / 8 when given 0).
  const OnlineOptions& options() const { return options_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  OnlineOptions options_;
  double now_;
};

}  // namespace sillage
