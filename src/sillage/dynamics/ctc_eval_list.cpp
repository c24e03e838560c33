#include "sillage/dynamics/ctc_eval_list.h"

#include <algorithm>
#include <cstdint>

#include "sillage/cn/tube_node.h"
#include "sillage/ctc/shrink.h"
#include "sillage/dynamics/ctc_eval.h"

namespace sillage {

namespace {

// Passes of one fix within a run (CtcEval's pass, then the fix's contractor)
// before the node leaves the rest to its next run (NodeRun::again).
constexpr int kMaxPasses = 50;

// cn.add(CtcEvalList(obs), {x, v}): x and v tubes of one size n.
class EvalListNode : public TubeNode {
 public:
  EvalListNode(std::shared_ptr<const std::vector<TubeObservation>> obs, const std::vector<BoundDomain>& args)
      : TubeNode("CtcEvalList", args), held_(std::move(obs)), obs_(*held_) {
    if (args.empty() || args.size() % 2 != 0) {
      throw DimensionError(where() + ": expects x and v with as many components, got " + std::to_string(args.size()) +
                           " tubes");
    }
    n_ = args.size() / 2;
    for (const auto& x : whole_tubes(0, n_, "x")) xs_.push_back(&x->tube());
    for (const auto& v : whole_tubes(n_, n_, "v")) vs_.push_back(&v->tube());
    const TDomain& td = *xs_.front()->tdomain();
    detail::check_observation_list(n_, td.t0_tf(), obs_, where());
    eval_.enable_time_sampling(false);  // the network's layout is fixed
    // Each fix's state, and the time atoms whose shrinking wakes it: the
    // slices meeting [t] and their neighbours, with their gates (as a CtcEval node).
    t_.reserve(obs_.size());
    z_.reserve(obs_.size() * n_);
    lo_.reserve(obs_.size());
    hi_.reserve(obs_.size());
    for (const TubeObservation& o : obs_) {
      t_.push_back(o.t & td.t0_tf());
      for (std::size_t j = 0; j < n_; ++j) z_.push_back(o.z[j]);
      std::size_t first = 0, last = 0;
      slice_range(td, t_.back(), first, last, "ContractorNetwork::add(CtcEvalList)");
      const std::size_t lo = first > 0 ? first - 1 : 0, hi = std::min(last + 1, td.nb_slices() - 1);
      lo_.push_back(gate_atom(lo));
      hi_.push_back(gate_atom(hi + 1));
    }
  }

  std::string describe() const override {
    if (emptied_ >= obs_.size()) return "CtcEvalList (" + std::to_string(obs_.size()) + " fixes)";
    const std::string& n = obs_[emptied_].name;
    return "CtcEvalList (" + (n.empty() ? "fix " + std::to_string(emptied_) : n) + ")";
  }

  bool run(NodeRun& r) const override {
    // The fronts beyond [t] are CtcDeriv's when the network runs it on every (x, v).
    bool beyond = false;
    for (std::size_t j = 0; j < n_; ++j) beyond = beyond || !r.has_derivative(ranges()[j], ranges()[n_ + j]);
    thread_local std::vector<TubeChanges> logs;
    logs.clear();
    for (std::size_t j = 0; j < n_; ++j) logs.push_back(changes(r, j));
    // The fixes to run: all on the first run, else those whose slices shrank
    // since, by another node or by this one (after the fix had run): marks of
    // the time atoms, summed, so that a fix asks for its window in O(1).
    thread_local std::vector<std::uint32_t> marked;
    if (!r.all) {
      marked.assign(nb_time_atoms() + 1, 0);
      std::size_t g = 0;  // r.dirty is sorted: its ranges come in order
      for (const std::size_t p : r.dirty) {
        while (g + 1 < ranges().size() && p >= offset(g + 1)) ++g;
        marked[p - offset(g) + 1] = 1;
      }
      for (const std::size_t a : own_) marked[a + 1] = 1;
      for (std::size_t a = 1; a < marked.size(); ++a) marked[a] += marked[a - 1];
    }
    own_.clear();
    bool again = false;
    for (std::size_t i = 0; i < obs_.size(); ++i) {
      if (!r.all && marked[hi_[i] + 1] == marked[lo_[i]]) continue;
      const std::size_t before = r.changed.size();
      const int passes = run_fix(i, r, logs, beyond);
      if (passes < 0) return inconsistent(r, i);
      again = again || passes > kMaxPasses;
      for (std::size_t k = before; k < r.changed.size(); ++k) {
        own_.push_back(r.changed[k] - offset(range_of(r.changed[k])));
      }
    }
    // A fix that ran before another shrank its slices runs again next round.
    r.again = again || !own_.empty();
    return true;
  }

