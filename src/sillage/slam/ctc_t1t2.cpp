#include "sillage/slam/ctc_t1t2.h"

#include <cmath>
#include <string>

#include "sillage/ctc/shrink.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/error.h"

namespace sillage {

namespace {

void check_args(const std::vector<Tube*>& p, const std::vector<const Tube*>& w, const std::vector<TubeChanges>& changes,
                const char* where) {
  if (p.empty()) throw DimensionError(std::string(where) + ": p has no component");
  if (w.size() != p.size()) {
    throw DimensionError(std::string(where) + ": p has " + std::to_string(p.size()) + " components, w " +
                         std::to_string(w.size()));
  }
  if (!changes.empty() && changes.size() != p.size()) {
    throw DimensionError(std::string(where) + ": " + std::to_string(changes.size()) + " change logs for " +
                         std::to_string(p.size()) + " components");
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p[i]->tdomain() != p[0]->tdomain() || w[i]->tdomain() != p[0]->tdomain()) {
      throw DimensionError(std::string(where) + ": p and w must share one TDomain (component " + std::to_string(i) +
                           " does not)");
    }
  }
}

// [p]([t]) with the derivative (the polygons inside the slices).
IntervalVector eval(const std::vector<Tube*>& p, const std::vector<const Tube*>& w, const Interval& t) {
  IntervalVector a(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) a[i] = p[i]->eval(t, *w[i]);
  return a;
}

bool set_empty(Interval& t1, Interval& t2, const std::vector<Tube*>& p) {
  t1.set_empty();
  t2.set_empty();
  for (Tube* pi : p) pi->set(Interval::empty());
  return false;
}

}  // namespace

CtcT1T2::CtcT1T2(double ratio, std::size_t max_passes) : ratio_(ratio), max_passes_(max_passes) {
  check_ratio(ratio, "CtcT1T2(ratio, max_passes)");
  if (max_passes == 0) throw Error("CtcT1T2(ratio, max_passes): max_passes must be at least 1");
}

bool CtcT1T2::contract(Interval& t1, Interval& t2, const std::vector<Tube*>& p, const std::vector<const Tube*>& w,
                       const std::vector<TubeChanges>& changes, std::size_t* passes) const {
  const char* where = "CtcT1T2::contract(t1, t2, p, w)";
  check_args(p, w, changes, where);
  if (passes) *passes = 0;
  const Interval dom = p[0]->tdomain()->t0_tf();
  if (std::isnan(t1.lb()) || std::isnan(t2.lb())) throw Error(std::string(where) + ": t1 or t2 is NaN");
  if (!t1.is_empty() && !t1.intersects(dom)) {
    throw Error(std::string(where) + ": [t1] = " + t1.str() + " does not meet the time domain " + dom.str());
  }
  if (!t2.is_empty() && !t2.intersects(dom)) {
    throw Error(std::string(where) + ": [t2] = " + t2.str() + " does not meet the time domain " + dom.str());
  }
  t1 &= dom;
  t2 &= dom;
  if (t1.is_empty() || t2.is_empty()) return set_empty(t1, t2, p);

  CtcEval ceval;
  ceval.enable_time_sampling(false);  // the TDomain is shared: never add gates here
  const std::vector<TubeChanges> none(p.size());
  const std::vector<TubeChanges>& logs = changes.empty() ? none : changes;

  IntervalVector a = eval(p, w, t1), b = eval(p, w, t2);
  for (std::size_t pass = 0; pass < max_passes_; ++pass) {
    if (passes) *passes = pass + 1;
    const Interval t1_before = t1, t2_before = t2;
    const IntervalVector a_before = a, b_before = b;
    // a = b: both evaluations meet.
    a &= b;
    if (a.is_empty()) return set_empty(t1, t2, p);
    if (!ceval.contract(t2, a, p, w, logs)) return set_empty(t1, t2, p);
    b = eval(p, w, t2) & a;
    if (b.is_empty()) return set_empty(t1, t2, p);
    if (!ceval.contract(t1, b, p, w, logs)) return set_empty(t1, t2, p);
    a = eval(p, w, t1) & b;
    b = eval(p, w, t2);
    if (a.is_empty() || b.is_empty()) return set_empty(t1, t2, p);
    const bool moved = shrank(t1_before, t1, ratio_) || shrank(t2_before, t2, ratio_) ||
                       shrank(a_before, a, ratio_) || shrank(b_before, b, ratio_);
    if (!moved) break;
  }
  return true;
}

bool CtcT1T2::contract(Interval& t1, Interval& t2, TubeVector& p, const TubeVector& w) const {
  if (p.size() != w.size()) {
    throw DimensionError("CtcT1T2::contract(t1, t2, p, w): p has " + std::to_string(p.size()) + " components, w " +
                         std::to_string(w.size()));
  }
  std::vector<Tube*> pp;
  std::vector<const Tube*> ww;
  for (std::size_t i = 0; i < p.size(); ++i) {
    pp.push_back(&p[i]);
    ww.push_back(&w[i]);
  }
  return contract(t1, t2, pp, ww, {});
}

bool CtcT1T2::contract(Interval& t1, Interval& t2, Tube& p, const Tube& w) const {
  return contract(t1, t2, std::vector<Tube*>{&p}, std::vector<const Tube*>{&w}, {});
}

}  // namespace sillage
