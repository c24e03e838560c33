// ContractorNetwork: the thesis' range-only localization (Table 2.1), waking
// only the affected contractors, empty short-circuit, stable identity of the
// shared domains, parts of boxes, errors, and the consistency law on random
// networks built around a known solution.
#include <gtest/gtest.h>

#include <atomic>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "cn/counting_ctc.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_binary.h"
#include "sillage/ctc/ctc_box.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/ctc_unary.h"
#include "sillage/ctc/shrink.h"

using namespace sillage;
using sillage::test::Counting;

namespace {

struct Beacon {
  double x, y;
  Interval rho;
};

// Table 2.1.
const Beacon kBeacons[] = {{-0.5, 4.0, {3.63, 4.43}}, {-2.5, -2.5, {3.13, 3.93}}, {2.5, -0.5, {2.15, 2.95}}};

std::shared_ptr<CtcFunction> range_ctc(const Beacon& b) {
  // f(x1, x2, rho) = sqrt((x1 - bx)^2 + (x2 - by)^2) - rho = 0 (2.35)
  const Function f({"x1", "x2", "rho"},
                   "sqrt((x1 - " + std::to_string(b.x) + ")^2 + (x2 - " + std::to_string(b.y) + ")^2) - rho");
  return std::make_shared<CtcFunction>(f);
}

std::shared_ptr<CtcFunction> ctc(const std::vector<std::string>& vars, const std::string& text,
                                 const Interval& y = Interval(0.0)) {
  return std::make_shared<CtcFunction>(Function(vars, text), y);
}

}  // namespace

TEST(ContractorNetwork, RangeOnlyLocalizationOfTable21) {
  ContractorNetwork cn;
  auto x = cn.create_dom(IntervalVector(2));  // [-inf, inf]^2
  std::vector<std::shared_ptr<Interval>> rho;
  for (const auto& b : kBeacons) {
    rho.push_back(cn.create_dom(b.rho));
    cn.add(range_ctc(b), {x, rho.back()});
  }
  EXPECT_EQ(cn.nb_ctc(), 3u);
  EXPECT_EQ(cn.nb_dom(), 4u);
  const ContractStats s = cn.contract();
  std::cout << "Table 2.1: " << s.iterations << " iterations, " << s.contractor_calls << " contractor calls, x = "
            << *x << ", rho = " << *rho[0] << " " << *rho[1] << " " << *rho[2] << "\n";
  EXPECT_FALSE(s.empty);
  EXPECT_TRUE(x->contains({0, 0}));
  EXPECT_TRUE(x->is_subset(IntervalVector{{-1, 1}, {-1, 1}}));  // bounded and tight
  EXPECT_GE(s.iterations, 2u);
  EXPECT_LE(s.iterations, 30u);
  EXPECT_GE(s.contractor_calls, 3u);
  // Each rho still contains the true range from (0, 0).
  for (std::size_t k = 0; k < 3; ++k) {
    const Interval d = sqrt(sqr(Interval(kBeacons[k].x)) + sqr(Interval(kBeacons[k].y)));
    EXPECT_TRUE(rho[k]->intersects(d) && d.is_subset(kBeacons[k].rho));
    EXPECT_TRUE(rho[k]->contains(d.mid())) << *rho[k] << " vs " << d;
  }
  // A second call finds the fixed point at once: one round, one call each.
  const ContractStats again = cn.contract();
  EXPECT_EQ(again.iterations, 1u);
  EXPECT_EQ(again.contractor_calls, 3u);
}

