// The generic contractor laws (sillage/testing/contractor_kit.h) on the box
// contractors: CtcFunction (one HC4 pass), CtcFixPoint of it, CtcQInter with
// an outlier. The exact thesis values stay in the contractors' own tests.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "sillage/testing/contractor_kit.h"
#include "sillage/ctc/ctc_algebra.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/ctc_qinter.h"
#include "sillage/interval/elementary.h"

using namespace sillage;

namespace {

// A random point of [-3, 3]^n, and a box around it (sides sometimes unbounded).
kit::Case box_case(std::mt19937_64& rng, std::size_t n, std::vector<double>& p) {
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  p.resize(n);
  IntervalVector box(n), truth(n);
  for (std::size_t i = 0; i < n; ++i) {
    p[i] = u(rng);
    truth[i] = Interval(p[i]);
    box[i] = kit::around(truth[i], rng, 2.0, 0.1);
  }
  return {{box}, {truth}};
}

// f(x, y, z) = x*y + sin(z) - exp(x/4) ∈ [y], [y] around f(p).
const Function& hc4_function() {
  static const Function f({"x", "y", "z"}, "x*y + sin(z) - exp(x/4)");
  return f;
}

Interval f_at(const std::vector<double>& p) {
  const Interval x(p[0]), y(p[1]), z(p[2]);
  return x * y + sin(z) - exp(x / Interval(4));
}

// The kit needs a fixed contractor per call: the image [y] is a domain of the
// case (a second domain, an Interval, never contracted by CtcFunction).
kit::Case function_case(std::mt19937_64& rng) {
  std::vector<double> p;
  kit::Case c = box_case(rng, 3, p);
  const Interval fy = f_at(p);
  c.domains.push_back(kit::around(fy, rng, 0.3));
  c.truth.push_back(fy);
  return c;
}

void function_contract(kit::Domains& d) {
  CtcFunction(hc4_function(), std::get<Interval>(d[1])).contract(std::get<IntervalVector>(d[0]));
}

TEST(CtcLaws, FunctionOnePass) {
  kit::Options o;
  o.idempotence = kit::Idempotence::ContractionOnly;  // one HC4 pass is not idempotent
  o.outputs = {0};
  EXPECT_TRUE(kit::check_laws(function_contract, function_case, o));
}

TEST(CtcLaws, FunctionFixPoint) {
  kit::Options o;
  o.idempotence = kit::Idempotence::ContractionOnly;  // stops at a ratio, not at the exact fixed point
  o.outputs = {0};
  const auto contract = [](kit::Domains& d) {
    auto f = std::make_shared<CtcFunction>(hc4_function(), std::get<Interval>(d[1]));
    CtcFixPoint(f).contract(std::get<IntervalVector>(d[0]));
  };
  EXPECT_TRUE(kit::check_laws(contract, function_case, o));
}

TEST(CtcLaws, FunctionFixPointRatioZeroIsIdempotent) {
  kit::Options o;
  o.outputs = {0};
  const auto contract = [](kit::Domains& d) {
    auto f = std::make_shared<CtcFunction>(hc4_function(), std::get<Interval>(d[1]));
    CtcFixPoint(f, 0.0).contract(std::get<IntervalVector>(d[0]));
  };
  EXPECT_TRUE(kit::check_laws(contract, function_case, o));
}

// Range measurements of a point from 5 beacons, one of them an outlier (its
// range misses the truth by at least 1); q = 1 keeps the truth.
kit::Case ranges_case(std::mt19937_64& rng) {
  std::vector<double> p;
  kit::Case c = box_case(rng, 2, p);
  std::uniform_real_distribution<double> u(-10.0, 10.0), e(0.0, 0.2), off(1.0, 3.0);
  std::uniform_int_distribution<int> pick(0, 4);
  const int outlier = pick(rng);
  for (int i = 0; i < 5; ++i) {
    // Beacons on a 1/8 grid: exact in the decimal text of the function.
    const Interval bx(std::round(u(rng) * 8) / 8), by(std::round(u(rng) * 8) / 8);
    const Interval r = sqrt(sqr(Interval(p[0]) - bx) + sqr(Interval(p[1]) - by));
    Interval meas = kit::around(r, rng, 0.2);
    if (i == outlier) meas = Interval(r.ub() + off(rng), r.ub() + 4.0);
    c.domains.push_back(IntervalVector{bx, by, meas});
    c.truth.emplace_back();  // std::monostate: data, not contracted
  }
  return c;
}

void ranges_contract(kit::Domains& d) {
  std::vector<CtcPtr> list;
  for (std::size_t i = 1; i < d.size(); ++i) {
    const auto& b = std::get<IntervalVector>(d[i]);
    const Function f({"x", "y"},
                     "sqrt((x - " + std::to_string(b[0].lb()) + ")^2 + (y - " + std::to_string(b[1].lb()) + ")^2)");
    list.push_back(std::make_shared<CtcFunction>(f, b[2]));
  }
  CtcQInter(list, 1).contract(std::get<IntervalVector>(d[0]));
}

TEST(CtcLaws, QInterWithOneOutlier) {
  kit::Options o;
  o.cases = 20;
  o.idempotence = kit::Idempotence::ContractionOnly;  // CtcQInter is not idempotent (ctc_qinter.h)
  o.outputs = {0};
  // An empty beacon box (data) is one more violated constraint, not an empty
  // result: with q = 1 the box survives one of them.
  o.skip_empty = {1, 2, 3, 4, 5};
  o.skip_unbounded = {1, 2, 3, 4, 5};
  EXPECT_TRUE(kit::check_laws(ranges_contract, ranges_case, o));
}

// (g) One HC4 pass and the q-relaxed intersection of monotone contractors are
// monotone: X ⊆ Y ⇒ C(X) ⊆ C(Y).
TEST(CtcLaws, FunctionAndQInterAreMonotone) {
  kit::Options o;
  o.cases = 100;
  EXPECT_TRUE(kit::check_monotone(function_contract, function_case, o));
  EXPECT_TRUE(kit::check_monotone(ranges_contract, ranges_case, o));
}

}  // namespace

