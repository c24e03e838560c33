// The pointwise contractor by batches of slices gives the box-by-box results
// bit for bit: on random tubes, CtcFunction (batch HC4) against the same
// contractor seen through a plain Ctc (one virtual call per slice and gate),
// directly and as a network node. With sin or cos the batch has bounds of
// its own (trig_batch.h): there it keeps every true point instead.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/tube/tube_ctc.h"

#include "kit/same_tube.h"

using namespace sillage;

namespace {

// The contractor of f, box by box (not a CtcFunction: contract() takes the per-box path).
class PerBox : public Ctc {
 public:
  explicit PerBox(const CtcFunction& f) : Ctc(f.nb_vars()), f_(f) {}
  void contract(IntervalVector& x) const override { f_.contract(x); }

 private:
  CtcFunction f_;
};

using test::expect_same_bits;

// A tube around a random walk from c, with random thickness, its gates narrowed at random.
Tube random_tube(const std::shared_ptr<TDomain>& td, std::mt19937_64& rng, double c, double spread) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Interval> s(td->nb_slices());
  double m = c;
  for (Interval& x : s) {
    m += 0.5 * spread * (u(rng) - 0.5);  // neighbours overlap: no gate is empty
    const double r = spread * (0.5 + u(rng));
    x = Interval(m - r, m + r);
  }
  Tube x(td, s);
  for (std::size_t k = 1; k < td->nb_slices(); k += 3) {
    const Interval g = x.gate(k);
    x.set_gate(k, Interval(g.lb(), g.mid()));
  }
  return x;
}

// Batch and per-box contraction of the same random tubes, directly and in a network.
void check(const CtcFunction& f, const std::vector<std::pair<double, double>>& around, std::uint64_t seed) {
  const auto td = TDomain::create(0.0, 7.0, 0.01);  // 700 slices: several chunks
  std::mt19937_64 rng(seed);
  std::vector<Tube> a, b, c, d;
  for (const auto& [m, s] : around) a.push_back(random_tube(td, rng, m, s));
  b = a;
  std::vector<Tube*> pa, pb;
  for (std::size_t i = 0; i < a.size(); ++i) {
    pa.push_back(&a[i]);
    pb.push_back(&b[i]);
  }
  const bool ok_batch = contract(f, pa);
  const bool ok_box = contract(PerBox(f), pb);
  EXPECT_EQ(ok_batch, ok_box);
  for (std::size_t i = 0; i < a.size(); ++i) expect_same_bits(a[i], b[i]);

  std::vector<std::shared_ptr<Tube>> na, nb;
  ContractorNetwork cna, cnb;
  std::vector<DomainRef> da, db;
  for (const auto& [m, s] : around) {
    na.push_back(std::make_shared<Tube>(random_tube(td, rng, m, s)));
    nb.push_back(std::make_shared<Tube>(*na.back()));
    da.emplace_back(na.back());
    db.emplace_back(nb.back());
  }
  cna.add(std::make_shared<CtcFunction>(f), da);
  cnb.add(std::make_shared<PerBox>(f), db);
  EXPECT_EQ(cna.contract().empty, cnb.contract().empty);
  for (std::size_t i = 0; i < na.size(); ++i) expect_same_bits(*na[i], *nb[i]);
}

// Tubes v, a, b contracted by v - b cos a in `band`, directly or in a network.
void contract_heading(const CtcFunction& f, std::vector<Tube>& x, bool network) {
  if (!network) {
    ASSERT_TRUE(contract(f, {&x[0], &x[1], &x[2]}));
    return;
  }
  std::vector<std::shared_ptr<Tube>> p;
  std::vector<DomainRef> d;
  for (const Tube& t : x) {
    p.push_back(std::make_shared<Tube>(t));
    d.emplace_back(p.back());
  }
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcFunction>(f), d);
  ASSERT_FALSE(cn.contract().empty);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = *p[i];
}

// Points (v, a, b) sampled in the slices and gates before contraction, with v
// - b cos a provably in the band, are still inside after.
void check_heading_solutions(bool network) {
  const auto td = TDomain::create(0.0, 7.0, 0.01);  // 700 slices: several chunks
  std::mt19937_64 rng(4);
  const Interval band(-1e-6, 1e-6);
  const CtcFunction f(Function({"v", "a", "b"}, "v - b*cos(a)"), band);
  // Around the trajectory a = 1 + sin t / 5, b = 10 + cos t / 10, v = b cos a: consistent everywhere.
  std::vector<Tube> before{Tube(td, Interval(-20, 20)), Tube(td, "1 + sin(t)/5 + [-0.3, 0.3]"),
                           Tube(td, "10 + cos(t)/10 + [-0.2, 0.2]")};
  std::vector<Tube> after = before;
  contract_heading(f, after, network);
  std::uniform_real_distribution<double> u(0, 1);
  const auto pick = [&](const Interval& x) { return std::clamp(x.lb() + u(rng) * x.diam(), x.lb(), x.ub()); };
  int solutions = 0, narrowed = 0;
  for (std::size_t e = 0; e < 2 * td->nb_slices() + 1; ++e) {
    const bool gate = e % 2 == 0;
    const std::size_t k = e / 2;
    const auto elem = [&](const Tube& t) { return gate ? t.gate(k) : t.slice(k); };
    for (std::size_t i = 0; i < 3; ++i) {
      ASSERT_TRUE(elem(after[i]).is_subset(elem(before[i]))) << "variable " << i << ", element " << e;
      narrowed += elem(after[i]) != elem(before[i]) ? 1 : 0;
    }
    for (int s = 0; s < 10; ++s) {
      const double a = pick(elem(before[1])), b = pick(elem(before[2])), v = b * std::cos(a);
      if (!elem(before[0]).contains(v)) continue;
      const IntervalVector p{Interval(v), Interval(a), Interval(b)};
      if (!f.function().eval_vector(p).is_interior_subset(IntervalVector{band})) continue;
      ++solutions;
      ASSERT_TRUE(elem(after[0]).contains(v) && elem(after[1]).contains(a) && elem(after[2]).contains(b))
          << "element " << e << ": the solution " << p << " lost";
    }
  }
  EXPECT_GT(solutions, 1000);
  EXPECT_GT(narrowed, 500);
}

}  // namespace

TEST(TubeCtcBatch, SpeedTimesCosHeadingKeepsSolutions) {
  check_heading_solutions(false);
  check_heading_solutions(true);
}

TEST(TubeCtcBatch, BeaconDistanceBitForBit) {
  const Function g({"y", "x1", "x2"}, "y - sqrt((x1 - 2)^2 + (x2 + 1)^2)");
  check(CtcFunction(g, Interval(-0.1, 0.1)), {{5, 0.5}, {3, 0.4}, {-2, 0.4}}, 2);
}

TEST(TubeCtcBatch, InconsistentBitForBit) {
  // x / y = 1 with y straddling zero and x drifting through it: some boxes empty.
  check(CtcFunction(Function({"x", "y"}, "x / y"), Interval(1.0)), {{0, 0.5}, {0, 0.5}}, 3);
}
