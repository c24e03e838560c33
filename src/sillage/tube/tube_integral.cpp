#include "sillage/tube/tube_integral.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "sillage/error.h"
#include "sillage/tube/primitive_difference.h"

namespace sillage {

namespace {

void check_inside(const SynthesisTree& x, const Interval& t, const char* what, const char* where) {
  if (!t.is_subset(Interval(x.t0(), x.tf()))) {
    throw Error(std::string(where) + ": " + what + " = " + t.str() + " is not inside the domain [" + number_text(x.t0()) +
                ", " + number_text(x.tf()) + "]");
  }
}

Interval checked_point(const SynthesisTree& x, double t, const char* what, const char* where) {
  if (!(t >= x.t0() && t <= x.tf())) {
    throw Error(std::string(where) + ": " + what + " = " + number_text(t) + " is outside the domain [" + number_text(x.t0()) +
                ", " + number_text(x.tf()) + "]");
  }
  return Interval(t);
}

}  // namespace

// ---- over a synthesis tree ----

std::pair<Interval, Interval> partial_integral(const SynthesisTree& x, const Interval& t1, const Interval& t2) {
  check_inside(x, t1, "[t1]", "partial_integral(x, [t1], [t2])");
  check_inside(x, t2, "[t2]", "partial_integral(x, [t1], [t2])");
  if (t1.is_empty() || t2.is_empty()) return {Interval::empty(), Interval::empty()};
  detail::PrimitiveRanges r1, r2;
  x.ranges(t1, r1.lower, r1.upper);  // also checks that a tube's tree is current
  x.ranges(t2, r2.lower, r2.upper);
  if (x.has_empty_slice()) return {Interval::empty(), Interval::empty()};
  return detail::partial_integral_of(r1, r2);
}

Interval integral(const SynthesisTree& x, const Interval& t1, const Interval& t2) {
  return detail::integral_of(partial_integral(x, t1, t2), t1, t2);
}

Interval integral(const SynthesisTree& x, double t1, double t2) {
  return integral(x, checked_point(x, t1, "t1", "integral(x, t1, t2)"),
                  checked_point(x, t2, "t2", "integral(x, t1, t2)"));
}

Interval integral(const SynthesisTree& x, double t) {
  return integral(x, Interval(x.t0()), checked_point(x, t, "t", "integral(x, t)"));
}

Interval integral(const SynthesisTree& x, const Interval& t) {
  check_inside(x, t, "[t]", "integral(x, [t])");
  return integral(x, Interval(x.t0()), t);
}

// ---- over a tube ----

Interval integral(const Tube& x, double t) { return integral(*x.synthesis_tree(), t); }
Interval integral(const Tube& x, const Interval& t) { return integral(*x.synthesis_tree(), t); }
Interval integral(const Tube& x, double t1, double t2) { return integral(*x.synthesis_tree(), t1, t2); }
Interval integral(const Tube& x, const Interval& t1, const Interval& t2) {
  return integral(*x.synthesis_tree(), t1, t2);
}
std::pair<Interval, Interval> partial_integral(const Tube& x, const Interval& t1, const Interval& t2) {
  return partial_integral(*x.synthesis_tree(), t1, t2);
}

Tube primitive(const Tube& x, const Interval& x0) {
  const auto& td = x.tdomain();
  const std::size_t n = x.nb_slices();
  const auto times = td->times();
  const auto in = x.slices();
  bool empty = x0.is_empty();
  for (std::size_t k = 0; k < n && !empty; ++k) empty = in[k].is_empty();
  if (empty) return Tube(td, Interval::empty());
  std::vector<Interval> slices(n), gates(n + 1);
  gates[0] = x0;
  for (std::size_t k = 0; k < n; ++k) {
    const Interval width = Interval(times[k + 1]) - Interval(times[k]);
    gates[k + 1] = gates[k] + width * in[k];
    // t - t_k ranges over [0, exact width] ⊂ [0, ub(width)].
    slices[k] = gates[k] + Interval(0.0, width.ub()) * in[k];
  }
  return Tube(td, slices, gates);
}

// ---- TubeAnalysis ----

std::shared_ptr<const SynthesisTree> TubeAnalysis::tree() const { return x_->synthesis_tree(); }

}  // namespace sillage
