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
  // The n x n identity matrix.
  static IntervalMatrix identity(std::size_t n);
  // The empty matrix of the given shape.
  static IntervalMatrix empty(std::size_t rows, std::size_t cols) { return {rows, cols, Interval::empty()}; }
  // The degenerate matrix {m}.
  static IntervalMatrix from_point(const Matrix& m);
  // Entry (i, j) = [lb[i][j], ub[i][j]].
  static IntervalMatrix from_bounds(const Matrix& lb, const Matrix& ub);

  // Number of rows.
  std::size_t rows() const { return rows_; }
  // Number of columns.
  std::size_t cols() const { return cols_; }
  Interval& operator()(std::size_t i, std::size_t j) { return data_[i * cols_ + j]; }
  const Interval& operator()(std::size_t i, std::size_t j) const { return data_[i * cols_ + j]; }
  // Bounds-checked access: throws DimensionError.
  Interval& at(std::size_t i, std::size_t j);
  const Interval& at(std::size_t i, std::size_t j) const;
  // Row i, a copy as an IntervalVector.
  IntervalVector row(std::size_t i) const;
  // Column j, a copy as an IntervalVector.
  IntervalVector col(std::size_t j) const;
  // Replaces row i by the box r.
  void set_row(std::size_t i, const IntervalVector& r);
  // Replaces column j by the box c.
  void set_col(std::size_t j, const IntervalVector& c);
  const std::vector<Interval>& entries() const { return data_; }  // row-major

  // The transpose (a new matrix).
  IntervalMatrix transpose() const;

  // True when an entry is empty.
  bool is_empty() const;
  // True when an entry is unbounded.
  bool is_unbounded() const;
  // True when every entry is a point.
  bool is_degenerate() const;
  // True when the real matrix m is in the interval matrix.
  bool contains(const Matrix& m) const;
  // True when every entry is a subset of the entry of y.
  bool is_subset(const IntervalMatrix& y) const;
  // True when every entry is in the interior of the entry of y.
  bool is_interior_subset(const IntervalMatrix& y) const;
  // True when every entry meets the entry of y.
  bool intersects(const IntervalMatrix& y) const;
  bool operator==(const IntervalMatrix& y) const;
  bool operator!=(const IntervalMatrix& y) const { return !(*this == y); }

  // The lower bounds of the entries, row by row.
  Matrix lb() const;
  // The upper bounds of the entries, row by row.
  Matrix ub() const;
  // The midpoints of the entries, row by row.
  Matrix mid() const;
  // The widths of the entries, row by row.
  Matrix diam() const;
  // The largest width of an entry.
  double max_diam() const;

  IntervalMatrix operator&(const IntervalMatrix& y) const;
  IntervalMatrix operator|(const IntervalMatrix& y) const;
  IntervalMatrix& operator&=(const IntervalMatrix& y);
  IntervalMatrix& operator|=(const IntervalMatrix& y);
  // Each entry inflated by r (a new matrix).
  IntervalMatrix inflate(double r) const;
  // Makes this matrix empty, in place.
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
