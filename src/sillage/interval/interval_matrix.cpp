#include "sillage/interval/interval_matrix.h"

#include <algorithm>
#include <ostream>
#include <sstream>

namespace sillage {

namespace {

std::string shape(std::size_t r, std::size_t c) { return std::to_string(r) + "x" + std::to_string(c); }

void check_same_shape(const IntervalMatrix& a, const IntervalMatrix& b, const char* where) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) {
    throw DimensionError(std::string(where) + ": shape mismatch (" + shape(a.rows(), a.cols()) + " vs " +
                         shape(b.rows(), b.cols()) + ")");
  }
}

// Number of columns shared by all rows; throws when they differ.
template <class Rows>
std::size_t common_width(const Rows& rows, const char* where) {
  const std::size_t c = rows.size() ? std::begin(rows)->size() : 0;
  std::size_t i = 0;
  for (const auto& r : rows) {
    if (r.size() != c) {
      throw DimensionError(std::string(where) + ": row " + std::to_string(i) + " has " + std::to_string(r.size()) +
                           " entries, row 0 has " + std::to_string(c));
    }
    ++i;
  }
  return c;
}

}  // namespace

IntervalMatrix::IntervalMatrix(std::size_t rows, std::size_t cols, const Interval& x)
    : rows_(rows), cols_(cols), data_(rows * cols, x) {}

IntervalMatrix::IntervalMatrix(std::initializer_list<std::initializer_list<Interval>> rows)
    : rows_(rows.size()), cols_(common_width(rows, "IntervalMatrix")) {
  data_.reserve(rows_ * cols_);
  for (const auto& r : rows) data_.insert(data_.end(), r.begin(), r.end());
}

IntervalMatrix::IntervalMatrix(const std::vector<IntervalVector>& rows)
    : rows_(rows.size()), cols_(common_width(rows, "IntervalMatrix")) {
  data_.reserve(rows_ * cols_);
  for (const auto& r : rows) data_.insert(data_.end(), r.begin(), r.end());
}

IntervalMatrix IntervalMatrix::identity(std::size_t n) {
  IntervalMatrix m(n, n, Interval(0.0));
  for (std::size_t i = 0; i < n; ++i) m(i, i) = Interval(1.0);
  return m;
}

IntervalMatrix IntervalMatrix::from_point(const Matrix& p) {
  IntervalMatrix m(p.size(), common_width(p, "IntervalMatrix::from_point"));
  for (std::size_t i = 0; i < m.rows_; ++i)
    for (std::size_t j = 0; j < m.cols_; ++j) m(i, j) = Interval(p[i][j]);
  return m;
}

IntervalMatrix IntervalMatrix::from_bounds(const Matrix& lb, const Matrix& ub) {
  const std::size_t c = common_width(lb, "IntervalMatrix::from_bounds");
  if (lb.size() != ub.size() || (ub.size() && common_width(ub, "IntervalMatrix::from_bounds") != c)) {
    throw DimensionError("IntervalMatrix::from_bounds: lower and upper bounds have different shapes");
  }
  IntervalMatrix m(lb.size(), c);
  for (std::size_t i = 0; i < m.rows_; ++i)
    for (std::size_t j = 0; j < c; ++j) m(i, j) = Interval(lb[i][j], ub[i][j]);
  return m;
}

Interval& IntervalMatrix::at(std::size_t i, std::size_t j) {
  if (i >= rows_ || j >= cols_) {
    throw DimensionError("IntervalMatrix: index (" + std::to_string(i) + ", " + std::to_string(j) +
                         ") out of range for shape " + shape(rows_, cols_));
  }
  return (*this)(i, j);
}

const Interval& IntervalMatrix::at(std::size_t i, std::size_t j) const {
  return const_cast<IntervalMatrix*>(this)->at(i, j);
}

IntervalVector IntervalMatrix::row(std::size_t i) const {
  if (i >= rows_) throw DimensionError("IntervalMatrix::row: " + std::to_string(i) + " out of range for shape " +
                                       shape(rows_, cols_));
  return IntervalVector(std::vector<Interval>(data_.begin() + i * cols_, data_.begin() + (i + 1) * cols_));
}

IntervalVector IntervalMatrix::col(std::size_t j) const {
  if (j >= cols_) throw DimensionError("IntervalMatrix::col: " + std::to_string(j) + " out of range for shape " +
                                       shape(rows_, cols_));
  IntervalVector c(rows_);
  for (std::size_t i = 0; i < rows_; ++i) c[i] = (*this)(i, j);
  return c;
}

