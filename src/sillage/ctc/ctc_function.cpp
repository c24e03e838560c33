#include "sillage/ctc/ctc_function.h"

namespace sillage {

namespace {

const IntervalVector& checked_image(const Function& f, const IntervalVector& y, const char* where) {
  if (y.size() != f.image_dim()) {
    throw DimensionError(std::string(where) + ": the image box has size " + std::to_string(y.size()) +
                         " but the function " + f.str() + " has " + std::to_string(f.image_dim()) + " outputs");
  }
  return y;
}

}  // namespace

CtcFunction::CtcFunction(const Function& f, const IntervalVector& y)
    : Ctc(f.nb_vars()), f_(f), y_(checked_image(f, y, "CtcFunction")) {}

CtcFunction::CtcFunction(const Function& f, const Interval& y) : CtcFunction(f, IntervalVector{y}) {}

CtcFunction::CtcFunction(const Function& f) : CtcFunction(f, IntervalVector(f.image_dim(), Interval(0.0))) {}

void CtcFunction::contract(IntervalVector& x) const {
  check_dim(x);
  if (x.is_empty()) return x.set_empty();
  if (!f_.hc4_revise(x, y_) || x.is_empty()) x.set_empty();
}

}  // namespace sillage
