#include "sillage/slam/ctc_omega.h"

#include <algorithm>
#include <string>
#include <numeric>
#include <utility>

#include "sillage/cn/tube_changes.h"
#include "sillage/ctc/shrink.h"
#include "sillage/error.h"

namespace sillage {

namespace {

const Interval& atom_of(const Tube& x, std::size_t a) { return a % 2 == 0 ? x.gate(a / 2) : x.slice(a / 2); }

void check_boxes(const std::vector<IntervalVector>& boxes, const char* where) {
  for (std::size_t j = 0; j < boxes.size(); ++j) {
    if (boxes[j].size() != 2) {
      throw DimensionError(std::string(where) + ": t-box " + std::to_string(j) + " has " +
                           std::to_string(boxes[j].size()) + " components, 2 expected ([t1], [t2])");
    }
  }
}

}  // namespace

bool OmegaHull::apply_to(TubeVector& p, std::size_t* nb_shrunk, double ratio) const {
  if (empty) {
    if (nb_shrunk && !p.is_empty()) ++*nb_shrunk;
    for (std::size_t i = 0; i < p.size(); ++i) p[i].set(Interval::empty());
    return false;
  }
  std::vector<bool> touched(p.size(), false);
  std::vector<Tube::Writer> w;
  for (std::size_t i = 0; i < p.size(); ++i) w.push_back(p[i].write());
  for (const Atom& a : atoms) {
    Interval& x = w[a.component].atom(a.atom);
    const Interval y = x & a.value;
    if (y != x) {
      if (nb_shrunk && shrank(x, y, ratio)) ++*nb_shrunk;
      x = y;
      touched[a.component] = true;
    }
  }
  for (std::size_t i = 0; i < p.size(); ++i) w[i].commit(touched[i]);
  return !p.is_empty();
}

OmegaHull CtcOmega::hull(const std::vector<IntervalVector>& boxes, const TubeVector& p, const TubeVector& w,
                         TubeVector& work, const CancelToken& cancel) const {
  const char* where = "CtcOmega::hull(boxes, p, w, work)";
  check_boxes(boxes, where);
  if (work.size() != p.size() || work.tdomain() != p.tdomain() || work.nb_slices() != p.nb_slices()) {
    throw DimensionError(std::string(where) + ": work must be a copy of p");
  }
  const std::size_t n = p.size(), atoms_per_tube = 2 * p.nb_slices() + 1;
  std::vector<Tube*> wp;
  std::vector<const Tube*> ww;
  for (std::size_t i = 0; i < n; ++i) {
    wp.push_back(&work[i]);
    ww.push_back(&w[i]);
  }
  // The candidates: atoms every consistent box so far touched, whose hull is
  // still narrower than the reference (sorted by key). A later box can only
  // remove candidates (by not touching one, or by widening its hull to the
  // reference value), so once none is left after a consistent box the result
  // is known and the remaining boxes are skipped.
  std::vector<std::pair<std::size_t, Interval>> cand, next, met;
  std::vector<std::vector<std::size_t>> logged(n);
  OmegaHull out;
  out.nb_boxes = boxes.size();
  // The hull does not depend on the order of the boxes: visit them spread
  // over Ω (a golden-ratio stride) so that the hulls reach the reference, and
  // the candidates run out, after few boxes.
  const std::size_t m = boxes.size();
  std::size_t stride = std::max<std::size_t>(1, static_cast<std::size_t>(0.618034 * static_cast<double>(m)));
  while (std::gcd(stride, m) != 1) ++stride;
  for (std::size_t j = 0, idx = 0; j < m; ++j, idx = (idx + stride) % m) {
    const IntervalVector& box = boxes[idx];
    if (out.nb_consistent > 0 && cand.empty()) break;
    check_cancel(cancel, "CtcOmega::hull");
    for (auto& l : logged) l.clear();
    std::vector<TubeChanges> logs;
    for (auto& l : logged) logs.emplace_back(l, 0, 0.0);
    Interval t1 = box[0], t2 = box[1];
    if (t1.is_empty() || t2.is_empty()) continue;
    const bool ok = t1t2_.contract(t1, t2, wp, ww, logs);
    met.clear();
    for (std::size_t i = 0; i < n; ++i) {
      auto& l = logged[i];
      std::sort(l.begin(), l.end());
      l.erase(std::unique(l.begin(), l.end()), l.end());
      out.nb_touched += l.size();
      const Tube::Writer back = work[i].write();
      for (std::size_t a : l) {
        if (ok) met.emplace_back(i * atoms_per_tube + a, back.atom(a));
        back.atom(a) = atom_of(p[i], a);  // back to the reference
      }
    }
    // An inconsistent contraction empties the whole working tube (CtcEval,
    // Lemma 5.1): put all of it back.
    if (!ok) {
      work = p;
      continue;
    }
    const auto reference = [&](std::size_t key) -> const Interval& {
      return atom_of(p[key / atoms_per_tube], key % atoms_per_tube);
    };
    next.clear();
    if (out.nb_consistent++ == 0) {
      for (const auto& m : met)
        if (m.second != reference(m.first)) next.push_back(m);
    } else {  // met and cand are both sorted by key: intersect them
      auto c = cand.begin();
      for (const auto& m : met) {
        while (c != cand.end() && c->first < m.first) ++c;
        if (c == cand.end()) break;
        if (c->first != m.first) continue;
        const Interval h = c->second | m.second;
        if (h != reference(m.first)) next.emplace_back(m.first, h);
      }
    }
    cand.swap(next);
  }
  out.empty = out.nb_consistent == 0;
  if (out.empty) return out;
  for (const auto& [key, h] : cand) out.atoms.push_back({key / atoms_per_tube, key % atoms_per_tube, h});
  std::sort(out.atoms.begin(), out.atoms.end(), [](const OmegaHull::Atom& x, const OmegaHull::Atom& y) {
    return x.component != y.component ? x.component < y.component : x.atom < y.atom;
  });
  return out;
}

bool CtcOmega::contract(const std::vector<IntervalVector>& boxes, TubeVector& p, const TubeVector& w) const {
  check_boxes(boxes, "CtcOmega::contract(boxes, p, w)");
  if (p.size() != w.size()) {
    throw DimensionError("CtcOmega::contract(boxes, p, w): p has " + std::to_string(p.size()) + " components, w " +
                         std::to_string(w.size()));
  }
  TubeVector work = p;  // one scratch tube for all the boxes
  return hull(boxes, p, w, work).apply_to(p);
}

}  // namespace sillage