TEST(ContractorNetwork, RangeOnlyDecomposedIntoPrimitives) {
  // The decomposition (2.30): a = x1 - bx, b = x2 - by, c = a^2, d = b^2,
  // e = c + d, rho = sqrt(e), with intermediate variables as domains.
  ContractorNetwork cn;
  auto x = cn.create_dom(IntervalVector(2));
  const auto sub = std::make_shared<CtcSub>();
  const auto add = std::make_shared<CtcAdd>();
  const auto sqr_c = std::make_shared<CtcUnary>("sqr"), sqrt_c = std::make_shared<CtcUnary>("sqrt");
  for (const auto& bc : kBeacons) {
    auto a = cn.create_dom(Interval()), b = cn.create_dom(Interval()), c = cn.create_dom(Interval()),
         d = cn.create_dom(Interval()), e = cn.create_dom(Interval()), rho = cn.create_dom(bc.rho);
    auto bx = cn.create_dom(Interval(bc.x)), by = cn.create_dom(Interval(bc.y));
    cn.add(sub, {a, DomainRef::component(x, 0), bx});
    cn.add(sub, {b, DomainRef::component(x, 1), by});
    cn.add(sqr_c, {c, a});
    cn.add(sqr_c, {d, b});
    cn.add(add, {e, c, d});
    cn.add(sqrt_c, {rho, e});
  }
  EXPECT_EQ(cn.nb_ctc(), 18u);
  EXPECT_EQ(cn.nb_dom(), 1u + 3 * 8);
  const ContractStats s = cn.contract();
  std::cout << "Table 2.1 decomposed (2.30): " << s.iterations << " iterations, " << s.contractor_calls
            << " contractor calls, x = " << *x << "\n";
  EXPECT_FALSE(s.empty);
  EXPECT_TRUE(x->contains({0, 0}));
  EXPECT_TRUE(x->is_subset(IntervalVector{{-1, 1}, {-1, 1}}));
}

TEST(ContractorNetwork, WakesOnlyTheAffectedContractors) {
  // Chain x_{i+1} = x_i + 1, i = 0..4, plus an unrelated constraint on (y, z).
  ContractorNetwork cn;
  std::vector<std::shared_ptr<Interval>> xs;
  for (int i = 0; i < 6; ++i) xs.push_back(cn.create_dom(i == 0 ? Interval(0, 0) : Interval()));
  std::vector<std::shared_ptr<Counting>> links;
  for (int i = 4; i >= 0; --i) {  // added backwards: each contraction is found one round later
    links.push_back(std::make_shared<Counting>(ctc({"a", "b"}, "b - a - 1")));
    cn.add(links.back(), {xs[i], xs[i + 1]});
  }
  auto y = cn.create_dom(Interval(0, 1)), z = cn.create_dom(Interval());
  const auto other = std::make_shared<Counting>(ctc({"y", "z"}, "z - y"));
  cn.add(other, {y, z});
  const ContractStats s = cn.contract();
  for (int i = 0; i < 6; ++i) EXPECT_EQ(*xs[i], Interval(i, i));
  EXPECT_EQ(*z, Interval(0, 1));
  // Round 1 runs all 6; then x_{i+1} wakes link i+1 alone, one per round.
  EXPECT_EQ(s.iterations, 5u);
  EXPECT_EQ(s.contractor_calls, 6u + 4u);
  EXPECT_EQ(other->calls, 1);
  for (std::size_t k = 0; k < links.size(); ++k) EXPECT_EQ(links[k]->calls, k == 4 ? 1 : 2) << k;

  // Added in the chain's order, one round does it all.
  ContractorNetwork fwd;
  std::vector<std::shared_ptr<Interval>> ws;
  for (int i = 0; i < 6; ++i) ws.push_back(fwd.create_dom(i == 0 ? Interval(0, 0) : Interval()));
  for (int i = 0; i < 5; ++i) fwd.add(ctc({"a", "b"}, "b - a - 1"), {ws[i], ws[i + 1]});
  const ContractStats t = fwd.contract();
  EXPECT_EQ(t.iterations, 1u);
  EXPECT_EQ(t.contractor_calls, 5u);
  EXPECT_EQ(*ws[5], Interval(5, 5));
}

