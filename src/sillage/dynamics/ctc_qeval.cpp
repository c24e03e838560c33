#include "sillage/dynamics/ctc_qeval.h"

#include <string>

#include "sillage/cn/tube_node.h"
#include "sillage/ctc/q_inter.h"
#include "sillage/ctc/q_inter_columns.h"
#include "sillage/ctc/shrink.h"
#include "sillage/dynamics/ctc_eval.h"

namespace sillage {

namespace {

void check_observations(const TubeVector& x, const TubeVector& v, const std::vector<TubeObservation>& obs) {
  if (v.size() != x.size() || v.tdomain() != x.tdomain()) {
    throw DimensionError("CtcQEval::contract: the derivative tube must have the size (" + std::to_string(x.size()) +
                         ") and the TDomain of the tube");
  }
  detail::check_observation_list(x.size(), x.tdomain()->t0_tf(), obs, "CtcQEval::contract");
}

// Contracts by one observation alone: `eval(t, z)` (CtcEval on the tube)
// alternated with the constraint on z until z stops shrinking (shrink.h);
// false if inconsistent.
template <class Eval>
bool contract_alone(const TubeObservation& o, const Interval& domain, Eval eval) {
  Interval t = o.t & domain;  // not empty (checked)
  IntervalVector z = o.z;
  while (true) {
    const IntervalVector before = z;
    if (o.ctc) {
      o.ctc->contract(z);
      z &= before;  // a contractor never enlarges; guard against one that would
    }
    if (z.is_empty() || !eval(t, z)) return false;
    if (!o.ctc || !shrank(before, z, 0.01)) return true;
  }
}

// Atom a of a tube: gate a / 2 when a is even, slice a / 2 when odd.
const Interval& atom_of(const TubeData& d, std::size_t a) { return a % 2 == 0 ? d.gates[a / 2] : d.slices[a / 2]; }

}  // namespace

CtcQEval::CtcQEval(int q) : q_(q) { check_q(q, "CtcQEval"); }

CtcQEval::CtcQEval(int q, std::vector<TubeObservation> obs) : q_(q), obs_(std::move(obs)) {
  check_q(q, "CtcQEval");
  if (obs_.empty()) throw Error("CtcQEval(q, obs): needs at least one observation");
}

std::vector<std::size_t> CtcQEval::contract(TubeVector& x, const TubeVector& v,
                                            const std::vector<TubeObservation>& obs) const {
  check_observations(x, v, obs);
  std::vector<std::size_t> violated;
  if (x.is_empty()) return violated;
  CtcEval eval;
  eval.enable_time_sampling(false);  // the copy and x share the TDomain
  // One copy y of x, contracted by each observation in turn; each atom's
  // values go to its column (component j, atom a: j * atoms + a).
  const std::size_t n = x.size(), atoms = 2 * x[0].nb_slices() + 1;
  detail::QInterColumns columns(n * atoms, q_);
  TubeVector y = x;
  for (std::size_t i = 0; i < obs.size(); ++i) {
    if (i > 0) y = x;
    const bool live = contract_alone(obs[i], x.tdomain()->t0_tf(), [&](Interval& t, IntervalVector& z) {
      return eval.contract(t, z, y, v) && !y.is_empty();
    });
    if (!live) {
      violated.push_back(i);
      continue;
    }
    for (std::size_t j = 0; j < n; ++j) {
      for (std::size_t a = 0; a < atoms; ++a) columns.add(j * atoms + a, atom_of(y[j].data(), a));
    }
  }
  if (static_cast<std::size_t>(q_) >= obs.size()) return violated;
  // A value must lie in m - q of the copies, the violated ones holding none.
  if (violated.size() > static_cast<std::size_t>(q_)) {
    x.set(IntervalVector::empty(n));
    return violated;
  }
  const int allowed = q_ - static_cast<int>(violated.size());
  for (std::size_t j = 0; j < n; ++j) {
    const Tube::Writer w = x[j].write();  // intersected in place, as Tube::operator&= does
    for (std::size_t a = 0; a < atoms; ++a) w.atom(a) &= columns.hull(j * atoms + a, allowed);
  }
  if (x.is_empty()) x.set(IntervalVector::empty(n));  // no trajectory left anywhere
  return violated;
}

// The network form.
namespace {

// cn.add(CtcQEval(q, obs), {x, v}): x and v tubes of one size n.
class QEvalNode : public TubeNode {
 public:
  QEvalNode(const CtcQEval& ctc, const std::vector<BoundDomain>& args) : TubeNode("CtcQEval", args), ctc_(ctc) {
    if (args.empty() || args.size() % 2 != 0) {
      throw DimensionError(where() + ": expects x and v with as many components, got " + std::to_string(args.size()) +
                           " tubes");
    }
    x_ = whole_tubes(0, args.size() / 2, "x");
    v_ = whole_tubes(args.size() / 2, args.size() / 2, "v");
    detail::check_observation_list(x_.size(), x_[0]->tube().tdomain()->t0_tf(), ctc_.observations(), where());
  }

