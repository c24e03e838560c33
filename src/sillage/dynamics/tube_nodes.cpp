#include "sillage/dynamics/tube_nodes.h"

#include <algorithm>
#include <string>

#include "sillage/cn/tube_node.h"
#include "sillage/ctc/shrink.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/error.h"

namespace sillage {

namespace {

class EvalNode : public TubeNode {
 public:
  EvalNode(CtcEval ctc, const std::vector<BoundDomain>& args) : TubeNode("CtcEval", args), ctc_(ctc) {
    ctc_.enable_time_sampling(false);
    // t: one atom of an Interval or box; z: the atoms of the next argument(s) up to the first tube.
    if (args.size() < 3 || tube(0) || args[0].range.count != 1) {
      throw DimensionError(where() + ": expects (t, z, y[, w]) with t an Interval");
    }
    std::size_t i = 1;
    while (i < args.size() && !tube(i)) nb_z_ += args[i++].range.count;
    z_args_ = i - 1;
    const std::size_t rest = args.size() - i;
    if (nb_z_ == 0 || (rest != nb_z_ && rest != 2 * nb_z_)) {
      throw DimensionError(where() + ": z has " + std::to_string(nb_z_) + " components but " + std::to_string(rest) +
                           " tubes follow (y, or y and w, with as many components)");
    }
    y_ = whole_tubes(i, nb_z_, "y");
    if (rest == 2 * nb_z_) w_ = whole_tubes(i + nb_z_, nb_z_, "w");
    for (const auto& y : y_) ys_.push_back(&y->tube());
    for (const auto& w : w_) ws_.push_back(&w->tube());
    // Wake only for the slices around [t] (it only shrinks): what happens
    // elsewhere reaches [t] and [z] through those slices, or is CtcDeriv's.
    const TDomain& td = *y_.front()->tube().tdomain();
    const Interval t = args[0].domain->atom(args[0].range.first) & td.t0_tf();
    if (!t.is_empty()) {
      std::size_t first = 0, last = 0;
      slice_range(td, t, first, last, "ContractorNetwork::add(CtcEval)");
      const std::size_t lo = first > 0 ? first - 1 : 0, hi = std::min(last + 1, td.nb_slices() - 1);
      for (std::size_t r = 1 + z_args_; r < args.size(); ++r) {
        watch_only(r, gate_atom(lo), slice_atom(hi) - gate_atom(lo) + 2);
      }
    }
  }

  // Its slices around [t] keep their indices when the tubes grow at the end,
  // and it reads the tubes themselves, whatever their length: an online
  // estimator keeps its observations through every advance().
  bool follows_appends() const override { return true; }

  bool run(NodeRun& r) const override {
    Domain& td = *r.domains[ranges()[0].domain];
    const Interval t0 = td.atom(ranges()[0].first);
    Interval t = t0;
    // Per thread, reused: a network runs this node and its like tens of thousands of times.
    thread_local IntervalVector z(1), z0(1);
    thread_local std::vector<TubeChanges> logs;
    if (z.size() != nb_z_) z = IntervalVector(nb_z_);
    std::size_t c = 0;
    for (std::size_t a = 1; a <= z_args_; ++a) {
      for (std::size_t j = 0; j < ranges()[a].count; ++j) z[c++] = r.domains[ranges()[a].domain]->atom(ranges()[a].first + j);
    }
    z0 = z;
    logs.clear();
    for (std::size_t i = 0; i < y_.size(); ++i) logs.push_back(changes(r, 1 + z_args_ + i));
    // The fronts beyond [t] are CtcDeriv's when the network runs it on every (y, w).
    bool beyond = false;
    for (std::size_t i = 0; i < w_.size(); ++i) {
      beyond = beyond || !r.has_derivative(ranges()[1 + z_args_ + i], ranges()[1 + z_args_ + nb_z_ + i]);
    }
    // One pass: when it shrank something the network runs the node again next
    // round (r.again below), where its neighbours' changes usually wake it anyway.
    const bool ok = ctc_.contract(t, z, ys_, ws_, logs, beyond, true);
    // Write back t and z (intersected), report what shrank.
    const auto put = [&](std::size_t range, std::size_t j, std::size_t pos, const Interval& was, const Interval& now) {
      Domain& d = *r.domains[ranges()[range].domain];
      const Interval cur = d.atom(ranges()[range].first + j);
      const Interval next = cur & now;
      if (next != cur) d.set_atom(ranges()[range].first + j, next);
      if (shrank(was, next, r.ratio)) r.changed.push_back(pos);
    };
    put(0, 0, 0, t0, t);
    c = 0;
    for (std::size_t a = 1; a <= z_args_; ++a) {
      for (std::size_t j = 0; j < ranges()[a].count; ++j, ++c) put(a, j, offset(a) + j, z0[c], z[c]);
    }
    if (!ok) locate_empty(r, t0);
    r.again = ok && !r.changed.empty();
    return ok;
  }

 private:
  // An observation found inconsistent: report y's first slice meeting [t].
  void locate_empty(NodeRun& r, const Interval& t0) const {
    const TDomain& td = *y_.front()->tube().tdomain();
    const Interval t = t0 & td.t0_tf();
    r.empty_time = t0;
    if (t.is_empty()) return;
    std::size_t first = 0, last = 0;
    slice_range(td, t, first, last, "ContractorNetwork(CtcEval)");
    r.empty_at = offset(1 + z_args_) + slice_atom(first);
  }

  CtcEval ctc_;
  std::size_t nb_z_ = 0, z_args_ = 0;
  std::vector<std::shared_ptr<TubeDomain>> y_, w_;
  std::vector<Tube*> ys_;  // the tubes of y_ and w_ (kept alive by them)
  std::vector<const Tube*> ws_;
};

}  // namespace

std::shared_ptr<const CnNode> detail::make_eval_node(const CtcEval& ctc, const std::vector<BoundDomain>& args) {
  return std::make_shared<EvalNode>(ctc, args);
}

}  // namespace sillage