TEST(ContractorNetwork, EmptyDomainStopsAtOnce) {
  ContractorNetwork cn;
  auto x = cn.create_dom(Interval(0, 1)), y = cn.create_dom(Interval(2, 3));
  auto a = cn.create_dom(Interval()), b = cn.create_dom(Interval());
  const auto eq = std::make_shared<Counting>(ctc({"x", "y"}, "x - y"));
  const auto later = std::make_shared<Counting>(ctc({"a", "b"}, "a - b"));
  cn.add(eq, {x, y});
  cn.add(later, {a, b});
  const ContractStats s = cn.contract();
  EXPECT_TRUE(s.empty);
  EXPECT_EQ(s.contractor_calls, 1u);
  EXPECT_EQ(later->calls, 0);
  EXPECT_TRUE(x->is_empty());
  EXPECT_NE(s.empty_domain.find("domain 0"), std::string::npos) << s.empty_domain;
  // Already empty: reported without any call.
  const ContractStats again = cn.contract();
  EXPECT_TRUE(again.empty);
  EXPECT_EQ(again.contractor_calls, 0u);
  // An empty component empties the whole box domain.
  ContractorNetwork cb;
  auto v = cb.create_dom(IntervalVector{{0, 1}, {5, 6}});
  cb.add(std::make_shared<CtcBox>(IntervalVector{{2, 3}}), {DomainRef::component(v, 0)});
  EXPECT_TRUE(cb.contract().empty);
  EXPECT_TRUE((*v)[1].is_empty());
}

TEST(ContractorNetwork, IdentitySurvivesMovingTheContainers) {
  ContractorNetwork cn;
  std::vector<std::shared_ptr<Interval>> doms;
  for (int i = 0; i < 4; ++i) doms.push_back(std::make_shared<Interval>());
  *doms[0] = Interval(1, 2);
  for (int i = 0; i < 3; ++i) cn.add(ctc({"a", "b"}, "b - 2 * a"), {doms[i], doms[i + 1]});
  // Move the vector away and make it reallocate: the shared objects stay put.
  std::vector<std::shared_ptr<Interval>> moved = std::move(doms);
  for (int i = 0; i < 1000; ++i) moved.push_back(std::make_shared<Interval>());
  std::vector<std::shared_ptr<Interval>> copy(moved.begin(), moved.begin() + 4);
  moved.clear();
  moved.shrink_to_fit();
  cn.contract();
  EXPECT_EQ(*copy[3], Interval(8, 16));
  // Registering the same object again (through a copy of the pointer) is the same domain.
  cn.add(ctc({"a"}, "a - 12"), {copy[3]});
  EXPECT_EQ(cn.nb_dom(), 4u);
  cn.contract();
  EXPECT_EQ(*copy[0], Interval(1.5, 1.5));
}

TEST(ContractorNetwork, PartsOfBoxesWakeTheWholeBox) {
  ContractorNetwork cn;
  auto x = std::make_shared<IntervalVector>(IntervalVector{{0, 10}, {-5, 5}, {0, 10}});
  const auto whole = std::make_shared<Counting>(ctc({"x0", "x1", "x2"}, "x0 - x2"));
  const auto part = std::make_shared<Counting>(std::make_shared<CtcBox>(IntervalVector{{2, 3}}));
  cn.add(whole, {x});
  cn.add(part, {DomainRef::component(x, 2)});
  const auto pair = std::make_shared<Counting>(ctc({"a", "b"}, "a + b", Interval(0, 1)));
  cn.add(pair, {DomainRef::subvector(x, 0, 1)});
  EXPECT_EQ(cn.nb_dom(), 1u);
  const ContractStats s = cn.contract();
  EXPECT_EQ((*x)[0], Interval(2, 3));
  EXPECT_EQ((*x)[2], Interval(2, 3));
  EXPECT_EQ((*x)[1], Interval(-3, -1));
  EXPECT_FALSE(s.empty);
  // Round 1: all three; the part (component 2) and the pair (components 0, 1)
  // wake the whole-box one. Round 2: it narrows component 0, waking the pair.
  // Round 3: the pair narrows component 1, waking the whole-box one (round 4).
  EXPECT_EQ(s.iterations, 4u);
  EXPECT_EQ(whole->calls, 3);
  EXPECT_EQ(pair->calls, 2);
  EXPECT_EQ(part->calls, 1);  // nobody else changed component 2
}

