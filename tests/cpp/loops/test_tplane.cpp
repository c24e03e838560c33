// TPlane (thesis ch. 6) on trajectories whose self-crossings are known in
// closed form: a limaçon (one crossing, at t = 2π/3 and 4π/3) and a prolate
// cycloid (one crossing per period, at 2πm ± s*, s* = 2 sin s*). Velocity
// tubes are the exact velocity ± e, so every true loop must be detected,
// and every crossing is transversal, so the degree is the sign of
// det J_f*(t*) = det(-v(t1*) | v(t2*)) and the count is 1.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sillage/error.h"
#include "sillage/loops/loop_function.h"
#include "sillage/loops/tplane.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {
namespace {

using std::numbers::pi;

struct Point {
  double x, y;
};

// ---- limaçon r = 1 + 2 cos θ: p = (cos t + 1 + cos 2t, sin t + sin 2t) ----
Point limacon_p(double t) { return {std::cos(t) + 1 + std::cos(2 * t), std::sin(t) + std::sin(2 * t)}; }
Point limacon_v(double t) { return {-std::sin(t) - 2 * std::sin(2 * t), std::cos(t) + 2 * std::cos(2 * t)}; }
const char* kLimaconV = "(-sin(t) - 2*sin(2*t) + [-0.01,0.01], cos(t) + 2*cos(2*t) + [-0.01,0.01])";
const char* kLimaconP = "(cos(t) + 1 + cos(2*t) + [-0.005,0.005], sin(t) + sin(2*t) + [-0.005,0.005])";

// ---- prolate cycloid p = (t - 2 sin t, 2 cos t) ----
Point cycloid_p(double t) { return {t - 2 * std::sin(t), 2 * std::cos(t)}; }
Point cycloid_v(double t) { return {1 - 2 * std::cos(t), -2 * std::sin(t)}; }
const char* kCycloidV = "(1 - 2*cos(t) + [-0.01,0.01], -2*sin(t) + [-0.01,0.01])";

// The positive root of s = 2 sin s (Newton from 2: converges to the last bit).
double cycloid_half_loop() {
  double s = 2.0;
  for (int i = 0; i < 50; ++i) s -= (s - 2 * std::sin(s)) / (1 - 2 * std::cos(s));
  return s;
}

// Sign of det(-v(t1) | v(t2)): the degree at a transversal crossing.
template <class V>
int crossing_degree(V v, double t1, double t2) {
  const Point a = v(t1), b = v(t2);
  const double det = -a.x * b.y + b.x * a.y;
  return det > 0 ? 1 : -1;
}

bool covers(const std::vector<IntervalVector>& boxes, double t1, double t2) {
  return std::any_of(boxes.begin(), boxes.end(), [&](const IntervalVector& b) { return b.contains({t1, t2}); });
}

// The detections (indices) whose boxes hold the point.
std::vector<std::size_t> detections_at(const TPlane& tp, double t1, double t2) {
  std::vector<std::size_t> r;
  for (std::size_t i = 0; i < tp.nb_detections(); ++i) {
    if (covers(tp.detections()[i].boxes(), t1, t2)) r.push_back(i);
  }
  return r;
}

TEST(TPlane, LimaconOneProvenLoop) {
  auto td = TDomain::create(0.3, 2 * pi - 0.3, 0.001);
  const TubeVector v(td, kLimaconV);
  TPlane tp(td);
  EXPECT_EQ(tp.domain(), IntervalVector({td->t0_tf(), td->t0_tf()}));
  const double eps = 0.02;
  tp.compute_detections(eps, v);
  EXPECT_EQ(tp.eps(), eps);
  // The speed is >= 1 everywhere and the ends are far apart: one detection.
  ASSERT_EQ(tp.nb_detections(), 1u);
  EXPECT_EQ(tp.nb_complete_detections(), 1u);
  const Loop& l = tp.detections()[0];
  const double t1 = 2 * pi / 3, t2 = 4 * pi / 3;
  EXPECT_TRUE(covers(l.boxes(), t1, t2));
  EXPECT_TRUE(l.t_box().contains({t1, t2}));
  EXPECT_GT(l.nb_inner(), 0u);  // a robust crossing: its neighbourhood is proven feasible
  EXPECT_TRUE(l.map_box().is_empty());
  EXPECT_FALSE(l.degree());
  EXPECT_EQ(tp.nb_proofs(), 0u);

  tp.compute_proofs(v);
  const Loop& p = tp.detections()[0];
  ASSERT_TRUE(p.degree());
  EXPECT_EQ(*p.degree(), crossing_degree(limacon_v, t1, t2));
  EXPECT_EQ(*p.degree(), 1);  // det = 3√3/2 > 0
  EXPECT_TRUE(p.proven());
  EXPECT_TRUE(p.proven_newton());
  ASSERT_TRUE(p.count());
  EXPECT_EQ(*p.count(), 1u);
  EXPECT_EQ(tp.nb_proofs(), 1u);
  EXPECT_EQ(tp.nb_newton_proofs(), 1u);
  ASSERT_EQ(tp.proofs().size(), 1u);
  EXPECT_EQ(tp.proofs()[0].t_box(), p.t_box());
  // From v, positions are relative to p(t0): the crossing point is the
  // origin, so it is at -p(t0) here.
  const Point start = limacon_p(td->t0());
  EXPECT_TRUE(p.map_box().contains({-start.x, -start.y})) << p.map_box();
  EXPECT_LT(p.map_box().max_diam(), 1.0);
}

TEST(TPlane, CycloidEveryLoopDetectedAndProven) {
  const int loops = 5;
  auto td = TDomain::create(0, 2 * pi * loops + pi, 0.01);
  const TubeVector v(td, kCycloidV);
  TPlane tp(td);
  tp.compute_detections(0.05, v);
  tp.compute_proofs(v);
  const double s = cycloid_half_loop();
  EXPECT_NEAR(s, 1.895494267033981, 1e-12);
  EXPECT_EQ(tp.nb_complete_detections(), static_cast<std::size_t>(loops));
  EXPECT_EQ(tp.nb_proofs(), static_cast<std::size_t>(loops));
  EXPECT_EQ(tp.nb_newton_proofs(), static_cast<std::size_t>(loops));
  std::vector<std::size_t> seen;
  for (int m = 1; m <= loops; ++m) {
    const double t1 = 2 * pi * m - s, t2 = 2 * pi * m + s;
    const auto at = detections_at(tp, t1, t2);
    ASSERT_EQ(at.size(), 1u) << "loop " << m;
    const Loop& l = tp.detections()[at[0]];
    EXPECT_TRUE(l.complete());
    ASSERT_TRUE(l.degree());
    EXPECT_EQ(*l.degree(), crossing_degree(cycloid_v, t1, t2));
    ASSERT_TRUE(l.count());
    EXPECT_EQ(*l.count(), 1u);
    const Point c = cycloid_p(t1), start = cycloid_p(0);
    EXPECT_TRUE(l.map_box().contains({c.x - start.x, c.y - start.y})) << l.map_box();
    seen.push_back(at[0]);
  }
  // Chronological order.
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  for (std::size_t i = 1; i < tp.nb_detections(); ++i) {
    EXPECT_LE(tp.detections()[i - 1].t_box()[0].lb(), tp.detections()[i].t_box()[0].lb());
  }
}

// Inner leaves must hold a loop of some velocity of the tube: since every
// velocity of the tube is within its thickness of the true one, the true
// displacement there is at most thickness * (t2 - t1) on each axis.
TEST(TPlane, InnerLeavesAreNearTrueLoops) {
  auto td = TDomain::create(0, 4 * pi + pi, 0.01);
  const TubeVector v(td, kCycloidV);
  TPlane tp(td);
  tp.compute_detections(0.002, v);
  const double thick = v.max_thickness();
  std::size_t checked = 0;
  for (const auto& b : tp.paving().inner()) {
    for (double t1 : {b[0].lb(), b[0].ub()}) {
      for (double t2 : {b[1].lb(), b[1].ub()}) {
        const Point a = cycloid_p(t1), c = cycloid_p(t2);
        const double bound = thick * (t2 - t1) + 1e-12;
        EXPECT_LE(std::abs(c.x - a.x), bound);
        EXPECT_LE(std::abs(c.y - a.y), bound);
        EXPECT_LT(t1, t2);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 0u);
}

// Brute force on the Outside claims. The tube holds every v* + c with c a
// constant vector, |c_i| <= e: if the true displacement d = p(t2) - p(t1)
// satisfies |d_i| <= e (t2 - t1), then v* - d / (t2 - t1) loops at
// (t1, t2), so (t1, t2) is a feasible loop and must not be Outside.
template <class P>
std::size_t check_feasible_points(const TPlane& tp, P p, double e, double t1c, double t2c, double half) {
  std::size_t feasible = 0;
  const int n = 120;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double t1 = t1c - half + 2 * half * i / n, t2 = t2c - half + 2 * half * j / n;
      const Point a = p(t1), b = p(t2);
      const double bound = 0.999 * e * (t2 - t1);
      if (std::abs(b.x - a.x) > bound || std::abs(b.y - a.y) > bound) continue;
      ++feasible;
      EXPECT_NE(tp.paving().tag_at({t1, t2}), std::optional<PavingTag>(PavingTag::Outside)) << t1 << " " << t2;
    }
  }
  return feasible;
}

TEST(TPlane, BruteForceFeasibleLoopsAreNeverOutside) {
  auto td = TDomain::create(0.3, 2 * pi - 0.3, 0.001);
  const TubeVector v(td, kLimaconV);
  TPlane tp(td);
  tp.compute_detections(0.005, v);
  EXPECT_GT(check_feasible_points(tp, limacon_p, 0.01, 2 * pi / 3, 4 * pi / 3, 0.03), 20u);

  auto tc = TDomain::create(0, 2 * pi * 3 + pi, 0.001);
  const TubeVector vc(tc, kCycloidV);
  TPlane tpc(tc);
  tpc.compute_detections(0.005, vc);
  const double s = cycloid_half_loop();
  for (int m = 1; m <= 3; ++m) {
    EXPECT_GT(check_feasible_points(tpc, cycloid_p, 0.01, 2 * pi * m - s, 2 * pi * m + s, 0.03), 20u);
  }
}

TEST(TPlane, StraightLineHasNoDetection) {
  auto td = TDomain::create(0, 100, 0.1);
  const TubeVector v(td, "(1 + [-0.01,0.01], 0.5 + [-0.01,0.01])");
  TPlane tp(td);
  tp.compute_detections(0.01, v);
  EXPECT_EQ(tp.nb_detections(), 0u);
  EXPECT_TRUE(tp.paving().outer().empty());
  // The injectivity test (6.9) decides the whole square in a few boxes.
  EXPECT_LT(tp.paving().nb_leaves(), 10u);
  tp.compute_proofs(v);
  EXPECT_EQ(tp.nb_proofs(), 0u);
}

// A robot that may stand still: loops are feasible right on the diagonal,
// and such detections are never complete.
TEST(TPlane, DiagonalAndBorderDetectionsAreIncomplete) {
  auto td = TDomain::create(0, 10, 0.1);
  const TubeVector still(td, IntervalVector{Interval(-0.01, 0.01), Interval(-0.01, 0.01)});
  TPlane tp(td);
  tp.compute_detections(0.5, still);
  EXPECT_GE(tp.nb_detections(), 1u);
  EXPECT_EQ(tp.nb_complete_detections(), 0u);
  tp.compute_proofs(still);
  EXPECT_EQ(tp.nb_proofs(), 0u);
  for (const Loop& l : tp.detections()) EXPECT_FALSE(l.degree());

  // The whole limaçon, [0, 2π]: p(0) = p(2π), a loop at the corner of the square.
  auto full = TDomain::create(0, 2 * pi, 0.001);
  const TubeVector v(full, kLimaconV);
  TPlane tf(full);
  tf.compute_detections(0.02, v);
  EXPECT_EQ(tf.nb_complete_detections(), 1u);
  EXPECT_EQ(detections_at(tf, 0, 2 * pi).size(), 1u);
  EXPECT_FALSE(tf.detections()[detections_at(tf, 0, 2 * pi)[0]].complete());
  EXPECT_EQ(detections_at(tf, 2 * pi / 3, 4 * pi / 3).size(), 1u);
  EXPECT_TRUE(tf.detections()[detections_at(tf, 2 * pi / 3, 4 * pi / 3)[0]].complete());
}

TEST(TPlane, PositionsGiveASubsetOfTheVelocityDetections) {
  auto td = TDomain::create(0.3, 2 * pi - 0.3, 0.001);
  const TubeVector v(td, kLimaconV);
  const TubeVector p(td, kLimaconP);
  TPlane tv(td), tpw(td);
  const double eps = 0.02;
  tv.compute_detections(eps, v);
  tpw.compute_detections(eps, p, v);
  EXPECT_EQ(tpw.paving().count(PavingTag::Inner), 0u);  // no Inner leaf with positions
  const auto outer_v = tv.paving().outer();
  for (const auto& b : tpw.paving().outer()) {
    EXPECT_TRUE(std::any_of(outer_v.begin(), outer_v.end(), [&](const IntervalVector& a) { return b.is_subset(a); }))
        << b;
  }
  EXPECT_LT(tpw.paving().outer_volume(), tv.paving().outer_volume());
  ASSERT_EQ(tpw.nb_complete_detections(), 1u);
  tpw.compute_proofs(p, v);
  const Loop& l = tpw.detections()[0];
  EXPECT_TRUE(covers(l.boxes(), 2 * pi / 3, 4 * pi / 3));
  ASSERT_TRUE(l.degree());
  EXPECT_EQ(*l.degree(), 1);
  EXPECT_TRUE(l.proven_newton());
  EXPECT_EQ(l.count(), std::optional<std::size_t>(1));
  EXPECT_TRUE(l.map_box().contains({0.0, 0.0})) << l.map_box();  // absolute positions with p
}

TEST(TPlane, ResultsDoNotDependOnThreads) {
  auto td = TDomain::create(0, 2 * pi * 4 + pi, 0.01);
  const TubeVector v(td, kCycloidV);
  auto run = [&](std::size_t threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    TPlane tp(td);
    tp.compute_detections(0.05, v);
    tp.compute_proofs(v);
    return tp;
  };
  const TPlane a = run(1), b = run(4);
  EXPECT_EQ(a.paving(), b.paving());
  ASSERT_EQ(a.nb_detections(), b.nb_detections());
  for (std::size_t i = 0; i < a.nb_detections(); ++i) {
    const Loop &x = a.detections()[i], &y = b.detections()[i];
    EXPECT_EQ(x.t_box(), y.t_box());
    EXPECT_EQ(x.boxes(), y.boxes());
    EXPECT_EQ(x.map_box(), y.map_box());
    EXPECT_EQ(x.degree(), y.degree());
    EXPECT_EQ(x.count(), y.count());
    EXPECT_EQ(x.proven_newton(), y.proven_newton());
  }
}

TEST(TPlane, ProofOptionsSwitchTestsOff) {
  auto td = TDomain::create(0.3, 2 * pi - 0.3, 0.001);
  const TubeVector v(td, kLimaconV);
  TPlane tp(td);
  tp.compute_detections(0.02, v);
  ProofOptions no_newton;
  no_newton.newton = false;
  no_newton.count = false;
  tp.compute_proofs(v, no_newton);
  EXPECT_TRUE(tp.detections()[0].proven());
  EXPECT_FALSE(tp.detections()[0].proven_newton());
  EXPECT_FALSE(tp.detections()[0].count());
}

// ---- a Lissajous survey, 30 min: many crossings, some close to each other ----
const double kW1 = 2 * pi * 7 / 3600, kW2 = 2 * pi * 8.3 / 3600;
Point survey_p(double t) { return {120 * std::sin(kW1 * t), 120 * std::sin(kW2 * t + 0.4)}; }

struct Crossing {
  double t1, t2;
};

// True self-crossings of the path, from its polyline at step h (the chord
// error is ~1e-3 s here, far below the size of the feasible neighbourhood
// of a crossing, which is > 0.1 s).
std::vector<Crossing> true_crossings(double t0, double tf, double h) {
  std::vector<double> t;
  std::vector<Point> q;
  for (double s = t0; s <= tf; s += h) {
    t.push_back(s);
    q.push_back(survey_p(s));
  }
  auto cross = [](Point a, Point b, Point c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); };
  std::vector<Crossing> r;
  for (std::size_t i = 0; i + 1 < q.size(); ++i) {
    for (std::size_t j = i + 2; j + 1 < q.size(); ++j) {
      const Point a = q[i], b = q[i + 1], c = q[j], d = q[j + 1];
      if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
          std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y)) {
        continue;
      }
      const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
      if ((d1 > 0) == (d2 > 0) || (d3 > 0) == (d4 > 0)) continue;
      const double u = d1 / (d1 - d2), w = d3 / (d3 - d4);
      r.push_back({t[i] + u * h, t[j] + w * h});
    }
  }
  return r;
}

