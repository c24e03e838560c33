#include "sillage/dynamics/ctc_qeval.h"

#include <string>

#include "sillage/ctc/q_inter.h"
#include "sillage/ctc/shrink.h"
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
    if (!obs[i].t.intersects(x.tdomain()->t0_tf())) {
      throw Error("CtcQEval::contract: the time " + obs[i].t.str() + " of observation " + std::to_string(i) +
                  " does not meet the time domain " + x.tdomain()->t0_tf().str());
    }
    if (obs[i].ctc && obs[i].ctc->nb_vars() != x.size()) {
      throw DimensionError("CtcQEval::contract: the contractor of observation " + std::to_string(i) + " (" +
                           obs[i].ctc->name() + ") acts on " + std::to_string(obs[i].ctc->nb_vars()) +
                           " variables, the tube has " + std::to_string(x.size()));
    }
  }
}

// Contracts y by one observation alone: CtcEval alternated with the
// constraint on z until z stops shrinking (shrink.h); false if inconsistent.
bool contract_alone(const CtcEval& eval, const TubeObservation& o, TubeVector& y, const TubeVector& v) {
  Interval t = o.t & y.tdomain()->t0_tf();  // not empty (checked)
  IntervalVector z = o.z;
  while (true) {
    const IntervalVector before = z;
    if (o.ctc) {
      o.ctc->contract(z);
      z &= before;  // a contractor never enlarges; guard against one that would
    }
    if (z.is_empty() || !eval.contract(t, z, y, v)) return false;
    if (!o.ctc || !shrank(before, z, 0.01)) return !y.is_empty();
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
    live[i] = contract_alone(eval, obs[i], copies[i], v);
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
