// The generic contractor laws (sillage/testing/contractor_kit.h) on a
// ContractorNetwork of tubes built with ContractorNetwork::add: x' = v
// (CtcDeriv), two uncertain fixes z_i = x(t_i) (CtcEval), and a pointwise
// constraint y = x^2 (CtcFunction applied at every time), and on a network of
// box constraints. Order independence: the same parts added in two orders.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

#include "sillage/testing/contractor_kit.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"

using namespace sillage;
using sillage::kit::SineSum;

namespace {

// Domains: 0 x, 1 v, 2 y, 3 t1, 4 z1, 5 t2, 6 z2.
kit::Case tube_network_case(std::mt19937_64& rng) {
  const SineSum f(rng);
  const auto td = kit::random_tdomain(rng, 25);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const kit::Trajectory1 x = [f](const Interval& t) { return f.x(t); };
  const kit::Trajectory1 v = [f](const Interval& t) { return f.v(t); };
  const kit::Trajectory1 y = [f](const Interval& t) { return sqr(f.x(t)); };
  kit::Case c;
  c.domains = {kit::tube_around(td, x, rng, 0.5, 0.6), kit::tube_around(td, v, rng, 0.3),
               kit::tube_around(td, y, rng, 1.0, 0.6)};
  c.truth = {x, v, y};
  for (int i = 0; i < 2; ++i) {
    const double ts = td->t(0) + u(rng) * (td->t(td->nb_slices()) - td->t(0));
    c.domains.push_back(kit::around(Interval(ts), rng, 0.5) & Interval(td->t(0), td->t(td->nb_slices())));
    c.domains.push_back(kit::around(f.x(Interval(ts)), rng, 0.1));
    c.truth.push_back(Interval(ts));
    c.truth.push_back(f.x(Interval(ts)));
  }
  return c;
}

// The network on shared copies of the domains, parts added in `order`,
// propagated with `ratio`; the results are copied back.
kit::OrderedContract tube_network(double ratio) {
  return [ratio](kit::Domains& d, const std::vector<std::size_t>& order) {
    auto x = std::make_shared<Tube>(std::get<Tube>(d[0]));
    auto v = std::make_shared<Tube>(std::get<Tube>(d[1]));
    auto y = std::make_shared<Tube>(std::get<Tube>(d[2]));
    auto t1 = std::make_shared<Interval>(std::get<Interval>(d[3]));
    auto z1 = std::make_shared<Interval>(std::get<Interval>(d[4]));
    auto t2 = std::make_shared<Interval>(std::get<Interval>(d[5]));
    auto z2 = std::make_shared<Interval>(std::get<Interval>(d[6]));
    ContractorNetwork cn;
    cn.set_ratio(ratio);
    const auto eval = std::make_shared<CtcEval>();
    for (std::size_t part : order) {
      switch (part) {
        case 0:
          cn.add(std::make_shared<CtcDeriv>(), {x, v});
          break;
        case 1:
          cn.add(eval, {t1, z1, x, v});
          break;
        case 2:
          cn.add(eval, {t2, z2, x, v});
          break;
        default:
          cn.add(std::make_shared<CtcFunction>(Function({"x", "y"}, "y - x^2")), {x, y});
          break;
      }
    }
    const ContractStats s = cn.contract();
    d = {*x, *v, *y, *t1, *z1, *t2, *z2};
    const bool some_empty = std::any_of(d.begin(), d.end(), kit::dom_is_empty);
    if (s.empty != some_empty) throw std::logic_error("ContractStats::empty disagrees with the domains");
  };
}

const std::vector<std::size_t> kForward{0, 1, 2, 3}, kBackward{3, 2, 1, 0};

kit::Options network_options() {
  kit::Options o;
  o.cases = 15;
  o.empty_any = true;  // the propagation stops at the first empty domain
  return o;
}

TEST(CnLaws, TubeNetwork) {
  auto o = network_options();
  // A second network refines what the first stopped (ratio 0.01) leaving.
  o.idempotence = kit::Idempotence::ContractionOnly;
  const auto net = tube_network(0.01);
  EXPECT_TRUE(kit::check_laws([&](kit::Domains& d) { net(d, kForward); }, tube_network_case, o));
}

TEST(CnLaws, TubeNetworkOrder) {
  // Two insertion orders, ratio 0.01: both keep the truth; the results differ
  // (the propagation stops at a ratio, and CtcEval is not idempotent).
  EXPECT_TRUE(kit::check_order_independent(tube_network(0.01), tube_network_case, kForward, kBackward, false,
                                           network_options()));
}

// Box constraints on scalar domains a, b, c, d: a + b = c, c * d = 1, b = sin(a).
kit::Case box_network_case(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  const Interval a(u(rng)), b = sin(a), c = a + b, d = Interval(1) / c;
  kit::Case k;
  for (const Interval& t : {a, b, c, d}) {
    k.domains.push_back(kit::around(t, rng, 1.0, 0.2));
    k.truth.emplace_back(std::in_place_type<Interval>, t);
  }
  return k;
}

kit::OrderedContract box_network(double ratio) {
  return [ratio](kit::Domains& dom, const std::vector<std::size_t>& order) {
    std::vector<std::shared_ptr<Interval>> v;
    for (const auto& x : dom) v.push_back(std::make_shared<Interval>(std::get<Interval>(x)));
    ContractorNetwork cn;
    cn.set_ratio(ratio);
    for (std::size_t part : order) {
      switch (part) {
        case 0:
          cn.add(std::make_shared<CtcFunction>(Function({"a", "b", "c"}, "a + b - c")), {v[0], v[1], v[2]});
          break;
        case 1:
          cn.add(std::make_shared<CtcFunction>(Function({"c", "d"}, "c * d - 1")), {v[2], v[3]});
          break;
        default:
          cn.add(std::make_shared<CtcFunction>(Function({"a", "b"}, "b - sin(a)")), {v[0], v[1]});
          break;
      }
    }
    cn.contract();
    for (std::size_t i = 0; i < dom.size(); ++i) dom[i] = *v[i];
  };
}

TEST(CnLaws, BoxNetwork) {
  auto o = network_options();
  o.cases = 40;
  o.idempotence = kit::Idempotence::ContractionOnly;
  const auto net = box_network(0.01);
  EXPECT_TRUE(kit::check_laws([&](kit::Domains& d) { net(d, {0, 1, 2}); }, box_network_case, o));
}

TEST(CnLaws, BoxNetworkOrder) {
  auto o = network_options();
  o.cases = 40;
  EXPECT_TRUE(kit::check_order_independent(box_network(0.01), box_network_case, {0, 1, 2}, {2, 1, 0}, false, o));
}

// With ratio 0 the propagation runs to a common fixed point of the parts; for
// monotone contractors it is the greatest one, whatever the order: the two
// orders agree bit for bit, and a second network changes nothing.
TEST(CnLaws, BoxNetworkRatioZeroSameFixedPoint) {
  auto o = network_options();
  o.cases = 40;
  EXPECT_TRUE(kit::check_order_independent(box_network(0.0), box_network_case, {0, 1, 2}, {2, 1, 0}, true, o));
  o.idempotence = kit::Idempotence::Exact;
  const auto net = box_network(0.0);
  EXPECT_TRUE(kit::check_laws([&](kit::Domains& d) { net(d, {0, 1, 2}); }, box_network_case, o));
}

TEST(CnLaws, TubeNetworkRatioZeroOrder) {
  EXPECT_TRUE(kit::check_order_independent(tube_network(0.0), tube_network_case, kForward, kBackward, false,
                                           network_options()));
}

// With ratio 0 the tube network reaches the same fixed point in both orders,
// bit for bit, and a second network changes nothing: CtcEval is monotone and
// one call is its own fixed point (it iterates over [t], [z] and the slices
// of [t]), so the network's result is the greatest common fixed point.
TEST(CnLaws, TubeNetworkRatioZeroSameFixedPoint) {
  auto o = network_options();
  EXPECT_TRUE(kit::check_order_independent(tube_network(0.0), tube_network_case, kForward, kBackward, true, o));
  o.idempotence = kit::Idempotence::Exact;
  const auto net = tube_network(0.0);
  EXPECT_TRUE(kit::check_laws([&](kit::Domains& d) { net(d, kBackward); }, tube_network_case, o));
}

}  // namespace
