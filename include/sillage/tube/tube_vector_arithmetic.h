#pragma once
// Component-wise arithmetic on tube vectors, and their inversion.
//
// x op y with y a TubeVector or a box: component i is x[i] op y[i] (like
// numpy; DimensionError if the sizes differ); with y a Tube or an Interval:
// every component op y. Rigorous as the scalar tube arithmetic
// (tube_arithmetic.h); DimensionError if TDomains differ.
#include "sillage/interval/interval.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace sillage {

// The TubeVector (f(0), ..., f(n-1)), f(i) a Tube (n >= 1, one TDomain).
template <class F>
TubeVector componentwise(std::size_t n, F f) {
  std::vector<Tube> xs;
  xs.reserve(n);
  for (std::size_t i = 0; i < n; ++i) xs.push_back(f(i));
  return TubeVector(std::move(xs));
}

TubeVector operator-(const TubeVector& x);

#define SILLAGE_TV_DECLARE(op)                                         \
  TubeVector operator op(const TubeVector& x, const TubeVector& y);    \
  TubeVector operator op(const TubeVector& x, const IntervalVector& y); \
  TubeVector operator op(const IntervalVector& x, const TubeVector& y); \
  TubeVector operator op(const TubeVector& x, const Tube& y);          \
  TubeVector operator op(const Tube& x, const TubeVector& y);          \
  TubeVector operator op(const TubeVector& x, const Interval& y);      \
  TubeVector operator op(const Interval& x, const TubeVector& y);
SILLAGE_TV_DECLARE(+)
SILLAGE_TV_DECLARE(-)
SILLAGE_TV_DECLARE(*)
SILLAGE_TV_DECLARE(/)
#undef SILLAGE_TV_DECLARE

// Hull of the times t where the box [x](t) meets y, every component at once
// (slices contribute their whole domain, gates their time point): a subset of
// the intersection of the components' inverses. Empty if none.
// DimensionError if the sizes differ.
Interval inverse(const TubeVector& x, const IntervalVector& y);

}  // namespace sillage
