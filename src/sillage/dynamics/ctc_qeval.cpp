#include "sillage/dynamics/ctc_qeval.h"

#include <string>

#include "sillage/ctc/q_inter.h"
#include "sillage/dynamics/ctc_eval.h"

namespace sillage {

namespace {

void check_observations(const TubeVector& x, const TubeVector& v, const std::vector<TubeObservation>& obs) {
  if (obs.empty()) throw Error("CtcQEval::contract: needs at least one observation");
  if (v.size() != x.size() || v.tdomain() != x.tdomain()) {
    throw DimensionError("CtcQEval::contract: the derivative tube must have the size (" + std::to_string(x.size()) +
                         ") and the TDomain of the tube");
  }
  for (std::size_t i = 0; i < obs.size(); ++i) {
    if (obs[i].z.size() != x.size()) {
      throw DimensionError("CtcQEval::contract: observation " + std::to_string(i) + " has " +
                           std::to_string(obs[i].z.size()) + " components, the tube " + std::to_string(x.size()));
    }
  }
}

// The q-relaxed intersection of the atoms (gate or slice k of component j)
// read by `atom` on the copies; empty copies count as violated constraints.
template <class Atom>
Interval relaxed_atom(const std::vector<TubeVector>& copies, const std::vector<bool>& live, int q, Atom atom) {
  std::vector<Interval> column(copies.size(), Interval::empty());
  for (std::size_t i = 0; i < copies.size(); ++i) {
    if (live[i]) column[i] = atom(copies[i]);
  }
  return q_inter(column, q);
}

}  // namespace

CtcQEval::CtcQEval(int q) : q_(q) { check_q(q, "CtcQEval"); }

std::vector<std::size_t> CtcQEval::contract(TubeVector& x, const TubeVector& v,
                                            const std::vector<TubeObservation>& obs) const {
  check_observations(x, v, obs);
  std::vector<std::size_t> violated;
  if (x.is_empty()) return violated;
  CtcEval eval;
  eval.enable_time_sampling(false);  // the copies and x share the TDomain
  std::vector<TubeVector> copies(obs.size(), x);
  std::vector<bool> live(obs.size());
  for (std::size_t i = 0; i < obs.size(); ++i) {
    Interval t = obs[i].t & Interval(x.tdomain()->t0(), x.tdomain()->tf());
    IntervalVector z = obs[i].z;
    live[i] = !t.is_empty() && eval.contract(t, z, copies[i], v) && !copies[i].is_empty();
    if (!live[i]) violated.push_back(i);
  }
  if (static_cast<std::size_t>(q_) >= obs.size()) return violated;
  for (std::size_t j = 0; j < x.size(); ++j) {
    TubeData& d = x[j].data();  // intersected in place, as Tube::operator&= does
    for (std::size_t k = 0; k < d.gates.size(); ++k) {
      d.gates[k] &= relaxed_atom(copies, live, q_, [&](const TubeVector& c) { return c[j].gate(k); });
    }
    for (std::size_t k = 0; k < d.slices.size(); ++k) {
      d.slices[k] &= relaxed_atom(copies, live, q_, [&](const TubeVector& c) { return c[j].slice(k); });
    }
    x[j].touch();
  }
  if (x.is_empty()) x.set(IntervalVector::empty(x.size()));  // no trajectory left anywhere
  return violated;
}

}  // namespace sillage
