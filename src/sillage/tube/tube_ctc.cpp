#include "sillage/tube/tube_ctc.h"

#include <string>

#include "sillage/error.h"

namespace sillage {

namespace {

void check_tubes(const Ctc& ctc, const std::vector<Tube*>& x) {
  const std::string where = "contract(" + ctc.name() + ", tubes)";
  if (x.size() != ctc.nb_vars()) {
    throw DimensionError(where + ": " + std::to_string(x.size()) + " tubes for a contractor on " +
                         std::to_string(ctc.nb_vars()) + " variables");
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!x[i]) throw Error(where + ": tube " + std::to_string(i) + " is null");
    if (x[i]->tdomain() != x[0]->tdomain()) {
      throw DimensionError(where + ": tube " + std::to_string(i) + " is not on the TDomain of tube 0");
    }
    // Aliasing would let the contraction of one variable overwrite another.
    for (std::size_t j = 0; j < i; ++j) {
      if (&x[i]->data() == &x[j]->data()) {
        throw Error(where + ": tubes " + std::to_string(j) + " and " + std::to_string(i) +
                    " are the same tube (use one variable)");
      }
    }
  }
}

void set_all_empty(const std::vector<Tube*>& x) {
  for (Tube* xi : x) {
    TubeData& d = xi->data();
    bool changed = false;
    for (auto* array : {&d.slices, &d.gates}) {
      for (Interval& v : *array) {
        changed = changed || !v.is_empty();
        v.set_empty();
      }
    }
    if (changed) xi->touch();
  }
}

// The box contraction used on every slice and gate: HC4 of f(x) ∈ y without
// a virtual call, or any contractor. False when the box is proven empty.
struct HC4 {
  const Function& f;
  const IntervalVector& y;
  bool operator()(IntervalVector& x) const { return f.hc4_revise(x, y); }
};
struct AnyCtc {
  const Ctc& c;
  bool operator()(IntervalVector& x) const {
    c.contract(x);
    return !x.is_empty();
  }
};

// Contracts the box of the k-th elements of `arrays` (slices or gates);
// writes back and records changes. False if proven empty.
template <class Op>
bool contract_column(const Op& op, std::vector<std::vector<Interval>*>& arrays, std::size_t k, IntervalVector& buf,
                     std::vector<char>& changed) {
  const std::size_t n = arrays.size();
  for (std::size_t i = 0; i < n; ++i) buf[i] = (*arrays[i])[k];
  if (!op(buf)) return false;
  for (std::size_t i = 0; i < n; ++i) {
    Interval& v = (*arrays[i])[k];
    if (!(buf[i] == v)) {
      v = buf[i];
      changed[i] = 1;
    }
  }
  return true;
}

template <class Op>
bool contract_tubes(const Op& op, const std::vector<Tube*>& x) {
  const std::size_t n = x.size();
  if (n == 0) return true;  // no variable: nothing to contract
  const std::size_t N = x[0]->nb_slices();

  std::vector<std::vector<Interval>*> slices(n), gates(n);
  std::vector<char> changed(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    slices[i] = &x[i]->data().slices;
    gates[i] = &x[i]->data().gates;
    if (x[i]->is_empty()) {
      set_all_empty(x);
      return false;
    }
  }

  IntervalVector buf(n);
  bool ok = true;
  for (std::size_t k = 0; k < N && ok; ++k) ok = contract_column(op, slices, k, buf, changed);
  // Gates: x(t_k) is in both neighbouring slices, then in f^-1(y).
  for (std::size_t k = 0; k <= N && ok; ++k) {
    for (std::size_t i = 0; i < n && ok; ++i) {
      Interval& g = (*gates[i])[k];
      Interval h = g;
      if (k > 0) h &= (*slices[i])[k - 1];
      if (k < N) h &= (*slices[i])[k];
      if (!(h == g)) {
        g = h;
        changed[i] = 1;
      }
      ok = !g.is_empty();
    }
    if (ok) ok = contract_column(op, gates, k, buf, changed);
  }
  if (!ok) {
    set_all_empty(x);
    return false;
  }
  for (std::size_t i = 0; i < n; ++i)
    if (changed[i]) x[i]->touch();
  return true;
}

std::vector<Tube*> components(TubeVector& x) {
  std::vector<Tube*> p(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) p[i] = &x[i];
  return p;
}

}  // namespace

bool contract(const CtcFunction& ctc, const std::vector<Tube*>& x) {
  check_tubes(ctc, x);
  return contract_tubes(HC4{ctc.function(), ctc.image()}, x);
}

bool contract(const Ctc& ctc, const std::vector<Tube*>& x) {
  if (const auto* f = dynamic_cast<const CtcFunction*>(&ctc)) return contract(*f, x);
  check_tubes(ctc, x);
  return contract_tubes(AnyCtc{ctc}, x);
}

bool contract(const CtcFunction& ctc, TubeVector& x) { return contract(ctc, components(x)); }
bool contract(const Ctc& ctc, TubeVector& x) { return contract(ctc, components(x)); }

}  // namespace sillage
