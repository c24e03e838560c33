// LoopFunction: [f] (6.6) and (7.28), [J_f] (6.18), positions and the
// bound integrals (6.11) on hand-computed tubes; loop_sivia's claims
// against these values; bad input.
#include <gtest/gtest.h>

#include <vector>

#include "sillage/error.h"
#include "sillage/loops/loop_function.h"
#include "sillage/loops/loop_sivia.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {
namespace {

// Component 1: slices [1,2], [-1,3], [0,0.5], [2,4] on [0,4], so that
// L = 0,1,0,0,2 and U = 0,2,5,5.5,9.5 at t = 0..4. Component 2: exactly 1.
TubeVector small_velocity() {
  auto td = TDomain::create(0, 4, 1);
  return TubeVector({Tube(td, std::vector<Interval>{{1, 2}, {-1, 3}, {0, 0.5}, {2, 4}}), Tube(td, Interval(1))});
}

TEST(LoopFunction, VelocityFormHandComputed) {
  const TubeVector v = small_velocity();
  const LoopFunction f(v);
  EXPECT_FALSE(f.has_positions());
  EXPECT_FALSE(f.is_empty());
  EXPECT_EQ(f.time_domain(), Interval(0, 4));
  const IntervalVector t{Interval(0.5, 1.5), Interval(2.5, 4)};
  // Component 1 as in the integral tests; component 2: t2 - t1 ∈ [1, 3.5].
  EXPECT_EQ(f(t), IntervalVector({Interval(-1, 8.5), Interval(1, 3.5)}));
  EXPECT_EQ(f.velocity_form(t), f(t));
  const auto [lower, upper] = f.integral_bounds(t[0], t[1]);
  EXPECT_EQ(lower, IntervalVector({Interval(-1, 1.5), Interval(1, 3.5)}));
  EXPECT_EQ(upper, IntervalVector({Interval(1.75, 8.5), Interval(1, 3.5)}));
  // (6.18): columns -[v]([t1]) and [v]([t2]); [v1]([0.5,1.5]) = [-1,3] (slices 0, 1),
  // [v1]([2.5,4]) = [0,4] (slices 2, 3 and the gates between).
  EXPECT_EQ(f.jacobian(t), IntervalMatrix({{Interval(-3, 1), Interval(0, 4)}, {Interval(-1), Interval(1)}}));
  // Positions from 0 at t = 0: [L, U] hulls; L([2.5,4]) ⊂ [0,2], U([2.5,4]) ⊂ [5.25,9.5].
  EXPECT_EQ(f.position(Interval(2.5, 4)), IntervalVector({Interval(0, 9.5), Interval(2.5, 4)}));
  EXPECT_EQ(f.position(Interval(0)), IntervalVector({Interval(0), Interval(0)}));
  // The callables answer the same.
  EXPECT_EQ(f.function()(t), f(t));
  EXPECT_EQ(f.jacobian_function()(t), f.jacobian(t));
  // Points outside [0, 4] are ignored; a point on the diagonal gives 0.
  EXPECT_EQ(f(IntervalVector{Interval(-2, 0.5), Interval(2.5, 9)}), f(IntervalVector{Interval(0, 0.5), Interval(2.5, 4)}));
  EXPECT_EQ(f(IntervalVector{Interval(2), Interval(2)}), IntervalVector({Interval(0), Interval(0)}));
  EXPECT_TRUE(f(IntervalVector::empty(2)).is_empty());
}

TEST(LoopFunction, PositionFormIntersects) {
  const TubeVector w = small_velocity();
  auto td = w.tdomain();
  // Positions known to ±0.25 around (t, t), on a finer TDomain of their own:
  // p([0.5,1.5]) = [0.25,1.75], p([2.5,4]) = [2.25,4.25], so Δp = [0.5, 4].
  auto fine = TDomain::create(0, 4, 0.5);
  const TubeVector p(fine, "(t + [-0.25,0.25], t + [-0.25,0.25])");
  const LoopFunction f(p, w);
  EXPECT_TRUE(f.has_positions());
  const IntervalVector t{Interval(0.5, 1.5), Interval(2.5, 4)};
  const IntervalVector dp = f.position(t[1]) - f.position(t[0]);
  EXPECT_EQ(dp, IntervalVector({Interval(0.5, 4), Interval(0.5, 4)}));
  EXPECT_EQ(f(t), IntervalVector({Interval(0.5, 4), Interval(1, 3.5)}));  // (7.28)
  EXPECT_EQ(f.velocity_form(t), IntervalVector({Interval(-1, 8.5), Interval(1, 3.5)}));
  // Inconsistent p and w: (7.28) is empty, the callable falls back on ∫w.
  const TubeVector far(fine, "(-t + [-0.25,0.25], t)");  // p1 decreases while ∫w1 > 0
  const LoopFunction g(far, w);
  const IntervalVector u{Interval(0, 0.5), Interval(3.5, 4)};
  EXPECT_TRUE(g(u).is_empty());
  EXPECT_EQ(g.function()(u), g.velocity_form(u));
}

TEST(LoopFunction, BadInput) {
  auto td = TDomain::create(0, 4, 1);
  const TubeVector v3(td, 3, Interval(1));
  EXPECT_THROW(LoopFunction{v3}, DimensionError);
  const TubeVector v = small_velocity();
  EXPECT_THROW(LoopFunction(v3, v), DimensionError);
  EXPECT_THROW(LoopFunction(v, v3), DimensionError);
  const TubeVector later(TDomain::create(5, 9, 1), 2, Interval(1));
  EXPECT_THROW(LoopFunction(later, v), Error);
  const LoopFunction f(v);
  EXPECT_THROW(f(IntervalVector{Interval(5, 6), Interval(1, 2)}), Error);
  EXPECT_THROW(f(IntervalVector{Interval(1, 2)}), DimensionError);
  EXPECT_THROW(f.velocity(Interval(3, 5)), Error);
  EXPECT_THROW(f.position(Interval(-1, 1)), Error);
  // loop_sivia checks its square.
  EXPECT_THROW(loop_sivia(f, IntervalVector{Interval(0, 4), Interval(0, 3)}, 0.1), Error);
  EXPECT_THROW(loop_sivia(f, IntervalVector{Interval(0, 5), Interval(0, 5)}, 0.1), Error);
  EXPECT_THROW(loop_sivia(f, IntervalVector{Interval(1, 1), Interval(1, 1)}, 0.1), Error);
  EXPECT_THROW(loop_sivia(f, IntervalVector{Interval(0, 4), Interval(0, 4)}, 0), Error);
}

// The trees refer to the tubes: a LoopFunction that outlives them throws.
TEST(LoopFunction, OutlivedTubesAreAnError) {
  const LoopFunction f(small_velocity());
  EXPECT_THROW(f(IntervalVector{Interval(0, 1), Interval(2, 3)}), Error);
  EXPECT_THROW(f.velocity(Interval(0, 1)), Error);
}

// memoized_function answers what function() answers, on every box of a
// paving-like grid queried twice (the second time from its kept ranges), in
// both forms, outside the domain and on an empty tube; a tube modified since
// is an error even for ranges already kept.
TEST(LoopFunction, MemoizedFunctionAnswersTheSame) {
  const TubeVector w = small_velocity();
  const TubeVector p(TDomain::create(0, 4, 0.5), "(t + [-0.25,0.25], t + [-0.25,0.25])");
  const TubeVector far(TDomain::create(0, 4, 0.5), "(-t + [-0.25,0.25], t)");
  for (const LoopFunction& f : {LoopFunction(w), LoopFunction(p, w), LoopFunction(far, w)}) {
    const PlaneFunction plain = f.function(), memo = f.memoized_function();
    for (int pass = 0; pass < 2; ++pass) {
      for (double a = -0.5; a < 4.5; a += 0.25) {
        for (double b = a; b < 4.5; b += 0.75) {
          const IntervalVector box{Interval(a, a + 0.25), Interval(b, b + 0.75)};
          if ((box & IntervalVector{Interval(0, 4), Interval(0, 4)}).is_empty()) {
            EXPECT_THROW(memo(box), Error);
            continue;
          }
          EXPECT_EQ(memo(box), plain(box)) << box;
          const IntervalVector point{Interval(a), Interval(b)};
          if (a >= 0 && b <= 4) { EXPECT_EQ(memo(point), plain(point)) << point; }
        }
      }
    }
  }
  auto td = TDomain::create(0, 4, 1);
  const TubeVector holed({Tube(td, std::vector<Interval>{{-1, 1}, Interval::empty(), {-1, 1}, {-1, 1}}),
                          Tube(td, Interval(-1, 1))});
  const IntervalVector box{Interval(0, 1), Interval(2, 3)};
  EXPECT_EQ(LoopFunction(holed).memoized_function()(box), LoopFunction(holed).function()(box));

  TubeVector v = small_velocity();
  const PlaneFunction memo = LoopFunction(v).memoized_function();
  memo(box);
  v[0].set(Interval(0, 1));
  EXPECT_THROW(memo(box), Error);  // the same box, its ranges kept: still refused
}

// A tube with an empty slice holds no trajectory: no detection at all.
TEST(LoopFunction, EmptyTubeHasNoLoop) {
  auto td = TDomain::create(0, 4, 1);
  const TubeVector v({Tube(td, std::vector<Interval>{{-1, 1}, Interval::empty(), {-1, 1}, {-1, 1}}),
                      Tube(td, Interval(-1, 1))});
  const LoopFunction f(v);
  EXPECT_TRUE(f.is_empty());
  const Paving p = loop_sivia(f, IntervalVector{Interval(0, 4), Interval(0, 4)}, 0.1);
  EXPECT_TRUE(p.outer().empty());
}

// Alg. 6 on the small tube, claims checked against the exact set: with
// v2 = 1, no loop exists at all (p2 is strictly increasing).
TEST(LoopFunction, LoopSiviaInjectiveComponent) {
  const TubeVector v = small_velocity();
  const LoopFunction f(v);
  const Paving p = loop_sivia(f, IntervalVector{Interval(0, 4), Interval(0, 4)}, 0.01);
  EXPECT_TRUE(p.outer().empty());
  EXPECT_EQ(p.nb_leaves(), 1u);  // (6.9) on the whole square at once
}

}  // namespace
}  // namespace sillage
