#pragma once
// IntervalMatrix: a rows x cols matrix of intervals, i.e. a box of real
// matrices. Stored row-major and contiguous. Like a box, it is empty as soon as
// one entry is; products are rigorous (each entry an interval dot product).
#include <cstddef>
#include <initializer_list>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "sillage/interval/interval_vector.h"

namespace sillage {

// A real matrix given by its rows.
using Matrix = std::vector<Vector>;

class IntervalMatrix {
 public:
  IntervalMatrix() = default;  // 0 x 0
  // rows x cols entries, each x (the whole real line by default).
  IntervalMatrix(std::size_t rows, std::size_t cols, const Interval& x = Interval());
  // From rows, e.g. {{{0, 1}, {2, 3}}, {{4, 5}, 1.0}}; rows of unequal length throw DimensionError.
  IntervalMatrix(std::initializer_list<std::initializer_list<Interval>> rows);
  explicit IntervalMatrix(const std::vector<IntervalVector>& rows);
  static IntervalMatrix identity(std::size_t n);
  static IntervalMatrix empty(std::size_t rows, std::size_t cols) { return {rows, cols, Interval::empty()}; }
  // The degenerate matrix {m}.
  static IntervalMatrix from_point(const Matrix& m);
  // Entry (i, j) = [lb[i][j], ub[i][j]].
  static IntervalMatrix from_bounds(const Matrix& lb, const Matrix& ub);

  std::size_t rows() const { return rows_; }
  std::size_t cols() const { return cols_; }
  Interval& operator()(std::size_t i, std::size_t j) { return data_[i * cols_ + j]; }
  const Interval& operator()(std::size_t i, std::size_t j) const { return data_[i * cols_ + j]; }
  // Bounds-checked access: throws DimensionError.
  Interval& at(std::size_t i, std::size_t j);
  const Interval& at(std::size_t i, std::size_t j) const;
  IntervalVector row(std::size_t i) const;
  IntervalVector col(std::size_t j) const;
  void set_row(std::size_t i, const IntervalVector& r);
  void set_col(std::size_t j, const IntervalVector& c);
  const std::vector<Interval>& entries() const { return data_; }  // row-major

  IntervalMatrix transpose() const;

  bool is_empty() const;
  bool is_unbounded() const;
  bool is_degenerate() const;
  bool contains(const Matrix& m) const;
  bool is_subset(const IntervalMatrix& y) const;
  bool is_interior_subset(const IntervalMatrix& y) const;
  bool intersects(const IntervalMatrix& y) const;
  bool operator==(const IntervalMatrix& y) const;
  bool operator!=(const IntervalMatrix& y) const { return !(*this == y); }

  Matrix lb() const;
  Matrix ub() const;
  Matrix mid() const;
  Matrix diam() const;
  double max_diam() const;

  IntervalMatrix operator&(const IntervalMatrix& y) const;
  IntervalMatrix operator|(const IntervalMatrix& y) const;
  IntervalMatrix& operator&=(const IntervalMatrix& y);
  IntervalMatrix& operator|=(const IntervalMatrix& y);
  IntervalMatrix inflate(double r) const;
  void set_empty();

  IntervalMatrix operator-() const;
  IntervalMatrix& operator+=(const IntervalMatrix& y);
  IntervalMatrix& operator-=(const IntervalMatrix& y);
  IntervalMatrix& operator*=(const Interval& a);

  std::string str() const;

 private:
  std::size_t rows_ = 0, cols_ = 0;
  std::vector<Interval> data_;
};

IntervalMatrix operator+(const IntervalMatrix& a, const IntervalMatrix& b);
IntervalMatrix operator-(const IntervalMatrix& a, const IntervalMatrix& b);
IntervalMatrix operator*(const IntervalMatrix& a, const IntervalMatrix& b);
IntervalVector operator*(const IntervalMatrix& a, const IntervalVector& x);
IntervalMatrix operator*(const Interval& s, const IntervalMatrix& a);
IntervalMatrix operator*(const IntervalMatrix& a, const Interval& s);
IntervalMatrix hull(const IntervalMatrix& a, const IntervalMatrix& b);
IntervalMatrix abs(const IntervalMatrix& a);
std::ostream& operator<<(std::ostream& os, const IntervalMatrix& a);

}  // namespace sillage
