#include "sillage/interval/interval_vector.h"

#include <ostream>
#include <sstream>

namespace sillage {

void check_same_size(std::size_t a, std::size_t b, const char* where) {
  if (a != b) {
    throw DimensionError(std::string(where) + ": dimension mismatch (" + std::to_string(a) + " vs " +
                         std::to_string(b) + ")");
  }
}

IntervalVector::IntervalVector(std::size_t n, const Interval& x) : v_(n, x) {}

IntervalVector IntervalVector::from_point(const Vector& p) {
  IntervalVector x(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) x[i] = Interval(p[i]);
  return x;
}

IntervalVector IntervalVector::from_bounds(const std::vector<std::pair<double, double>>& bounds) {
  IntervalVector x(bounds.size());
  for (std::size_t i = 0; i < bounds.size(); ++i) x[i] = Interval(bounds[i].first, bounds[i].second);
  return x;
}

Interval& IntervalVector::at(std::size_t i) {
  if (i >= v_.size()) {
    throw DimensionError("IntervalVector: index " + std::to_string(i) + " out of range for size " +
                         std::to_string(v_.size()));
  }
  return v_[i];
}

const Interval& IntervalVector::at(std::size_t i) const { return const_cast<IntervalVector*>(this)->at(i); }

IntervalVector IntervalVector::subvector(std::size_t i, std::size_t j) const {
  if (i > j || j >= v_.size()) {
    throw DimensionError("IntervalVector::subvector: invalid range [" + std::to_string(i) + ", " +
                         std::to_string(j) + "] for size " + std::to_string(v_.size()));
  }
  return IntervalVector(std::vector<Interval>(v_.begin() + i, v_.begin() + j + 1));
}

void IntervalVector::put(std::size_t start, const IntervalVector& x) {
  if (start + x.size() > v_.size()) {
    throw DimensionError("IntervalVector::put: a subvector of size " + std::to_string(x.size()) + " at " +
                         std::to_string(start) + " does not fit in size " + std::to_string(v_.size()));
  }
  for (std::size_t k = 0; k < x.size(); ++k) v_[start + k] = x[k];
}

bool IntervalVector::is_empty() const {
  for (const auto& x : v_) {
    if (x.is_empty()) return true;
  }
  return false;
}

bool IntervalVector::is_unbounded() const {
  for (const auto& x : v_) {
    if (x.is_unbounded()) return true;
  }
  return false;
}

bool IntervalVector::is_degenerate() const {
  for (const auto& x : v_) {
    if (!x.is_degenerate()) return false;
  }
  return true;
}

bool IntervalVector::contains(const Vector& p) const {
  check_same_size(size(), p.size(), "IntervalVector::contains");
  for (std::size_t i = 0; i < size(); ++i) {
    if (!v_[i].contains(p[i])) return false;
  }
  return true;
}

bool IntervalVector::is_subset(const IntervalVector& y) const {
  check_same_size(size(), y.size(), "IntervalVector::is_subset");
  if (is_empty()) return true;
  for (std::size_t i = 0; i < size(); ++i) {
    if (!v_[i].is_subset(y[i])) return false;
  }
  return true;
}

bool IntervalVector::is_interior_subset(const IntervalVector& y) const {
  check_same_size(size(), y.size(), "IntervalVector::is_interior_subset");
  if (is_empty()) return true;
  for (std::size_t i = 0; i < size(); ++i) {
    if (!v_[i].is_interior_subset(y[i])) return false;
  }
  return true;
}

bool IntervalVector::intersects(const IntervalVector& y) const {
  check_same_size(size(), y.size(), "IntervalVector::intersects");
  for (std::size_t i = 0; i < size(); ++i) {
    if (!v_[i].intersects(y[i])) return false;
  }
  return true;
}

bool IntervalVector::operator==(const IntervalVector& y) const {
  if (size() != y.size()) return false;
  if (is_empty() || y.is_empty()) return is_empty() && y.is_empty();
  for (std::size_t i = 0; i < size(); ++i) {
    if (v_[i] != y[i]) return false;
  }
  return true;
}

namespace {

template <class F>
Vector map_components(const std::vector<Interval>& v, F f) {
  Vector r(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) r[i] = f(v[i]);
  return r;
}

}  // namespace

Vector IntervalVector::lb() const { return map_components(v_, [](const Interval& x) { return x.lb(); }); }
Vector IntervalVector::ub() const { return map_components(v_, [](const Interval& x) { return x.ub(); }); }
Vector IntervalVector::mid() const { return map_components(v_, [](const Interval& x) { return x.mid(); }); }
Vector IntervalVector::diam() const { return map_components(v_, [](const Interval& x) { return x.diam(); }); }
Vector IntervalVector::rad() const { return map_components(v_, [](const Interval& x) { return x.rad(); }); }
Vector IntervalVector::mag() const { return map_components(v_, [](const Interval& x) { return x.mag(); }); }
Vector IntervalVector::mig() const { return map_components(v_, [](const Interval& x) { return x.mig(); }); }

std::size_t IntervalVector::extr_diam_index(bool largest) const {
  if (v_.empty()) throw DimensionError("IntervalVector::extr_diam_index: zero-dimensional box");
  std::size_t best = 0;
  for (std::size_t i = 1; i < v_.size(); ++i) {
    const double d = v_[i].diam(), b = v_[best].diam();
    if (largest ? d > b : d < b) best = i;
  }
  return best;
}

double IntervalVector::max_diam() const { return v_[extr_diam_index(true)].diam(); }
double IntervalVector::min_diam() const { return v_[extr_diam_index(false)].diam(); }

double IntervalVector::volume() const {
  if (is_empty()) return 0.0;
  double vol = 1.0;
  for (const auto& x : v_) vol *= x.diam();
  return vol;
}

IntervalVector IntervalVector::operator&(const IntervalVector& y) const {
  IntervalVector r(*this);
  return r &= y;
}

IntervalVector IntervalVector::operator|(const IntervalVector& y) const {
  IntervalVector r(*this);
  return r |= y;
}

IntervalVector& IntervalVector::operator&=(const IntervalVector& y) {
  check_same_size(size(), y.size(), "IntervalVector::operator&");
  for (std::size_t i = 0; i < size(); ++i) v_[i] &= y[i];
  if (is_empty()) set_empty();
  return *this;
}

IntervalVector& IntervalVector::operator|=(const IntervalVector& y) {
  check_same_size(size(), y.size(), "IntervalVector::operator|");
  if (y.is_empty()) return *this;
  if (is_empty()) return *this = y;
  for (std::size_t i = 0; i < size(); ++i) v_[i] |= y[i];
  return *this;
}

std::pair<IntervalVector, IntervalVector> IntervalVector::bisect(double ratio) const {
  return bisect(extr_diam_index(true), ratio);
}

std::pair<IntervalVector, IntervalVector> IntervalVector::bisect(std::size_t i, double ratio) const {
  if (i >= size()) {
    throw DimensionError("IntervalVector::bisect: component " + std::to_string(i) + " out of range for size " +
                         std::to_string(size()));
  }
  auto [a, b] = v_[i].bisect(ratio);
  IntervalVector l(*this), r(*this);
  l[i] = a;
  r[i] = b;
  return {l, r};
}

IntervalVector IntervalVector::inflate(double r) const {
  IntervalVector y(*this);
  for (auto& x : y.v_) x = x.inflate(r);
  return y;
}

void IntervalVector::set_empty() {
  for (auto& x : v_) x = Interval::empty();
}

IntervalVector IntervalVector::operator-() const {
  IntervalVector y(*this);
  for (auto& x : y.v_) x = -x;
  return y;
}

IntervalVector& IntervalVector::operator+=(const IntervalVector& y) {
  check_same_size(size(), y.size(), "IntervalVector::operator+");
  for (std::size_t i = 0; i < size(); ++i) v_[i] += y[i];
  return *this;
}

IntervalVector& IntervalVector::operator-=(const IntervalVector& y) {
  check_same_size(size(), y.size(), "IntervalVector::operator-");
  for (std::size_t i = 0; i < size(); ++i) v_[i] -= y[i];
  return *this;
}

IntervalVector operator+(const IntervalVector& x, const IntervalVector& y) {
  IntervalVector r(x);
  return r += y;
}

IntervalVector operator-(const IntervalVector& x, const IntervalVector& y) {
  IntervalVector r(x);
  return r -= y;
}

IntervalVector operator*(const Interval& a, const IntervalVector& x) {
  IntervalVector r(x);
  for (auto& c : r) c = a * c;
  return r;
}

IntervalVector operator*(const IntervalVector& x, const Interval& a) { return a * x; }

Interval dot(const IntervalVector& x, const IntervalVector& y) {
  check_same_size(x.size(), y.size(), "dot");
  Interval s(0.0);
  for (std::size_t i = 0; i < x.size(); ++i) s += x[i] * y[i];
  return s;
}

IntervalVector hull(const IntervalVector& x, const IntervalVector& y) { return x | y; }

IntervalVector abs(const IntervalVector& x) {
  IntervalVector r(x);
  for (auto& c : r) c = abs(c);
  return r;
}

Interval norm(const IntervalVector& x) {
  Interval s(0.0);
  for (const auto& c : x) s += sqr(c);
  return sqrt(s);
}

std::string IntervalVector::str() const {
  std::ostringstream os;
  os << "(";
  for (std::size_t i = 0; i < size(); ++i) os << (i ? " ; " : "") << v_[i];
  os << ")";
  return os.str();
}

std::ostream& operator<<(std::ostream& os, const IntervalVector& x) { return os << x.str(); }

}  // namespace sillage
