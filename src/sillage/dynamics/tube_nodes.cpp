#include "sillage/dynamics/tube_nodes.h"

#include <algorithm>
#include <string>

#include "sillage/cn/empty_prefix.h"
#include "sillage/cn/tube_changes.h"
#include "sillage/cn/tube_domain.h"
#include "sillage/ctc/shrink.h"
#include "sillage/error.h"

namespace sillage {

namespace {

std::shared_ptr<TubeDomain> tube_of(const BoundDomain& b) { return std::dynamic_pointer_cast<TubeDomain>(b.domain); }

std::vector<AtomRange> ranges_of(const std::vector<BoundDomain>& args) {
  std::vector<AtomRange> r;
  for (const auto& a : args) r.push_back(a.range);
  return r;
}

// Tube arguments [first, first + n): whole tubes on one TDomain, or an error naming `who`.
std::vector<std::shared_ptr<TubeDomain>> tubes(const std::vector<BoundDomain>& args, std::size_t first,
                                               std::size_t n, const std::string& who, const char* what) {
  std::vector<std::shared_ptr<TubeDomain>> out;
  for (std::size_t i = first; i < first + n; ++i) {
    auto t = i < args.size() ? tube_of(args[i]) : nullptr;
    if (!t) throw DimensionError(who + ": " + what + " must be tubes (argument " + std::to_string(i) + ")");
    if (args[i].range.first != 0 || args[i].range.count != t->nb_atoms()) {
      throw DimensionError(who + ": " + what + " must be whole tubes");
    }
    if (!out.empty() && t->tube().tdomain() != out.front()->tube().tdomain()) {
      throw DimensionError(who + ": the tubes are not on one TDomain");
    }
    out.push_back(std::move(t));
  }
  return out;
}

// x' = v (CtcDeriv) or x(t_{k+1}) - x(t_k) ∈ [v](k) (CtcIncrement), x and v
// tubes (or components) in pairs.
template <class C>
class PairNode : public CnNode {
 public:
  PairNode(C ctc, const std::vector<BoundDomain>& args) : CnNode(ranges_of(args)), ctc_(ctc) {
    const std::string who = "ContractorNetwork::add(" + ctc_.name() + ")";
    if (args.empty() || args.size() % 2 != 0) {
      throw DimensionError(who + ": expects x and v with as many components, got " + std::to_string(args.size()) +
                           " tubes");
    }
    const std::size_t n = args.size() / 2;
    x_ = tubes(args, 0, n, who, "x");
    v_ = tubes(args, n, n, who, "v");
    if (x_.front()->tube().tdomain() != v_.front()->tube().tdomain()) {
      throw DimensionError(who + ": x and v are not on one TDomain");
    }
  }
  std::string name() const override { return ctc_.name(); }
  bool run(NodeRun& r) const override {
    for (std::size_t i = 0; i < x_.size(); ++i) {
      Tube& x = x_[i]->tube();
      before_.take(x);
      const Tube& v = v_[i]->tube();
      const bool ok = ctc_.contract(x, v);
      before_.report(x, offset(i), r.ratio, r.changed);
      if (!ok) {
        // x is now empty everywhere: find from its former value where it stopped being consistent.
        const std::size_t a =
            first_empty_prefix(before_.restore(x.tdomain()), [&](Tube& y) { return ctc_.contract(y, v); });
        if (a < x_[i]->nb_atoms()) r.empty_at = offset(i) + a;
        return false;
      }
    }
    return true;
  }