void IntervalMatrix::set_row(std::size_t i, const IntervalVector& r) {
  if (i >= rows_) throw DimensionError("IntervalMatrix::set_row: row " + std::to_string(i) + " out of range for shape " +
                                       shape(rows_, cols_));
  check_same_size(r.size(), cols_, "IntervalMatrix::set_row");
  std::copy(r.begin(), r.end(), data_.begin() + i * cols_);
}

void IntervalMatrix::set_col(std::size_t j, const IntervalVector& c) {
  if (j >= cols_) throw DimensionError("IntervalMatrix::set_col: column " + std::to_string(j) + " out of range for shape " +
                                       shape(rows_, cols_));
  check_same_size(c.size(), rows_, "IntervalMatrix::set_col");
  for (std::size_t i = 0; i < rows_; ++i) (*this)(i, j) = c[i];
}

IntervalMatrix IntervalMatrix::transpose() const {
  IntervalMatrix t(cols_, rows_);
  for (std::size_t i = 0; i < rows_; ++i)
    for (std::size_t j = 0; j < cols_; ++j) t(j, i) = (*this)(i, j);
  return t;
}

bool IntervalMatrix::is_empty() const {
  return std::any_of(data_.begin(), data_.end(), [](const Interval& x) { return x.is_empty(); });
}

bool IntervalMatrix::is_unbounded() const {
  return std::any_of(data_.begin(), data_.end(), [](const Interval& x) { return x.is_unbounded(); });
}

bool IntervalMatrix::is_degenerate() const {
  return std::all_of(data_.begin(), data_.end(), [](const Interval& x) { return x.is_degenerate(); });
}

bool IntervalMatrix::contains(const Matrix& m) const {
  if (m.size() != rows_ || common_width(m, "IntervalMatrix::contains") != cols_) {
    throw DimensionError("IntervalMatrix::contains: a " + shape(m.size(), m.empty() ? 0 : m[0].size()) +
                         " matrix against shape " + shape(rows_, cols_));
  }
  for (std::size_t i = 0; i < rows_; ++i)
    for (std::size_t j = 0; j < cols_; ++j)
      if (!(*this)(i, j).contains(m[i][j])) return false;
  return true;
}

bool IntervalMatrix::is_subset(const IntervalMatrix& y) const {
  check_same_shape(*this, y, "IntervalMatrix::is_subset");
  if (is_empty()) return true;
  for (std::size_t k = 0; k < data_.size(); ++k)
    if (!data_[k].is_subset(y.data_[k])) return false;
  return true;
}

bool IntervalMatrix::is_interior_subset(const IntervalMatrix& y) const {
  check_same_shape(*this, y, "IntervalMatrix::is_interior_subset");
  if (is_empty()) return true;
  for (std::size_t k = 0; k < data_.size(); ++k)
    if (!data_[k].is_interior_subset(y.data_[k])) return false;
  return true;
}

bool IntervalMatrix::intersects(const IntervalMatrix& y) const {
  check_same_shape(*this, y, "IntervalMatrix::intersects");
  for (std::size_t k = 0; k < data_.size(); ++k)
    if (!data_[k].intersects(y.data_[k])) return false;
  return true;
}

bool IntervalMatrix::operator==(const IntervalMatrix& y) const {
  if (rows_ != y.rows_ || cols_ != y.cols_) return false;
  if (is_empty() || y.is_empty()) return is_empty() && y.is_empty();
  return data_ == y.data_;
}

namespace {

template <class F>
Matrix map_entries(const IntervalMatrix& a, F f) {
  Matrix m(a.rows(), Vector(a.cols()));
  for (std::size_t i = 0; i < a.rows(); ++i)
    for (std::size_t j = 0; j < a.cols(); ++j) m[i][j] = f(a(i, j));
  return m;
}

}  // namespace

Matrix IntervalMatrix::lb() const { return map_entries(*this, [](const Interval& x) { return x.lb(); }); }
Matrix IntervalMatrix::ub() const { return map_entries(*this, [](const Interval& x) { return x.ub(); }); }
Matrix IntervalMatrix::mid() const { return map_entries(*this, [](const Interval& x) { return x.mid(); }); }
Matrix IntervalMatrix::diam() const { return map_entries(*this, [](const Interval& x) { return x.diam(); }); }

double IntervalMatrix::max_diam() const {
  if (data_.empty()) throw DimensionError("IntervalMatrix::max_diam: empty shape " + shape(rows_, cols_));
  double d = data_[0].diam();
  for (const auto& x : data_) d = std::max(d, x.diam());
  return d;
}

IntervalMatrix IntervalMatrix::operator&(const IntervalMatrix& y) const {
  IntervalMatrix r(*this);
  return r &= y;
}

