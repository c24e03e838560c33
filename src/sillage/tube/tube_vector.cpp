#include "sillage/tube/tube_vector.h"

#include <algorithm>
#include <ostream>

#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/interval/rounding.h"

namespace sillage {

namespace {

std::vector<Tube> constant_tubes(const std::shared_ptr<TDomain>& td, const IntervalVector& x) {
  if (x.size() == 0) throw DimensionError("TubeVector: at least one component is needed");
  std::vector<Tube> r;
  r.reserve(x.size());
  for (const auto& xi : x) r.emplace_back(td, xi);
  return r;
}

std::vector<Tube> function_tubes(const std::shared_ptr<TDomain>& td, const Function& f) {
  if (!td) throw Error("TubeVector(td, f): null TDomain");
  if (f.nb_vars() != 1) {
    throw DimensionError("TubeVector(td, f): f must be a function of one variable t, got " +
                         std::to_string(f.nb_vars()));
  }
  return detail::tubes_of_function(td, f);
}

}  // namespace

TubeVector::TubeVector(std::shared_ptr<TDomain> td, std::size_t n, const Interval& x)
    : x_(constant_tubes(td, IntervalVector(n, x))) {}

TubeVector::TubeVector(std::shared_ptr<TDomain> td, const IntervalVector& x) : x_(constant_tubes(td, x)) {}

TubeVector::TubeVector(std::shared_ptr<TDomain> td, const std::string& expr_of_t)
    : x_(function_tubes(td, Function({"t"}, expr_of_t))) {}

TubeVector::TubeVector(std::shared_ptr<TDomain> td, const Function& f) : x_(function_tubes(td, f)) {}

TubeVector::TubeVector(std::vector<Tube> components) : x_(std::move(components)) {
  if (x_.empty()) throw DimensionError("TubeVector(tubes): at least one component is needed");
  for (std::size_t i = 1; i < x_.size(); ++i) {
    if (x_[i].tdomain() != x_[0].tdomain()) {
      throw DimensionError("TubeVector(tubes): component " + std::to_string(i) + " is not on the TDomain of component 0");
    }
  }
}

void TubeVector::check_size(std::size_t n, const char* where) const {
  if (n != size()) {
    throw DimensionError(std::string(where) + ": size " + std::to_string(n) + " given, the tube vector has " +
                         std::to_string(size()));
  }
}

Tube& TubeVector::operator[](std::size_t i) {
  if (i >= size()) {
    throw OutOfRangeError("TubeVector[i]: index " + std::to_string(i) + " out of range for size " + std::to_string(size()));
  }
  return x_[i];
}

const Tube& TubeVector::operator[](std::size_t i) const { return const_cast<TubeVector&>(*this)[i]; }

std::shared_ptr<Tube> TubeVector::shared_component(std::size_t i) {
  (void)(*this)[i];  // OutOfRangeError when out of range
  return x_.shared(i);
}

TubeVector TubeVector::subvector(std::size_t i, std::size_t j) const {
  if (i > j || j >= size()) {
    throw DimensionError("TubeVector::subvector: invalid range [" + std::to_string(i) + ", " + std::to_string(j) +
                         "] for size " + std::to_string(size()));
  }
  return TubeVector(std::vector<Tube>(x_.begin() + static_cast<std::ptrdiff_t>(i),
                                      x_.begin() + static_cast<std::ptrdiff_t>(j) + 1));
}

IntervalVector TubeVector::slice(std::size_t k) const {
  IntervalVector r(size());
  for (std::size_t i = 0; i < size(); ++i) r[i] = x_[i].slice(k);
  return r;
}

IntervalVector TubeVector::gate(std::size_t k) const {
  IntervalVector r(size());
  for (std::size_t i = 0; i < size(); ++i) r[i] = x_[i].gate(k);
  return r;
}

IntervalVector TubeVector::operator()(double t) const {
  IntervalVector r(size());
  for (std::size_t i = 0; i < size(); ++i) r[i] = x_[i](t);
  return r;
}

IntervalVector TubeVector::operator()(const Interval& t) const {
  IntervalVector r(size());
  for (std::size_t i = 0; i < size(); ++i) r[i] = x_[i](t);
  return r;
}

IntervalVector TubeVector::codomain() const {
  IntervalVector r(size());
  for (std::size_t i = 0; i < size(); ++i) r[i] = x_[i].codomain();
  return r;
}

double TubeVector::volume() const {
  double v = 0.0;
  for (std::size_t k = 0; k < nb_slices(); ++k) {
    double p = tdomain()->slice_width(k).ub();
    for (const auto& xi : x_) {
      const Interval& y = xi.data().slices[k];
      const double d = y.is_empty() ? 0.0 : y.diam();
      if (d == 0.0) {  // a flat or empty slice has no volume (and no 0 * inf)
        p = 0.0;
        break;
      }
      p = rounding::mul_up(p, d);
    }
    v = rounding::add_up(v, p);
  }
  return v;
}

double TubeVector::max_thickness() const {
  double m = 0.0;
  for (const auto& xi : x_) m = std::max(m, xi.max_thickness());
  return m;
}

bool TubeVector::is_empty() const {
  return std::any_of(x_.begin(), x_.end(), [](const Tube& xi) { return xi.is_empty(); });
}

bool TubeVector::is_subset(const TubeVector& y) const {
  check_size(y.size(), "TubeVector::is_subset");
  for (std::size_t i = 0; i < size(); ++i) {
    if (!x_[i].is_subset(y.x_[i])) return false;
  }
  return true;
}

bool TubeVector::contains(const std::vector<Trajectory>& x) const {
  check_size(x.size(), "TubeVector::contains");
  for (std::size_t i = 0; i < size(); ++i) {
    if (!x_[i].contains(x[i])) return false;
  }
  return true;
}

bool TubeVector::operator==(const TubeVector& y) const { return x_ == y.x_; }

TubeVector& TubeVector::operator&=(const TubeVector& y) {
  check_size(y.size(), "TubeVector::operator&=");
  for (std::size_t i = 0; i < size(); ++i) x_[i] &= y.x_[i];
  return *this;
}

TubeVector& TubeVector::operator|=(const TubeVector& y) {
  check_size(y.size(), "TubeVector::operator|=");
  for (std::size_t i = 0; i < size(); ++i) x_[i] |= y.x_[i];
  return *this;
}

void TubeVector::set(const IntervalVector& y) {
  check_size(y.size(), "TubeVector::set(y)");
  for (std::size_t i = 0; i < size(); ++i) x_[i].set(y[i]);
}

void TubeVector::set(const IntervalVector& y, std::size_t k) {
  check_size(y.size(), "TubeVector::set(y, k)");
  for (std::size_t i = 0; i < size(); ++i) x_[i].set(y[i], k);
}

void TubeVector::set_gate(std::size_t k, const IntervalVector& y) {
  check_size(y.size(), "TubeVector::set_gate(k, y)");
  for (std::size_t i = 0; i < size(); ++i) x_[i].set_gate(k, y[i]);
}

std::ostream& operator<<(std::ostream& os, const TubeVector& x) {
  return os << "TubeVector " << x.tdomain()->t0_tf() << " -> " << x.codomain() << ", " << x.nb_slices()
            << " slices";
}

}  // namespace sillage