 private:
  // Fix i to its fixed point (at most kMaxPasses passes): the number of
  // passes, kMaxPasses + 1 when stopped short, -1 if inconsistent.
  int run_fix(std::size_t i, NodeRun& r, const std::vector<TubeChanges>& logs, bool beyond) const {
    thread_local IntervalVector z(1), z0(1), z1(1);  // scratch, per thread (runs never nest)
    if (z.size() != n_) z = z0 = z1 = IntervalVector(n_);
    for (std::size_t j = 0; j < n_; ++j) z[j] = z_[i * n_ + j];
    Interval t = t_[i];
    const CtcPtr& ctc = obs_[i].ctc;
    int pass = 1;
    for (;; ++pass) {
      const Interval t0 = t;
      z0 = z;
      if (!eval_.contract(t, z, xs_, vs_, logs, beyond, true)) return -1;
      if (ctc) {
        z1 = z;
        ctc->contract(z);
        z &= z1;  // a contractor never enlarges; guard against one that would
        if (z.is_empty()) return -1;
      }
      if (!shrank(t0, t, r.ratio) && !shrank(z0, z, r.ratio)) break;
      if (pass > kMaxPasses) break;
    }
    t_[i] = t;
    for (std::size_t j = 0; j < n_; ++j) z_[i * n_ + j] = z[j];
    return pass;
  }

  // Fix i is inconsistent with the tube: x is emptied (Lemma 5.1) and the
  // network told where (the first slice meeting [t_i]).
  bool inconsistent(NodeRun& r, std::size_t i) const {
    emptied_ = i;
    const TDomain& td = *xs_.front()->tdomain();
    const Interval t = obs_[i].t & td.t0_tf();
    std::size_t first = 0, last = 0;
    slice_range(td, t, first, last, "ContractorNetwork(CtcEvalList)");
    r.empty_at = offset(0) + slice_atom(first);
    r.empty_time = obs_[i].t;
    return empty_tubes(r, 0, n_);
  }

  std::shared_ptr<const std::vector<TubeObservation>> held_;  // the CtcEvalList's, shared
  const std::vector<TubeObservation>& obs_;
  std::size_t n_ = 0;
  std::vector<Tube*> xs_;  // the tubes of the node's ranges (kept alive by the network's domains)
  std::vector<const Tube*> vs_;
  CtcEval eval_;
  std::vector<std::size_t> lo_, hi_;  // per fix, the time atoms that wake it
  // Per fix, its [t] and [z] (n components) as contracted so far.
  mutable std::vector<Interval> t_, z_;
  // The time atoms of x this node shrank in its last run (they may concern a fix that ran before).
  mutable std::vector<std::size_t> own_;
  mutable std::size_t emptied_ = static_cast<std::size_t>(-1);  // the fix found inconsistent
};

}  // namespace

CtcEvalList::CtcEvalList(std::vector<TubeObservation> obs)
    : obs_(std::make_shared<const std::vector<TubeObservation>>(std::move(obs))) {
  if (obs_->empty()) throw Error("CtcEvalList(obs): needs at least one observation");
}

std::shared_ptr<const CnNode> CtcEvalList::make_node(const std::vector<BoundDomain>& args) const {
  return std::make_shared<EvalListNode>(obs_, args);
}

}  // namespace sillage
