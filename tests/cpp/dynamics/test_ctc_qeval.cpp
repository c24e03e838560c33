// CtcQEval: position fixes on a tube, some of them wrong. A 2-D trajectory
// x(t) = (cos t, sin t) known through its derivative, ten fixes of which two
// are wrong: q = 0 and q = 1 prove inconsistency, q = 2 keeps the truth and a
// thin tube, and a second pass names the two wrong fixes.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dynamics/circle_mission.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_qeval.h"

using namespace sillage;

namespace {

struct Fixes : test::CircleMission {
  std::vector<TubeObservation> obs;

  explicit Fixes(const std::vector<std::size_t>& wrong) {
    for (std::size_t i = 0; i < 10; ++i) {
      const double t = 0.5 + static_cast<double>(i);
      IntervalVector z{Interval(std::cos(t)).inflate(0.05), Interval(std::sin(t)).inflate(0.05)};
      for (std::size_t w : wrong) {
        if (w == i) z += IntervalVector{Interval(2.0), Interval(-1.0)};
      }
      obs.push_back({Interval(t).inflate(0.01), z});
    }
  }
};

}  // namespace

TEST(CtcQEval, TwoWrongFixes) {
  for (int q = 0; q <= 1; ++q) {
    Fixes f({3, 7});
    CtcQEval(q).contract(f.x, f.v, f.obs);
    EXPECT_TRUE(f.x.is_empty()) << "q " << q;
  }
  Fixes f({3, 7});
  const TubeVector before = f.x;
  EXPECT_TRUE(CtcQEval(2).contract(f.x, f.v, f.obs).empty());  // each fix alone fits the wide tube
  EXPECT_TRUE(f.x.is_subset(before));
  EXPECT_TRUE(test::holds_circle(f.x));
  EXPECT_LT(f.x.max_thickness(), 0.3);
  // On the contracted tube the two wrong fixes are violated by every trajectory.
  EXPECT_EQ(CtcQEval(2).contract(f.x, f.v, f.obs), (std::vector<std::size_t>{3, 7}));
  EXPECT_TRUE(test::holds_circle(f.x));
}

TEST(CtcQEval, NoWrongFixIsTheIntersectionAndLargeQTheIdentity) {
  Fixes f({});
  CtcQEval(0).contract(f.x, f.v, f.obs);
  EXPECT_TRUE(test::holds_circle(f.x));
  EXPECT_LT(f.x.max_thickness(), 0.3);
  Fixes g({});
  const TubeVector before = g.x;
  CtcQEval(10).contract(g.x, g.v, g.obs);
  EXPECT_EQ(g.x, before);
}

TEST(CtcQEval, Errors) {
  Fixes f({});
  EXPECT_THROW(CtcQEval(-1), Error);
  EXPECT_THROW(CtcQEval(0).contract(f.x, f.v, {}), Error);
  std::vector<TubeObservation> bad{{Interval(1.0), IntervalVector(3)}};
  EXPECT_THROW(CtcQEval(0).contract(f.x, f.v, bad), DimensionError);
  const TubeVector v3(f.td, 3);
  EXPECT_THROW(CtcQEval(0).contract(f.x, v3, f.obs), DimensionError);
}

// The network form: CtcQEval(q, obs) and cn.add(ctc, {x, v}). Alone in a
// network its first run is the direct call (the node records only the atoms
// each fix changed, the direct call every atom of its copy).
TEST(CtcQEval, NetworkFormIsTheDirectCall) {
  for (int q = 0; q <= 3; ++q) {
    Fixes f({3, 7});
    TubeVector direct = f.x;
    CtcQEval(q).contract(direct, f.v, f.obs);
    auto x = std::make_shared<TubeVector>(f.x);
    auto v = std::make_shared<TubeVector>(f.v);
    ContractorNetwork cn;
    cn.add(std::make_shared<CtcQEval>(q, f.obs), {x, v});
    const ContractStats s = cn.contract();
    EXPECT_EQ(s.empty, q < 2) << "q " << q;
    if (q < 2) {
      EXPECT_NE(s.emptiness.find("CtcQEval"), std::string::npos) << s.emptiness;
      continue;
    }
    EXPECT_TRUE(x->is_subset(direct)) << "q " << q;
    if (s.contractor_calls == 1) { EXPECT_EQ(*x, direct) << "q " << q; }
    EXPECT_TRUE(test::holds_circle(*x)) << "q " << q;
  }
}

TEST(CtcQEval, RangesWithOutliersInANetwork) {
  // Ranges to two beacons (fixes with a constraint on z), two of them 3 m too long: with q = 2 the truth is kept
  // and the tube is thin; with q = 1 the network is empty.
  for (int q = 1; q <= 2; ++q) {
    test::CircleMission mission;
    std::vector<TubeObservation> obs;
    for (std::size_t i = 0; i < 20; ++i) {
      const double t = 0.25 + 0.5 * static_cast<double>(i);
      const double bx = i % 2 ? 3.0 : -3.0, by = 1.0;
      double r = std::hypot(std::cos(t) - bx, std::sin(t) - by);
      if (i == 4 || i == 13) r += 3.0;
      const Function dist({"a", "b"}, "sqrt((a - " + number_text(bx) + ")^2 + (b - " + number_text(by) + ")^2)");
      obs.push_back({Interval(t).inflate(0.01), IntervalVector(2),
                     std::make_shared<CtcFunction>(dist, Interval(r).inflate(0.05))});
    }
    auto x = std::make_shared<TubeVector>(mission.x);
    auto v = std::make_shared<TubeVector>(mission.v);
    x->set_gate(0, IntervalVector{Interval(0.9, 1.1), Interval(-0.1, 0.1)});
    ContractorNetwork cn;
    cn.add(std::make_shared<CtcQEval>(q, obs), {x, v});
    cn.add(std::make_shared<CtcDeriv>(), {x, v});  // CtcEval carries its fronts only while they shrink gates
    const ContractStats s = cn.contract();
    if (q == 1) {
      EXPECT_TRUE(s.empty);
      continue;
    }
    ASSERT_FALSE(s.empty) << s.emptiness;
    EXPECT_TRUE(test::holds_circle(*x));
    EXPECT_LT(x->max_thickness(), 1.0);
  }
}

TEST(CtcQEval, NetworkFormErrors) {
  Fixes f({});
  EXPECT_THROW(CtcQEval(0, {}), Error);
  ContractorNetwork cn;
  auto x = std::make_shared<TubeVector>(f.x);
  auto v = std::make_shared<TubeVector>(f.v);
  EXPECT_THROW(cn.add(std::make_shared<CtcQEval>(0), {x, v}), Error);  // no observations held
  std::vector<TubeObservation> bad{{Interval(1.0), IntervalVector(3)}};
  EXPECT_THROW(cn.add(std::make_shared<CtcQEval>(0, bad), {x, v}), DimensionError);
  EXPECT_THROW(cn.add(std::make_shared<CtcQEval>(0, f.obs), {x}), DimensionError);
}
