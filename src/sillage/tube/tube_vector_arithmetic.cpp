#include "sillage/tube/tube_vector_arithmetic.h"

#include <string>
#include <utility>
#include <vector>

#include "sillage/error.h"
#include "sillage/tube/tube_arithmetic.h"

namespace sillage {

namespace {
void check_sizes(std::size_t a, std::size_t b, const char* op) {
  check_same_size(a, b, (std::string("TubeVector ") + op).c_str());  // interval_vector.h
}
}  // namespace

TubeVector operator-(const TubeVector& x) {
  return componentwise(x.size(), [&](std::size_t i) { return -x[i]; });
}

#define SILLAGE_TV_DEFINE(op)                                                                  \
  TubeVector operator op(const TubeVector& x, const TubeVector& y) {                           \
    check_sizes(x.size(), y.size(), #op);                                                      \
    return componentwise(x.size(), [&](std::size_t i) { return x[i] op y[i]; });               \
  }                                                                                            \
  TubeVector operator op(const TubeVector& x, const IntervalVector& y) {                       \
    check_sizes(x.size(), y.size(), #op);                                                      \
    return componentwise(x.size(), [&](std::size_t i) { return x[i] op y[i]; });               \
  }                                                                                            \
  TubeVector operator op(const IntervalVector& x, const TubeVector& y) {                       \
    check_sizes(x.size(), y.size(), #op);                                                      \
    return componentwise(y.size(), [&](std::size_t i) { return x[i] op y[i]; });               \
  }                                                                                            \
  TubeVector operator op(const TubeVector& x, const Tube& y) {                                 \
    return componentwise(x.size(), [&](std::size_t i) { return x[i] op y; });                  \
  }                                                                                            \
  TubeVector operator op(const Tube& x, const TubeVector& y) {                                 \
    return componentwise(y.size(), [&](std::size_t i) { return x op y[i]; });                  \
  }                                                                                            \
  TubeVector operator op(const TubeVector& x, const Interval& y) {                             \
    return componentwise(x.size(), [&](std::size_t i) { return x[i] op y; });                  \
  }                                                                                            \
  TubeVector operator op(const Interval& x, const TubeVector& y) {                             \
    return componentwise(y.size(), [&](std::size_t i) { return x op y[i]; });                  \
  }
SILLAGE_TV_DEFINE(+)
SILLAGE_TV_DEFINE(-)
SILLAGE_TV_DEFINE(*)
SILLAGE_TV_DEFINE(/)
#undef SILLAGE_TV_DEFINE

Interval inverse(const TubeVector& x, const IntervalVector& y) {
  check_sizes(x.size(), y.size(), "inverse");
  const TDomain& td = *x.tdomain();
  const auto meets = [&](std::size_t k, bool gate) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Interval& v = gate ? x[i].gate(k) : x[i].slice(k);
      if ((v & y[i]).is_empty()) return false;
    }
    return true;
  };
  Interval h = Interval::empty();
  for (std::size_t k = 0; k <= x.nb_slices(); ++k) {
    if (meets(k, true)) h |= Interval(td.t(k));
    if (k < x.nb_slices() && meets(k, false)) h |= td.slice_domain(k);
  }
  return h;
}

}  // namespace sillage