// The velocity of the Lissajous survey of true_crossings, known to ±0.01 m/s.
TubeVector survey_velocity(const std::shared_ptr<TDomain>& td) {
  const std::string w1 = "(2*pi*7/3600)", w2 = "(2*pi*8.3/3600)";
  return TubeVector(td, "(120*" + w1 + "*cos(" + w1 + "*t) + [-0.01,0.01], 120*" + w2 + "*cos(" + w2 +
                            "*t + 0.4) + [-0.01,0.01])");
}

// Every claim of the proofs holds for the true trajectory, whose velocity
// lies in the tube: a count is the exact number of true crossings in the
// detection, a proof holds one at least, a Newton proof exactly one.
TEST(TPlane, SurveyClaimsHoldForTheTrueTrajectory) {
  const double T = 1800;
  auto td = TDomain::create(0, T, 0.1);
  const TubeVector v = survey_velocity(td);
  TPlane tp(td);
  tp.compute_detections(T / 2000, v);
  tp.compute_proofs(v);
  const auto crossings = true_crossings(0, T, 0.25);
  ASSERT_GE(crossings.size(), 10u);
  std::vector<std::size_t> inside(tp.nb_detections(), 0);
  for (const Crossing& c : crossings) {
    const auto at = detections_at(tp, c.t1, c.t2);
    ASSERT_EQ(at.size(), 1u) << c.t1 << " " << c.t2;
    ++inside[at[0]];
  }
  std::size_t counted = 0;
  for (std::size_t i = 0; i < tp.nb_detections(); ++i) {
    const Loop& l = tp.detections()[i];
    if (l.proven()) {
      EXPECT_GE(inside[i], 1u) << l.t_box();
    }
    if (l.count()) {
      EXPECT_EQ(*l.count(), inside[i]) << l.t_box();
      ++counted;
    }
    if (l.degree() || l.proven_newton()) {
      EXPECT_TRUE(l.complete());
    }
    if (l.proven_newton()) {
      EXPECT_EQ(inside[i], 1u);
      // The hull meets no other detection.
      for (std::size_t j = 0; j < tp.nb_detections(); ++j) {
        if (j == i) continue;
        for (const auto& b : tp.detections()[j].boxes()) EXPECT_FALSE(b.intersects(l.t_box()));
      }
    }
  }
  EXPECT_GE(tp.nb_proofs(), crossings.size() / 2);
  EXPECT_GE(counted, tp.nb_proofs() / 2);
  // The pieces of split detections: the same claims, and their degrees add up.
  for (std::size_t i = 0; i < tp.nb_detections(); ++i) {
    const Loop& l = tp.detections()[i];
    int degree = 0;
    bool determined = true;
    std::size_t in_pieces = 0;
    for (const Loop& p : l.pieces()) {
      std::size_t inside_piece = 0;
      for (const Crossing& c : crossings) {
        for (const auto& b : p.boxes()) {
          if (b[0].contains(c.t1) && b[1].contains(c.t2)) {
            ++inside_piece;
            break;
          }
        }
      }
      in_pieces += inside_piece;
      if (p.proven()) { EXPECT_GE(inside_piece, 1u) << p.t_box(); }
      if (p.count()) { EXPECT_EQ(*p.count(), inside_piece) << p.t_box(); }
      EXPECT_TRUE(p.t_box().is_subset(l.t_box()));
      EXPECT_TRUE(p.pieces().empty());
      determined = determined && p.degree();
      degree += p.degree().value_or(0);
    }
    if (!l.pieces().empty()) { EXPECT_EQ(in_pieces, inside[i]); }  // every loop lies in a piece
    if (!l.pieces().empty() && determined && l.degree()) { EXPECT_EQ(degree, *l.degree()); }
  }
  for (const Loop& p : tp.proofs()) EXPECT_TRUE(p.proven());
  EXPECT_GE(tp.proofs().size(), tp.nb_proofs());
}

