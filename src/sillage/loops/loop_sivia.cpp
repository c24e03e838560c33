#include "sillage/loops/loop_sivia.h"

#include <algorithm>
#include <string>

#include "sillage/error.h"
#include "sillage/paving/paving_builder.h"

namespace sillage {

namespace {

constexpr const char* kWhere = "loop_sivia";

bool excludes_zero(const Interval& x) { return !x.contains(0.0); }  // true for an empty x too

// Keeps the part of t where t1 <= t2; false if no t1 < t2 is left (a box
// that only touches the diagonal holds no loop).
bool keep_upper_half(IntervalVector& t) {
  if (!(t[0].lb() < t[1].ub())) return false;
  const double t1_hi = std::min(t[0].ub(), t[1].ub());
  const double t2_lo = std::max(t[1].lb(), t[0].lb());
  t[0] = Interval::from_bounds_unchecked(t[0].lb(), t1_hi);
  t[1] = Interval::from_bounds_unchecked(t2_lo, t[1].ub());
  return true;
}

// (6.9): some velocity component keeps one sign over [lb t1, ub t2].
bool is_injective(const LoopFunction& f, const IntervalVector& t) {
  const IntervalVector v = f.velocity(Interval::from_bounds_unchecked(t[0].lb(), t[1].ub()));
  return excludes_zero(v[0]) || excludes_zero(v[1]);
}

bool inner_bounds(const IntervalVector& lower, const IntervalVector& upper) {
  if (lower.is_empty() || upper.is_empty()) return false;
  for (std::size_t i = 0; i < 2; ++i) {
    if (!(lower[i].ub() <= 0.0 && 0.0 <= upper[i].lb())) return false;
  }
  return true;
}

// Alg. 6 on one box, as a separation (paving_builder.h): x_out loses what is
// proven outside T, x_in is emptied when what is left is proven inside.
void separate(const LoopFunction& f, IntervalVector& x_in, IntervalVector& x_out) {
  IntervalVector& t = x_out;
  if (f.is_empty() || !keep_upper_half(t)) {
    t.set_empty();
    return;
  }
  // On or against the diagonal, f(t, t) = 0 lies in [f]: only (6.9) can decide.
  if (!(t[0].ub() < t[1].lb())) {
    if (is_injective(f, t)) t.set_empty();
    return;
  }
  const auto [lower, upper] = f.integral_bounds(t[0], t[1]);
  IntervalVector fx{Interval::from_bounds_unchecked(lower[0].lb(), upper[0].ub()),
                    Interval::from_bounds_unchecked(lower[1].lb(), upper[1].ub())};
  if (lower.is_empty() || upper.is_empty()) fx.set_empty();  // a tube with an empty slice
  if (f.has_positions()) {  // (7.28), tighter
    const IntervalVector p1 = f.position(t[0]), p2 = f.position(t[1]);
    for (std::size_t i = 0; i < 2; ++i) fx[i] &= p2[i] - p1[i];
  }
  if (excludes_zero(fx[0]) || excludes_zero(fx[1])) {  // (6.8)
    t.set_empty();
    return;
  }
  if (!f.has_positions() && inner_bounds(lower, upper)) {  // (6.10)
    x_in.set_empty();
    return;
  }
  if (is_injective(f, t)) t.set_empty();  // (6.9), last: the other tests decide most boxes off the diagonal
}

}  // namespace

namespace {

SiviaResult run_of(const LoopFunction& f, const IntervalVector& square, double eps, bool parallel,
                   const Budget& budget, const char* where, const char* option) {
  detail::check_sivia_input(square, eps, where);
  if (square.size() != 2 || square.is_empty() || square[0] != square[1] || !(square[0].lb() < square[0].ub())) {
    throw Error(std::string(where) + ": the t-plane must be a square [a, b]^2 with a < b, got " + square.str());
  }
  if (!square[0].is_subset(f.time_domain())) {
    throw Error(std::string(where) + ": the t-plane " + square.str() + " is not inside the time domain " +
                f.time_domain().str() + " of the tubes");
  }
  auto test = [&f](IntervalVector& x_in, IntervalVector& x_out) { separate(f, x_in, x_out); };
  SiviaResult r = detail::run_paving(square, eps, test, parallel, budget, where, option);
  if (r.summary.status == Status::NoSolution) {
    r.summary.reason = std::string(where) + ": no loop: every t-box is proven outside the feasible loops";
  }
  return r;
}

}  // namespace

SiviaResult loop_sivia_run(const LoopFunction& f, const IntervalVector& square, double eps,
                           const SiviaOptions& options) {
  return run_of(f, square, eps, options.parallel, options.budget, kWhere, "options.budget");
}

Paving loop_sivia(const LoopFunction& f, const IntervalVector& square, double eps, const SiviaOptions& options) {
  return loop_sivia_run(f, square, eps, options).take();
}

bool detail::is_inner_box(const LoopFunction& f, const IntervalVector& t) {
  if (f.has_positions() || f.is_empty() || !(t[0].ub() < t[1].lb())) return false;
  const auto [lower, upper] = f.integral_bounds(t[0], t[1]);
  return inner_bounds(lower, upper);
}

SiviaResult detail::run_loop_paving(const LoopFunction& f, const IntervalVector& square, double eps,
                                    const Budget& budget, const char* where) {
  return run_of(f, square, eps, true, budget, where, "budget");
}

}  // namespace sillage