TEST(ContractorNetwork, Errors) {
  ContractorNetwork cn;
  auto x = cn.create_dom(IntervalVector(2));
  auto r = cn.create_dom(Interval(1, 2));
  try {
    cn.add(ctc({"a", "b", "c"}, "a + b + c"), {x});
    FAIL() << "no DimensionError";
  } catch (const DimensionError& e) {
    EXPECT_NE(std::string(e.what()).find("CtcFunction"), std::string::npos) << e.what();
  }
  EXPECT_THROW(cn.add(ctc({"a"}, "a"), {x, r}), DimensionError);
  EXPECT_THROW(DomainRef::component(x, 2), DimensionError);
  EXPECT_THROW(DomainRef::subvector(x, 1, 0), DimensionError);
  EXPECT_THROW(cn.add(std::shared_ptr<const Ctc>(), {r}), Error);
  EXPECT_THROW(DomainRef(std::shared_ptr<Interval>()), Error);
  EXPECT_THROW(cn.set_ratio(1.0), Error);
  EXPECT_THROW(cn.set_ratio(-1e-3), Error);
  EXPECT_EQ(cn.nb_ctc(), 0u);  // failed adds leave the network unchanged
  cn.add(ctc({"a", "b", "c"}, "a + b + c"), {x, r});
  *x = IntervalVector(3);  // resized behind the network's back
  EXPECT_THROW(cn.contract(), DimensionError);
  EXPECT_THROW(cn.add(ctc({"a"}, "a"), {DomainRef::component(x, 2)}), DimensionError);
  EXPECT_EQ(cn.nb_ctc(), 1u);
}

TEST(ContractorNetwork, RandomNetworksKeepTheirSolution) {
  // Random constraints f_k(vars) ∈ [f_k](p) around a random point p: p is a
  // solution of all of them, so every domain must still contain it.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-4, 4);
  std::uniform_int_distribution<int> pick_var(0, 4), pick_f(0, 3);
  const char* forms[] = {"a + 2 * b", "a * b", "sin(a) + b^2", "exp(a / 4) - b"};
  for (int trial = 0; trial < 60; ++trial) {
    ContractorNetwork cn;
    cn.set_ratio(trial % 3 == 0 ? 0.0 : 0.05);
    Vector p(5);
    for (auto& v : p) v = u(rng);
    auto box = cn.create_dom(IntervalVector(3, Interval(-10, 10)));  // variables 0..2
    auto s3 = cn.create_dom(Interval(-10, 10)), s4 = cn.create_dom(Interval(-10, 10));
    const auto ref = [&](int i) -> DomainRef {
      if (i < 3) return DomainRef::component(box, static_cast<std::size_t>(i));
      return i == 3 ? DomainRef(s3) : DomainRef(s4);
    };
    for (int k = 0; k < 8; ++k) {
      const int i = pick_var(rng), j = pick_var(rng);
      const Function f({"a", "b"}, forms[pick_f(rng)]);
      const Interval y = f.eval(IntervalVector::from_point({p[i], p[j]}));
      cn.add(std::make_shared<CtcFunction>(f, y), {ref(i), ref(j)});
    }
    const ContractStats s = cn.contract();
    ASSERT_FALSE(s.empty);
    for (int i = 0; i < 3; ++i) ASSERT_TRUE((*box)[i].contains(p[i]));
    ASSERT_TRUE(s3->contains(p[3]) && s4->contains(p[4]));
  }
}