  // Naming, after an emptiness, the fixes no trajectory satisfied.
  std::string describe() const override {
    const auto& obs = ctc_.observations();
    const std::string q = "q = " + std::to_string(ctc_.q());
    if (bad_.empty()) return "CtcQEval (" + q + ", " + std::to_string(obs.size()) + " fixes)";
    std::string s = "CtcQEval (" + q + ": " + std::to_string(bad_.size()) + " of its " + std::to_string(obs.size()) +
                    " fixes violated by every trajectory:";
    for (std::size_t k = 0; k < bad_.size() && k < 5; ++k) {
      const std::string& name = obs[bad_[k]].name;
      s += (k ? ", " : " ") + (name.empty() ? "fix " + std::to_string(bad_[k]) : name);
    }
    return s + (bad_.size() > 5 ? ", ...)" : ")");
  }

  bool run(NodeRun& r) const override {
    const auto& obs = ctc_.observations();
    const std::size_t m = obs.size(), n = x_.size();
    bad_.clear();
    if (static_cast<std::size_t>(ctc_.q()) >= m) return true;
    std::vector<Tube> work;  // x, contracted by one observation at a time and restored
    std::vector<Tube*> y;
    std::vector<const Tube*> w;
    for (std::size_t j = 0; j < n; ++j) work.push_back(x_[j]->tube()), w.push_back(&v_[j]->tube());
    for (auto& t : work) y.push_back(&t);
    CtcEval eval;
    eval.enable_time_sampling(false);  // the network's layout is fixed
    std::vector<std::vector<std::size_t>> changed(n);
    std::vector<TubeChanges> logs;
    for (auto& c : changed) logs.emplace_back(c, 0, 0.0);  // ratio 0: every change
    // One column per atom (component j, atom a: j * atoms + a) of the values
    // the observations that changed it left.
    const std::size_t atoms = 2 * work[0].nb_slices() + 1;
    thread_local detail::QInterColumns columns;  // scratch, per thread (a run never enters another): no page faults per run
    thread_local std::vector<std::size_t> seen_by;  // the last observation that added to each column
    columns.reset(n * atoms, ctc_.q());
    seen_by.assign(n * atoms, m);
    std::size_t violated = 0;
    const Interval domain = work[0].tdomain()->t0_tf();
    for (std::size_t i = 0; i < m; ++i) {
      for (auto& c : changed) c.clear();
      const bool live = contract_alone(obs[i], domain, [&](Interval& t, IntervalVector& z) {
        return eval.contract(t, z, y, w, logs);
      });
      for (std::size_t j = 0; j < n; ++j) {
        const TubeData& x = x_[j]->tube().data();
        if (!live) {  // CtcEval emptied the copy: start again from x
          work[j] = x_[j]->tube();
          continue;
        }
        const Tube::Writer d = work[j].write();
        for (const std::size_t a : changed[j]) {
          const std::size_t col = j * atoms + a;
          if (seen_by[col] == i) continue;  // logged again by a later pass of the same observation
          seen_by[col] = i;
          columns.add(col, d.atom(a));
          d.atom(a) = atom_of(x, a);
        }
      }
      violated += !live;
      if (!live) bad_.push_back(i);
    }
    // More than q observations violated by every trajectory of x: none is left.
    if (violated > static_cast<std::size_t>(ctc_.q())) return inconsistent(r);
    // Atom by atom: the L - c live observations that left it whole hold all of it; a value
    // must lie in m - q observations, so in need = (m - q) - (L - c) of the c that changed it,
    // that is, at most q - violated of those c may exclude it.
    const int allowed = ctc_.q() - static_cast<int>(violated);
    bool ok = true;
    std::vector<Tube::Writer> xw;  // every x is marked modified, as before the writers
    for (auto& x : x_) xw.push_back(x->tube().write());
    for (std::size_t j = 0; j < n && ok; ++j) {
      for (std::size_t a = 0; a < atoms; ++a) {
        const std::size_t col = j * atoms + a;
        if (columns.count(col) <= static_cast<std::size_t>(allowed)) continue;
        Interval& atom = xw[j].atom(a);
        const Interval before = atom;
        atom &= columns.hull(col, allowed);
        changes(r, j).atom(a, before, atom);
        if (atom.is_empty()) {
          r.empty_at = offset(j) + a;
          ok = false;
          break;
        }
      }
    }
    xw.clear();
    if (!ok) return empty_tubes(r, 0, x_.size());
    return true;
  }

 private:
  // x emptied, the network told where: the first slice of the first fix violated.
  bool inconsistent(NodeRun& r) const {
    const TDomain& td = *x_.front()->tube().tdomain();
    const Interval t = ctc_.observations()[bad_.front()].t & td.t0_tf();
    std::size_t first = 0, last = 0;
    slice_range(td, t, first, last, "ContractorNetwork(CtcQEval)");
    r.empty_at = offset(0) + slice_atom(first);
    r.empty_time = t;
    return empty_tubes(r, 0, x_.size());
  }

  mutable std::vector<std::size_t> bad_;  // the fixes the last run found violated by every trajectory
  CtcQEval ctc_;
  std::vector<std::shared_ptr<TubeDomain>> x_, v_;
};

}  // namespace

std::shared_ptr<const CnNode> CtcQEval::make_node(const std::vector<BoundDomain>& args) const {
  if (obs_.empty()) {
    throw Error("ContractorNetwork::add(CtcQEval): the network form needs the observations: CtcQEval(q, obs)");
  }
  return std::make_shared<QEvalNode>(*this, args);
}

}  // namespace sillage