IntervalMatrix IntervalMatrix::operator|(const IntervalMatrix& y) const {
  IntervalMatrix r(*this);
  return r |= y;
}

IntervalMatrix& IntervalMatrix::operator&=(const IntervalMatrix& y) {
  check_same_shape(*this, y, "IntervalMatrix::operator&");
  for (std::size_t k = 0; k < data_.size(); ++k) data_[k] &= y.data_[k];
  if (is_empty()) set_empty();
  return *this;
}

IntervalMatrix& IntervalMatrix::operator|=(const IntervalMatrix& y) {
  check_same_shape(*this, y, "IntervalMatrix::operator|");
  if (y.is_empty()) return *this;
  if (is_empty()) return *this = y;
  for (std::size_t k = 0; k < data_.size(); ++k) data_[k] |= y.data_[k];
  return *this;
}

IntervalMatrix IntervalMatrix::inflate(double r) const {
  IntervalMatrix m(*this);
  for (auto& x : m.data_) x = x.inflate(r);
  return m;
}

void IntervalMatrix::set_empty() { std::fill(data_.begin(), data_.end(), Interval::empty()); }

IntervalMatrix IntervalMatrix::operator-() const {
  IntervalMatrix m(*this);
  for (auto& x : m.data_) x = -x;
  return m;
}

IntervalMatrix& IntervalMatrix::operator+=(const IntervalMatrix& y) {
  check_same_shape(*this, y, "IntervalMatrix::operator+");
  for (std::size_t k = 0; k < data_.size(); ++k) data_[k] += y.data_[k];
  return *this;
}

IntervalMatrix& IntervalMatrix::operator-=(const IntervalMatrix& y) {
  check_same_shape(*this, y, "IntervalMatrix::operator-");
  for (std::size_t k = 0; k < data_.size(); ++k) data_[k] -= y.data_[k];
  return *this;
}

IntervalMatrix& IntervalMatrix::operator*=(const Interval& a) {
  for (auto& x : data_) x *= a;
  return *this;
}

IntervalMatrix operator+(const IntervalMatrix& a, const IntervalMatrix& b) {
  IntervalMatrix r(a);
  return r += b;
}

IntervalMatrix operator-(const IntervalMatrix& a, const IntervalMatrix& b) {
  IntervalMatrix r(a);
  return r -= b;
}

IntervalMatrix operator*(const IntervalMatrix& a, const IntervalMatrix& b) {
  if (a.cols() != b.rows()) {
    throw DimensionError("IntervalMatrix product: " + shape(a.rows(), a.cols()) + " times " +
                         shape(b.rows(), b.cols()));
  }
  IntervalMatrix r(a.rows(), b.cols(), Interval(0.0));
  for (std::size_t i = 0; i < a.rows(); ++i)
    for (std::size_t k = 0; k < a.cols(); ++k) {
      const Interval& aik = a(i, k);
      for (std::size_t j = 0; j < b.cols(); ++j) r(i, j) += aik * b(k, j);
    }
  return r;
}

IntervalVector operator*(const IntervalMatrix& a, const IntervalVector& x) {
  if (a.cols() != x.size()) {
    throw DimensionError("IntervalMatrix * IntervalVector: " + shape(a.rows(), a.cols()) + " times a vector of size " +
                         std::to_string(x.size()));
  }
  IntervalVector r(a.rows(), Interval(0.0));
  for (std::size_t i = 0; i < a.rows(); ++i)
    for (std::size_t j = 0; j < a.cols(); ++j) r[i] += a(i, j) * x[j];
  return r;
}

IntervalMatrix operator*(const Interval& s, const IntervalMatrix& a) {
  IntervalMatrix r(a);
  return r *= s;
}

IntervalMatrix operator*(const IntervalMatrix& a, const Interval& s) { return s * a; }

IntervalMatrix hull(const IntervalMatrix& a, const IntervalMatrix& b) { return a | b; }

IntervalMatrix abs(const IntervalMatrix& a) {
  IntervalMatrix r(a);
  for (std::size_t i = 0; i < a.rows(); ++i)
    for (std::size_t j = 0; j < a.cols(); ++j) r(i, j) = abs(a(i, j));
  return r;
}

std::string IntervalMatrix::str() const {
  std::ostringstream os;
  os << "(";
  for (std::size_t i = 0; i < rows_; ++i) {
    os << (i ? " ; " : "") << "(";
    for (std::size_t j = 0; j < cols_; ++j) os << (j ? " ; " : "") << (*this)(i, j);
    os << ")";
  }
  os << ")";
  return os.str();
}

std::ostream& operator<<(std::ostream& os, const IntervalMatrix& a) { return os << a.str(); }

}  // namespace sillage
