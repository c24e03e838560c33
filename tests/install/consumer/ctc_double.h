#pragma once
// A contractor written outside sillage, on its public headers only:
// y(t) = 2 x(t), slice by slice and gate by gate.
#include <cstddef>
#include <vector>

#include "sillage/interval/interval.h"
#include "sillage/tube/tube.h"

class CtcDouble {
 public:
  void contract(sillage::Interval& x, sillage::Interval& y) const {
    y &= sillage::Interval(2.0) * x;
    x &= y / sillage::Interval(2.0);
  }

  void contract(sillage::Tube& x, sillage::Tube& y) const {
    const std::size_t n = x.nb_slices();
    std::vector<sillage::Interval> xs(n), ys(n), xg(n + 1), yg(n + 1);
    for (std::size_t k = 0; k < n; ++k) {
      xs[k] = x.slice(k);
      ys[k] = y.slice(k);
      contract(xs[k], ys[k]);
    }
    for (std::size_t k = 0; k <= n; ++k) {
      xg[k] = x.gate(k);
      yg[k] = y.gate(k);
      contract(xg[k], yg[k]);
    }
    x = sillage::Tube(x.tdomain(), xs, xg);
    y = sillage::Tube(y.tdomain(), ys, yg);
  }
};
