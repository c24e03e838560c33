#include "sillage/tube/tube_ctc.h"

#include <algorithm>
#include <string>

#include "sillage/error.h"
#include "sillage/tube/time_box_ctc.h"

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

// The box contractor at every slice and gate (time_box_ctc.h); on
// emptiness (on input or proven) every tube is set empty. An empty element
// on input needs no scan of its own: the box holding it is proven empty.
bool contract_tubes(const Ctc& ctc, const std::vector<Tube*>& x) {
  if (x.empty()) return true;  // no variable: nothing to contract
  std::vector<detail::TimeVar> vars;
  for (Tube* xi : x) vars.push_back({xi, 0});
  std::vector<std::size_t> atoms(2 * x[0]->nb_slices() + 1);
  for (std::size_t i = 0; i < atoms.size(); ++i) atoms[i] = i;
  IntervalVector no_params(1);
  const bool ok = detail::contract_time_elements(ctc, vars, atoms, no_params, {}) == detail::kNoTimeAtom;
  if (!ok) {
    const auto empty = [](const Interval& v) { return v.is_empty(); };
    for (Tube* xi : x) {  // touched only if not already the empty tube
      if (!std::all_of(xi->slices().begin(), xi->slices().end(), empty) ||
          !std::all_of(xi->gates().begin(), xi->gates().end(), empty)) {
        xi->set(Interval::empty());
      }
    }
  }
  return ok;
}

std::vector<Tube*> components(TubeVector& x) {
  std::vector<Tube*> p(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) p[i] = &x[i];
  return p;
}

}  // namespace

bool contract(const CtcFunction& ctc, const std::vector<Tube*>& x) {
  check_tubes(ctc, x);
  return contract_tubes(ctc, x);
}

bool contract(const Ctc& ctc, const std::vector<Tube*>& x) {
  if (const auto* f = dynamic_cast<const CtcFunction*>(&ctc)) return contract(*f, x);
  check_tubes(ctc, x);
  return contract_tubes(ctc, x);
}

bool contract(const CtcFunction& ctc, TubeVector& x) { return contract(ctc, components(x)); }
bool contract(const Ctc& ctc, TubeVector& x) { return contract(ctc, components(x)); }

}  // namespace sillage