// The kit itself catches a broken contractor, and says which law and where.
TEST(CtcLaws, KitCatchesViolations) {
  kit::Options o;
  o.cases = 3;
  o.outputs = {0};
  const auto grows = [](kit::Domains& d) {
    auto& b = std::get<IntervalVector>(d[0]);
    if (!b.is_empty()) b[1] = Interval(b[1].lb() - 1, b[1].ub());
  };
  auto r = kit::check_laws(grows, function_case, o);
  EXPECT_FALSE(r);
  EXPECT_NE(std::string(r.message()).find("contraction: domain 0 component 1 grew"), std::string::npos) << r.message();
  const auto loses = [](kit::Domains& d) {
    auto& b = std::get<IntervalVector>(d[0]);
    if (!b.is_empty() && b[0].is_bounded()) b[0] = Interval(b[0].ub());
  };
  r = kit::check_laws(loses, function_case, o);
  EXPECT_FALSE(r);
  EXPECT_NE(std::string(r.message()).find("truth kept: domain 0 component 0"), std::string::npos) << r.message();
  const auto nibbles = [](kit::Domains& d) {  // one ulp more at each call
    auto& b = std::get<IntervalVector>(d[0]);
    if (!b.is_empty() && b[2].is_bounded() && b[2].diam() > 0) {
      b[2] = Interval(b[2].lb(), rounding::next_down(b[2].ub()));
    }
  };
  o.idempotence = kit::Idempotence::Exact;
  o.unbounded_inputs = o.empty_inputs = false;
  r = kit::check_laws(nibbles, function_case, o);
  EXPECT_FALSE(r);
  EXPECT_NE(std::string(r.message()).find("idempotence"), std::string::npos) << r.message();
  const auto ignores_empty = [](kit::Domains&) {};
  o.idempotence = kit::Idempotence::Exact;
  o.empty_inputs = true;
  r = kit::check_laws(ignores_empty, function_case, o);
  EXPECT_FALSE(r);
  EXPECT_NE(std::string(r.message()).find("empty input (domain 1 empty): domain 0 is not empty"), std::string::npos)
      << r.message();
}
