// The study of the unproven crossings (examples/cpp/loops_study.h) on the
// 1 h Lissajous mission of bench_tplane, and the degrees of its detections and
// pieces against the indices of the true crossings they hold.
#include <gtest/gtest.h>

#include <optional>
#include <vector>

#include "../../../examples/cpp/looping_mission.h"
#include "../../../examples/cpp/loops_study.h"
#include "sillage/loops/tplane.h"

using namespace sillage;

namespace {

struct Lissajous1h {
  looping_mission::Lissajous mission{3600.0};
  std::vector<PathCrossing> truth = mission.true_crossings(0.05);
  loops_study::Velocity velocity = [this](double t) { return mission.velocity(t); };

  TPlane prove(double eps) const {
    TPlane tp(mission.tdomain());
    tp.compute_detections(eps, mission.velocity_tube());
    tp.compute_proofs(mission.velocity_tube());
    return tp;
  }

  int net_index(const std::vector<IntervalVector>& boxes) const {
    int net = 0;
    for (const PathCrossing& c : truth) net += loops_study::holds(boxes, c) ? loops_study::orientation(c, velocity) : 0;
    return net;
  }
};

const Lissajous1h& lissajous() {
  static const Lissajous1h m;
  return m;
}

}  // namespace

// The degree of a region is the sum of the indices of the zeros inside it:
// every known degree, of a detection or of a piece of a split, equals the sum
// of the indices of the true crossings it holds, and a split keeps the degree.
TEST(LoopsStudy, DegreesAreTheIndicesOfTheTrueCrossings) {
  const Lissajous1h& m = lissajous();
  for (double eps : {10.0, 3600.0 / 2000}) {
    const TPlane tp = m.prove(eps);
    std::size_t known = 0, pieces = 0;
    for (const Loop& l : tp.detections()) {
      if (!l.complete()) continue;
      if (l.degree()) {
        ++known;
        EXPECT_EQ(*l.degree(), m.net_index(l.boxes())) << l.t_box();
      }
      std::optional<int> sum = 0;
      for (const Loop& p : l.pieces()) {
        ++pieces;
        if (p.degree()) {
          EXPECT_EQ(*p.degree(), m.net_index(p.boxes())) << p.t_box();
        }
        if (p.proven()) {
          EXPECT_GT(p.count().value_or(1), 0u);
        }
        sum = sum && p.degree() ? std::optional<int>(*sum + *p.degree()) : std::nullopt;
      }
      if (!l.pieces().empty() && sum && l.degree()) {
        EXPECT_EQ(*sum, *l.degree()) << l.t_box();
      }
    }
    EXPECT_GT(known, 60u);
    EXPECT_GT(pieces, 0u);
  }
}

// Every crossing left unproven there is a twin: connected through feasible
// (Inner) t-boxes to a crossing of opposite index, so that no boundary free
// of feasible loops separates them (docs/loops.md, "What is left").
TEST(LoopsStudy, EveryUnprovenCrossingOfTheLissajousMissionIsATwin) {
  const Lissajous1h& m = lissajous();
  for (double eps : {10.0, 3600.0 / 2000}) {
    const TPlane tp = m.prove(eps);
    const loops_study::Totals t = loops_study::Study(tp, m.mission.velocity_tube(), m.truth, m.velocity, false).run();
    const std::size_t left = t.in_complete - t.proven;
    EXPECT_GT(t.in_complete, 70u);
    EXPECT_GT(left, 0u);
    using R = loops_study::Reason;
    EXPECT_EQ(t.by_reason[std::size_t(R::InnerTwin)] + t.by_reason[std::size_t(R::FineTwin)], left) << "eps " << eps;
  }
}

// The index is that of the zero of f(t1, t2) = p(t2) - p(t1): the sign of
// det(-v(t1) | v(t2)).
TEST(LoopsStudy, OrientationIsTheSignOfTheJacobian) {
  const loops_study::Velocity v = [](double t) { return t < 1 ? std::array<double, 2>{1, 0} : std::array<double, 2>{0, 1}; };
  PathCrossing c;
  c.t1 = 0.5, c.t2 = 1.5;
  // J = (-v1 | v2) = [[-1, 0], [0, 1]]: det -1.
  EXPECT_EQ(loops_study::orientation(c, v), -1);
  const loops_study::Velocity w = [](double t) { return t < 1 ? std::array<double, 2>{0, 1} : std::array<double, 2>{1, 0}; };
  EXPECT_EQ(loops_study::orientation(c, w), 1);
  const loops_study::Velocity parallel = [](double) { return std::array<double, 2>{1, 1}; };
  EXPECT_EQ(loops_study::orientation(c, parallel), 0);
}