TEST(TPlane, BadInput) {
  EXPECT_THROW(TPlane(Interval(1, 1)), Error);
  EXPECT_THROW(TPlane(Interval(0, std::numeric_limits<double>::infinity())), Error);
  EXPECT_THROW(TPlane(Interval::empty()), Error);
  EXPECT_THROW(TPlane(std::shared_ptr<TDomain>()), Error);
  auto td = TDomain::create(0, 5, 0.1);
  const TubeVector v(td, IntervalVector{Interval(1, 2), Interval(-1, 1)});
  const TubeVector v3(td, 3, Interval(1, 2));
  TPlane tp(td);
  EXPECT_THROW(tp.compute_proofs(v), Error);  // no detections yet
  EXPECT_THROW(tp.compute_detections(0.1, v3), DimensionError);
  EXPECT_THROW(tp.compute_detections(0.1, v, v3), DimensionError);
  EXPECT_THROW(tp.compute_detections(0.1, v3, v), DimensionError);
  EXPECT_THROW(tp.compute_detections(0.0, v), Error);
  EXPECT_THROW(tp.compute_detections(-1.0, v), Error);
  EXPECT_THROW(tp.compute_detections(std::numeric_limits<double>::quiet_NaN(), v), Error);
  // A tube that does not cover the t-plane.
  const TubeVector shorter(TDomain::create(1, 5, 0.1), IntervalVector{Interval(1, 2), Interval(-1, 1)});
  EXPECT_THROW(tp.compute_detections(0.1, shorter), Error);
  EXPECT_THROW(tp.compute_detections(0.1, shorter, v), Error);
  // A larger tube domain is fine.
  TPlane inner(Interval(1, 4));
  EXPECT_NO_THROW(inner.compute_detections(0.1, v));
  EXPECT_THROW(inner.compute_proofs(v3), DimensionError);
  ProofOptions bad;
  bad.degree_edge_fraction = 0;
  EXPECT_THROW(inner.compute_proofs(v, bad), Error);
}

