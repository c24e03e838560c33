#include "sillage/dynamics/ctc_eval_angle.h"

#include <span>

#include "sillage/cn/tube_node.h"
#include "sillage/ctc/shrink.h"
#include "sillage/dynamics/deriv_sweep.h"
#include "sillage/error.h"
#include "sillage/interval/angle.h"

namespace sillage {

bool CtcEvalAngle::contract(const Interval& t, Interval& z, Tube& x, const Tube& v) const {
  return contract(t, z, x, v, TubeChanges());
}

bool CtcEvalAngle::contract(const Interval& t, Interval& z, Tube& x, const Tube& v, const TubeChanges& changes) const {
  detail::check_deriv_pair(x, v, "CtcEvalAngle::contract(t, z, x, v)");
  const TDomain& td = *x.tdomain();
  const Interval tt = t & td.t0_tf();
  if (tt.is_empty()) return true;  // a time outside the domain says nothing about it
  std::size_t first = 0, last = 0;
  slice_range(td, tt, first, last, "CtcEvalAngle::contract(t, z, x, v)");
  Interval rate = Interval::empty();
  for (std::size_t k = first; k <= last; ++k) rate |= v.slice(k);
  const bool moves = !rate.is_unbounded() && !rate.is_empty();
  bool ok = !z.is_empty() && !x.is_empty();
  bool changed = false;
  {
    Tube::Writer w = x.write();
    const std::span<Interval> s = w.slices(), g = w.gates();
    if (ok && moves) {
      z = angle_meet(z, g[first] + rate * (tt - Interval(td.t(first))));
      z = angle_meet(z, g[last + 1] - rate * (Interval(td.t(last + 1)) - tt));
    }
    if (first == last) z = angle_meet(z, s[first]);
    ok = ok && !z.is_empty();
    const auto meet = [&](Interval& cur, const Interval& arc, std::size_t atom) {
      const Interval was = cur;
      cur = angle_meet(cur, arc);
      if (cur != was) changed = true, changes.atom(atom, was, cur);
      ok = ok && !cur.is_empty();
    };
    if (ok && moves) {
      for (std::size_t j = first; j <= last + 1; ++j) meet(g[j], z + rate * (Interval(td.t(j)) - tt), 2 * j);
      for (std::size_t k = first; k <= last; ++k) meet(s[k], z + rate * (td.slice_domain(k) - tt), 2 * k + 1);
    } else if (ok && first == last) {
      meet(s[first], z, 2 * first + 1);
    }
    w.commit(ok && changed);
  }
  if (!ok) {
    z = Interval::empty();
    x.set(Interval::empty());
  }
  return ok;
}

namespace {

// The node: (t, z, x, v), woken by the slices around [t] and by z.
class EvalAngleNode : public TubeNode {
 public:
  EvalAngleNode(const CtcEvalAngle& ctc, const std::vector<BoundDomain>& args)
      : TubeNode("CtcEvalAngle", args), ctc_(ctc) {
    if (args.size() != 4 || tube(0) || tube(1) || args[0].range.count != 1 || args[1].range.count != 1) {
      throw DimensionError(where() + ": expects (t, z, x, v) with t and z Intervals, x and v tubes");
    }
    x_ = whole_tubes(2, 1, "x").front();
    v_ = whole_tubes(3, 1, "v").front();
    const TDomain& td = *x_->tube().tdomain();
    const Interval t = args[0].domain->atom(args[0].range.first) & td.t0_tf();
    if (!t.is_empty()) {
      std::size_t first = 0, last = 0;
      slice_range(td, t, first, last, "ContractorNetwork::add(CtcEvalAngle)");
      for (std::size_t r = 2; r < 4; ++r) watch_only(r, gate_atom(first), slice_atom(last) - gate_atom(first) + 2);
    }
  }

  bool follows_appends() const override { return true; }

  bool run(NodeRun& r) const override {
    const Interval t = r.domains[ranges()[0].domain]->atom(ranges()[0].first);
    Domain& zd = *r.domains[ranges()[1].domain];
    const Interval z0 = zd.atom(ranges()[1].first);
    Interval z = z0;
    const bool ok = ctc_.contract(t, z, x_->tube(), v_->tube(), changes(r, 2));
    if (z != z0) zd.set_atom(ranges()[1].first, z);
    if (shrank(z0, z, r.ratio)) r.changed.push_back(offset(1));
    if (!ok) r.empty_time = t;
    return ok;
  }

 private:
  CtcEvalAngle ctc_;
  std::shared_ptr<TubeDomain> x_, v_;
};

}  // namespace

std::shared_ptr<const CnNode> CtcEvalAngle::make_node(const std::vector<BoundDomain>& args) const {
  return std::make_shared<EvalAngleNode>(*this, args);
}

}  // namespace sillage
