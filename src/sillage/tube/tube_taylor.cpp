#include "sillage/tube/tube_taylor.h"

#include <string>

#include "sillage/error.h"
#include "sillage/tube/tube_arithmetic.h"

namespace sillage {

std::vector<Interval> taylor_increments(const Tube& w, const Tube& dw, const Interval& noise) {
  if (w.tdomain() != dw.tdomain()) throw DimensionError("taylor_increments: w and dw are not on one TDomain");
  const TDomain& td = *w.tdomain();
  const Interval half(0.5);
  std::vector<Interval> inc(td.nb_slices());
  for (std::size_t k = 0; k < inc.size(); ++k) {
    const Interval d = td.slice_width(k);
    const Interval curve = sqr(d) * half * dw.slice(k);
    inc[k] = (d * (w.gate(k) + noise) + curve) & (d * (w.gate(k + 1) + noise) - curve) & (d * (w.slice(k) + noise));
  }
  return inc;
}

Tube primitive_from_increments(const Tube& x, const std::vector<Interval>& increments, const Interval& x0,
                               const std::vector<Interval>& gates) {
  const TDomain& td = *x.tdomain();
  const std::size_t n = td.nb_slices();
  if (increments.size() != n) {
    throw DimensionError("primitive_from_increments: " + std::to_string(increments.size()) + " increments for " +
                         std::to_string(n) + " slices");
  }
  if (!gates.empty() && gates.size() != n + 1) {
    throw DimensionError("primitive_from_increments: " + std::to_string(gates.size()) + " gates for " +
                         std::to_string(n) + " slices (N+1 expected, or none)");
  }
  std::vector<Interval> g = gates.empty() ? std::vector<Interval>(n + 1) : gates;
  g[0] &= x0;
  for (std::size_t k = 0; k < n; ++k) g[k + 1] &= g[k] + increments[k];
  for (std::size_t k = n; k-- > 0;) g[k] &= g[k + 1] - increments[k];
  std::vector<Interval> s(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Interval span = Interval(0, td.slice_width(k).ub()) * x.slice(k);
    s[k] = (g[k] + span) & (g[k + 1] - span);
  }
  for (std::size_t k = 0; k <= n; ++k) {
    if (k > 0) g[k] &= s[k - 1];
    if (k < n) g[k] &= s[k];
  }
  return Tube(x.tdomain(), s, g);
}

Tube primitive_taylor(const Tube& w, const Tube& dw, const Interval& x0, const Interval& noise) {
  return primitive_from_increments(w + noise, taylor_increments(w, dw, noise), x0);
}

}  // namespace sillage