// A detection of degree 0 holding two crossings of opposite orientations
// (the 1 h Lissajous survey at eps = T/1000): the split proves both, each in
// its own piece, and the pieces' degrees add up to 0.
TEST(TPlane, SplitProvesTwoCrossingsInADegreeZeroDetection) {
  const double T = 3600;
  auto td = TDomain::create(0, T, 0.5);
  const TubeVector v = survey_velocity(td);
  TPlane tp(td);
  tp.compute_detections(T / 1000, v);
  tp.compute_proofs(v);
  const auto crossings = true_crossings(0, T, 0.25);
  std::size_t split = 0;
  for (const Loop& l : tp.detections()) {
    if (l.degree() != 0 || l.nb_proven_pieces() < 2) continue;
    ++split;
    EXPECT_FALSE(l.proven());
    EXPECT_TRUE(l.proven_split());
    EXPECT_EQ(l.count(), 2u);
    int sum = 0;
    for (const Loop& p : l.pieces()) {
      ASSERT_TRUE(p.degree());
      sum += *p.degree();
      if (!p.proven()) continue;
      std::size_t inside = 0;
      for (const Crossing& c : crossings) {
        for (const auto& b : p.boxes()) {
          if (b[0].contains(c.t1) && b[1].contains(c.t2)) {
            ++inside;
            break;
          }
        }
      }
      EXPECT_EQ(inside, 1u);
    }
    EXPECT_EQ(sum, 0);
  }
  EXPECT_GE(split, 1u);
  // Without the split, the same detection proves nothing; bad split options are refused.
  ProofOptions o;
  o.split = false;
  tp.compute_proofs(v, o);
  for (const Loop& l : tp.detections()) EXPECT_TRUE(l.pieces().empty());
  o.split = true;
  o.split_max_levels = 0;
  EXPECT_THROW(tp.compute_proofs(v, o), Error);
}

}  // namespace
}  // namespace sillage
