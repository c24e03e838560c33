#include "sillage/loops/loop_function.h"

#include <algorithm>
#include <string>

#include "sillage/error.h"
#include "sillage/tube/tube_integral.h"

namespace sillage {

namespace {

Interval time_domain_of(const TubeVector& x) { return x.tdomain()->t0_tf(); }

}  // namespace

LoopFunction::Trees LoopFunction::trees_of(const TubeVector& x, const char* what, const char* where) {
  if (x.size() != 2) {
    throw DimensionError(std::string(where) + ": the " + what + " tube has dimension " + std::to_string(x.size()) +
                         ", expected 2 (planar trajectories)");
  }
  // Built here, once and sequentially: queries from threads then only read them.
  return {x[0].synthesis_tree(), x[1].synthesis_tree()};
}

LoopFunction::LoopFunction(const TubeVector& v)
    : v_(trees_of(v, "velocity", "LoopFunction(v)")), domain_(time_domain_of(v)) {}

LoopFunction::LoopFunction(const TubeVector& p, const TubeVector& w)
    : v_(trees_of(w, "velocity (w)", "LoopFunction(p, w)")),
      p_(trees_of(p, "position (p)", "LoopFunction(p, w)")),
      domain_(time_domain_of(p) & time_domain_of(w)) {
  if (domain_.is_empty() || domain_.is_degenerate()) {
    throw Error("LoopFunction(p, w): the time domains of p " + time_domain_of(p).str() + " and w " +
                time_domain_of(w).str() + " do not overlap");
  }
}

bool LoopFunction::is_empty() const {
  for (const auto& trees : {v_, p_}) {
    for (const auto& t : trees) {
      if (t && t->has_empty_slice()) return true;
    }
  }
  return false;
}

void LoopFunction::check_inside(const Interval& t, const char* where) const {
  if (!t.is_subset(domain_)) {
    throw Error(std::string(where) + ": [t] = " + t.str() + " is not inside the time domain " + domain_.str());
  }
}

IntervalVector LoopFunction::clamp(const IntervalVector& t, const char* where) const {
  if (t.size() != 2) {
    throw DimensionError(std::string(where) + ": a t-box has dimension 2, got " + std::to_string(t.size()));
  }
  IntervalVector c{t[0] & domain_, t[1] & domain_};
  if (c.is_empty() && !t.is_empty()) {
    throw Error(std::string(where) + ": the t-box " + t.str() + " has no point in the time domain " +
                domain_.str());
  }
  return c;
}

IntervalVector LoopFunction::velocity(const Interval& t) const {
  check_inside(t, "LoopFunction::velocity");
  return {v_[0]->eval(t), v_[1]->eval(t)};
}

IntervalVector LoopFunction::position(const Interval& t) const {
  check_inside(t, "LoopFunction::position");
  if (has_positions()) return {p_[0]->eval(t), p_[1]->eval(t)};
  return {integral(*v_[0], t), integral(*v_[1], t)};
}

std::pair<IntervalVector, IntervalVector> LoopFunction::integral_bounds(const Interval& t1, const Interval& t2) const {
  const auto [l0, u0] = partial_integral(*v_[0], t1, t2);
  const auto [l1, u1] = partial_integral(*v_[1], t1, t2);
  return {IntervalVector{l0, l1}, IntervalVector{u0, u1}};
}

IntervalVector LoopFunction::velocity_form(const IntervalVector& box) const {
  const IntervalVector t = clamp(box, "LoopFunction");
  if (t.is_empty()) return IntervalVector::empty(2);
  return {integral(*v_[0], t[0], t[1]), integral(*v_[1], t[0], t[1])};
}

IntervalVector LoopFunction::operator()(const IntervalVector& box) const {
  return with_positions(velocity_form(box), box);
}

IntervalVector LoopFunction::with_positions(IntervalVector f, const IntervalVector& box) const {
  if (has_positions() && !f.is_empty()) {
    const IntervalVector t = clamp(box, "LoopFunction");
    for (std::size_t i = 0; i < 2; ++i) f[i] &= p_[i]->eval(t[1]) - p_[i]->eval(t[0]);  // (7.28)
    if (f.is_empty()) f.set_empty();  // every component empty
  }
  return f;
}

IntervalVector LoopFunction::for_zero_tests(const IntervalVector& t, const IntervalVector& velocity_form) const {
  IntervalVector r = with_positions(velocity_form, t);
  // The zero tests take an empty image of a non-empty box for a broken
  // inclusion function; here it only means that p and w admit no common
  // trajectory there. ∫[w] alone still encloses every f* of w.
  if (r.is_empty() && !t.is_empty() && has_positions()) r = velocity_form;
  return r;
}

IntervalMatrix LoopFunction::jacobian(const IntervalVector& box) const {
  const IntervalVector t = clamp(box, "LoopFunction::jacobian");
  if (t.is_empty()) return IntervalMatrix::empty(2, 2);
  // Leibniz' rule (6.17): ∂f/∂t1 = -v(t1), ∂f/∂t2 = v(t2).
  const IntervalVector v1 = velocity(t[0]), v2 = velocity(t[1]);
  return IntervalMatrix{{-v1[0], v2[0]}, {-v1[1], v2[1]}};
}

PlaneFunction LoopFunction::function() const {
  return [f = *this](const IntervalVector& t) { return f.for_zero_tests(t, f.velocity_form(t)); };
}

PlaneJacobian LoopFunction::jacobian_function() const {
  return [f = *this](const IntervalVector& t) { return f.jacobian(t); };
}

}  // namespace sillage