 private:
  C ctc_;
  std::vector<std::shared_ptr<TubeDomain>> x_, v_;
  mutable TubeSnapshot before_;  // scratch of run() (a network runs one node at a time)
};

class EvalNode : public CnNode {
 public:
  EvalNode(CtcEval ctc, const std::vector<BoundDomain>& args) : CnNode(ranges_of(args)), ctc_(ctc) {
    const std::string who = "ContractorNetwork::add(CtcEval)";
    ctc_.enable_time_sampling(false);
    // t: one atom of an Interval or box; z: the atoms of the next argument(s) up to the first tube.
    if (args.size() < 3 || tube_of(args[0]) || args[0].range.count != 1) {
      throw DimensionError(who + ": expects (t, z, y[, w]) with t an Interval");
    }
    std::size_t i = 1;
    while (i < args.size() && !tube_of(args[i])) nb_z_ += args[i++].range.count;
    z_args_ = i - 1;
    const std::size_t rest = args.size() - i;
    if (nb_z_ == 0 || (rest != nb_z_ && rest != 2 * nb_z_)) {
      throw DimensionError(who + ": z has " + std::to_string(nb_z_) + " components but " + std::to_string(rest) +
                           " tubes follow (y, or y and w, with as many components)");
    }
    y_ = tubes(args, i, nb_z_, who, "y");
    if (rest == 2 * nb_z_) w_ = tubes(args, i + nb_z_, nb_z_, who, "w");
    if (!w_.empty() && w_.front()->tube().tdomain() != y_.front()->tube().tdomain()) {
      throw DimensionError(who + ": y and w are not on one TDomain");
    }
    // Wake only for the slices around [t] (it only shrinks): what happens
    // elsewhere reaches [t] and [z] through those slices, or is CtcDeriv's.
    const TDomain& td = *y_.front()->tube().tdomain();
    const Interval t = args[0].domain->atom(args[0].range.first) & td.t0_tf();
    if (!t.is_empty()) {
      std::size_t first = 0, last = 0;
      slice_range(td, t, first, last, "ContractorNetwork::add(CtcEval)");
      const std::size_t lo = first > 0 ? first - 1 : 0, hi = std::min(last + 1, td.nb_slices() - 1);
      for (std::size_t r = 1 + z_args_; r < args.size(); ++r) watch_only(r, 2 * lo, 2 * (hi - lo + 1) + 1);
    }
  }
  std::string name() const override { return "CtcEval"; }

  bool run(NodeRun& r) const override {
    Domain& td = *r.domains[ranges()[0].domain];
    const Interval t0 = td.atom(ranges()[0].first);
    Interval t = t0;
    IntervalVector z(nb_z_);
    std::size_t c = 0;
    for (std::size_t a = 1; a <= z_args_; ++a) {
      for (std::size_t j = 0; j < ranges()[a].count; ++j) z[c++] = r.domains[ranges()[a].domain]->atom(ranges()[a].first + j);
    }
    const IntervalVector z0 = z;
    std::vector<Tube*> ys;
    std::vector<const Tube*> ws;
    for (const auto& y : y_) ys.push_back(&y->tube());
    for (const auto& w : w_) ws.push_back(&w->tube());
    std::vector<std::vector<std::size_t>> changed;
    const bool ok = ctc_.contract(t, z, ys, ws, r.ratio, changed);
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
    for (std::size_t i = 0; i < y_.size(); ++i) {
      for (const std::size_t a : changed[i]) r.changed.push_back(offset(1 + z_args_ + i) + a);
    }
    if (!ok) locate_empty(r, t0);
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
    r.empty_at = offset(1 + z_args_) + 2 * first + 1;
  }

  CtcEval ctc_;
  std::size_t nb_z_ = 0, z_args_ = 0;
  std::vector<std::shared_ptr<TubeDomain>> y_, w_;
};

}  // namespace

std::shared_ptr<const CnNode> make_deriv_node(const CtcDeriv& ctc, const std::vector<BoundDomain>& args) {
  return std::make_shared<PairNode<CtcDeriv>>(ctc, args);
}

std::shared_ptr<const CnNode> make_increment_node(const CtcIncrement& ctc, const std::vector<BoundDomain>& args) {
  return std::make_shared<PairNode<CtcIncrement>>(ctc, args);
}

std::shared_ptr<const CnNode> make_eval_node(const CtcEval& ctc, const std::vector<BoundDomain>& args) {
  return std::make_shared<EvalNode>(ctc, args);
}

}  // namespace sillage
