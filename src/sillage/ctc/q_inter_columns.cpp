#include "sillage/ctc/q_inter_columns.h"

#include <algorithm>

#include "sillage/ctc/q_inter.h"

namespace sillage::detail {

namespace {

// Inserts x among the n kept values of `kept` (k slots, ordered by `before`),
// dropping the last when all k are taken and x comes before it.
template <class Before>
void keep_extreme(double* kept, std::size_t n, std::size_t k, double x, Before before) {
  std::size_t i = n < k ? n : k - 1;
  if (n >= k && !before(x, kept[i])) return;
  while (i > 0 && before(x, kept[i - 1])) {
    kept[i] = kept[i - 1];
    --i;
  }
  kept[i] = x;
}

// The number of the s values of v that `beyond` x.
template <class Beyond>
std::size_t count_beyond(const double* v, std::size_t s, double x, Beyond beyond) {
  std::size_t c = 0;
  for (std::size_t i = 0; i < s; ++i) c += beyond(v[i], x);
  return c;
}

}  // namespace

void QInterColumns::reset(std::size_t columns, int q) {
  check_q(q, "QInterColumns");
  k_ = static_cast<std::size_t>(q) + 1;
  count_.assign(columns, 0);
  empties_.assign(columns, 0);
  lows_.resize(columns * k_);  // read only below each column's count: no need to clear
  highs_.resize(columns * k_);
}

void QInterColumns::add(std::size_t column, const Interval& x) {
  const std::size_t n = count_[column] - empties_[column];
  ++count_[column];
  if (x.is_empty()) {
    ++empties_[column];
    return;
  }
  keep_extreme(&lows_[column * k_], n, k_, x.lb(), [](double a, double b) { return a > b; });
  keep_extreme(&highs_[column * k_], n, k_, x.ub(), [](double a, double b) { return a < b; });
}

// Why q + 1 bounds per side suffice. A point x is excluded by an empty
// interval, by those with a lower bound > x and by those with an upper bound
// < x (never both: a <= b). With e empties, x is in the hull's set iff at most
// r = q' - e non-empty intervals exclude it. The set is a union of closed
// intervals starting at lower bounds, so its minimum is a lower bound x with
// at most r lower bounds above it: one of the r + 1 largest, L[0..r]. For such
// an x the lower bounds above it are all among the kept ones (those not kept
// are <= L[k-1] <= x), and the upper bounds below it are counted exactly among
// the kept smallest ones as long as they are at most r < k (else every kept
// one is below x and the count, k > r, already rejects x). The same, mirrored,
// for the maximum among H[0..r].
Interval QInterColumns::hull(std::size_t column, int q_prime) const {
  const std::size_t c = count_[column], e = empties_[column];
  const auto qp = static_cast<std::size_t>(q_prime);
  if (qp >= c) return Interval::all_reals();
  if (e > qp) return Interval::empty();
  const std::size_t r = qp - e, s = std::min(c - e, k_);  // s >= r + 1 since c - e > r and k_ > q' >= r
  const double* lo = &lows_[column * k_];
  const double* hi = &highs_[column * k_];
  const auto above = [](double v, double x) { return v > x; };
  const auto below = [](double v, double x) { return v < x; };
  for (std::size_t j = r + 1; j-- > 0;) {  // ascending candidates
    const double x = lo[j];
    if (count_beyond(lo, s, x, above) + count_beyond(hi, s, x, below) > r) continue;
    for (std::size_t i = r + 1; i-- > 0;) {  // descending candidates; one is in the set since x is
      const double y = hi[i];
      if (count_beyond(hi, s, y, below) + count_beyond(lo, s, y, above) <= r) return Interval::from_bounds_unchecked(x, y);
    }
  }
  return Interval::empty();
}

}  // namespace sillage::detail
