#pragma once
// IntervalVector: a box [x1] x ... x [xn] of IR^n (thesis 2.24). A box is empty
// as soon as one of its components is; operations follow the intervals.
#include <cstddef>
#include <initializer_list>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "sillage/interval/interval.h"

namespace sillage {

using Vector = std::vector<double>;

class IntervalVector {
 public:
  IntervalVector() = default;
  // n components, each x (the whole real line by default).
  explicit IntervalVector(std::size_t n, const Interval& x = Interval());
  IntervalVector(std::initializer_list<Interval> xs) : v_(xs) {}
  explicit IntervalVector(std::vector<Interval> xs) : v_(std::move(xs)) {}
  // The degenerate box {p}.
  static IntervalVector from_point(const Vector& p);
  // Box from rows of bounds {{lb1, ub1}, {lb2, ub2}, ...}.
  static IntervalVector from_bounds(const std::vector<std::pair<double, double>>& bounds);
  // The empty box of dimension n.
  static IntervalVector empty(std::size_t n) { return IntervalVector(n, Interval::empty()); }

  // The dimension n.
  std::size_t size() const { return v_.size(); }
  Interval& operator[](std::size_t i) { return v_[i]; }
  const Interval& operator[](std::size_t i) const { return v_[i]; }
  // Bounds-checked access: throws DimensionError.
  Interval& at(std::size_t i);
  const Interval& at(std::size_t i) const;
  auto begin() { return v_.begin(); }
  auto end() { return v_.end(); }
  auto begin() const { return v_.begin(); }
  auto end() const { return v_.end(); }
  const std::vector<Interval>& components() const { return v_; }
  // Components [i, j] inclusive.
  IntervalVector subvector(std::size_t i, std::size_t j) const;
  // Writes the box x into components start, start + 1, ... in place.
  void put(std::size_t start, const IntervalVector& x);

  // True when a component is empty.
  bool is_empty() const;
  // True when a component is unbounded.
  bool is_unbounded() const;
  // True when every component is degenerate (a point).
  bool is_degenerate() const;
  // True when the point p is in the box.
  bool contains(const Vector& p) const;
  // True when this box is a subset of y.
  bool is_subset(const IntervalVector& y) const;
  // True when this box is a subset of y and differs from it.
  bool is_strict_subset(const IntervalVector& y) const { return is_subset(y) && *this != y; }
  // True when this box is in the interior of y.
  bool is_interior_subset(const IntervalVector& y) const;
  // True when this box and y have a common point.
  bool intersects(const IntervalVector& y) const;
  bool operator==(const IntervalVector& y) const;
  bool operator!=(const IntervalVector& y) const { return !(*this == y); }

  // The lower bounds of the components.
  Vector lb() const;
  // The upper bounds of the components.
  Vector ub() const;
  // The midpoint.
  Vector mid() const;
  // The widths of the components.
  Vector diam() const;
  // Half the widths of the components.
  Vector rad() const;
  // The largest width of a component.
  double max_diam() const;
  // The smallest width of a component.
  double min_diam() const;
  // Index of the widest component (largest=true) or of the narrowest one.
  std::size_t extr_diam_index(bool largest = true) const;
  double volume() const;  // product of the diameters, 0 if empty
  // The magnitudes of the components.
  Vector mag() const;
  // The mignitudes of the components.
  Vector mig() const;

  IntervalVector operator&(const IntervalVector& y) const;
  IntervalVector operator|(const IntervalVector& y) const;
  IntervalVector& operator&=(const IntervalVector& y);
  IntervalVector& operator|=(const IntervalVector& y);
  // Bisection of component i (default: the largest) at lb + ratio * diam.
  std::pair<IntervalVector, IntervalVector> bisect(double ratio = 0.5) const;
  // Splits component i at lb + ratio * diam; returns the two halves.
  std::pair<IntervalVector, IntervalVector> bisect(std::size_t i, double ratio) const;
  // Each component inflated by r (a new box).
  IntervalVector inflate(double r) const;
  // Makes this box empty, in place.
  void set_empty();

  IntervalVector operator-() const;
  IntervalVector& operator+=(const IntervalVector& y);
  IntervalVector& operator-=(const IntervalVector& y);

  std::string str() const;

 private:
  std::vector<Interval> v_;
};

IntervalVector operator+(const IntervalVector& x, const IntervalVector& y);
IntervalVector operator-(const IntervalVector& x, const IntervalVector& y);
IntervalVector operator*(const Interval& a, const IntervalVector& x);
IntervalVector operator*(const IntervalVector& x, const Interval& a);
// Dot product of two boxes (a rigorous interval sum of products).
Interval dot(const IntervalVector& x, const IntervalVector& y);
// The smallest box containing x and y.
IntervalVector hull(const IntervalVector& x, const IntervalVector& y);
// Componentwise absolute value of a box.
IntervalVector abs(const IntervalVector& x);
// Euclidean norm, rigorous.
Interval norm(const IntervalVector& x);
std::ostream& operator<<(std::ostream& os, const IntervalVector& x);

// Throws DimensionError naming `where` when the sizes differ.
void check_same_size(std::size_t a, std::size_t b, const char* where);

}  // namespace sillage
