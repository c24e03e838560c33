// The pointwise contractor by batches of slices gives the box-by-box results
// bit for bit: on random tubes, CtcFunction (batch HC4) against the same
// contractor seen through a plain Ctc (one virtual call per slice and gate),
// directly and as a network node.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/tube/tube_ctc.h"

#include "kit/same_bits.h"

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

using test::same_bits;

void expect_same(const Tube& a, const Tube& b) {
  for (std::size_t k = 0; k < a.nb_slices(); ++k) ASSERT_TRUE(same_bits(a.slice(k), b.slice(k))) << "slice " << k;
  for (std::size_t k = 0; k <= a.nb_slices(); ++k) ASSERT_TRUE(same_bits(a.gate(k), b.gate(k))) << "gate " << k;
}

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
  for (std::size_t i = 0; i < a.size(); ++i) expect_same(a[i], b[i]);

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
  for (std::size_t i = 0; i < na.size(); ++i) expect_same(*na[i], *nb[i]);
}

}  // namespace

TEST(TubeCtcBatch, SpeedTimesCosHeadingBitForBit) {
  check(CtcFunction(Function({"v", "a", "b"}, "v - b*cos(a)")), {{0, 40}, {1, 0.3}, {10, 0.2}}, 1);
}

TEST(TubeCtcBatch, BeaconDistanceBitForBit) {
  const Function g({"y", "x1", "x2"}, "y - sqrt((x1 - 2)^2 + (x2 + 1)^2)");
  check(CtcFunction(g, Interval(-0.1, 0.1)), {{5, 0.5}, {3, 0.4}, {-2, 0.4}}, 2);
}

TEST(TubeCtcBatch, InconsistentBitForBit) {
  // x / y = 1 with y straddling zero and x drifting through it: some boxes empty.
  check(CtcFunction(Function({"x", "y"}, "x / y"), Interval(1.0)), {{0, 0.5}, {0, 0.5}}, 3);
}
