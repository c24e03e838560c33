#pragma once
// The network of the low-cost beacons example (thesis 5.3.1, CN (5.18)),
// shared by examples/cpp/lowcost_beacons.cpp and bench/bench_examples_ch5.cpp.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "table_values.h"

namespace lowcost_beacons {

using namespace sillage;
using example::cents;
using example::num;

inline constexpr double kTf = 64.0;

struct Beacon {
  const char* name;
  double b1, b2;
};
inline const std::array<Beacon, 3> kBeacons{{{"alpha", 30, 20}, {"beta", 80, -5}, {"gamma", 125, 20}}};  // Table 5.1

struct Measurement {
  std::size_t k;  // beacon
  Interval t, z;
};
inline const std::array<Measurement, 11> kMeasurements{{{1, {14.75, 15.55}, {11.69, 12.69}},  // Table 5.2
                                                 {0, {20.80, 21.60}, {15.40, 16.40}},
                                                 {0, {23.80, 24.60}, {10.62, 11.62}},
                                                 {0, {26.80, 27.60}, {11.05, 12.05}},
                                                 {0, {29.80, 30.60}, {11.87, 12.87}},
                                                 {0, {32.80, 33.60}, {15.31, 16.31}},
                                                 {2, {44.35, 45.15}, {13.65, 14.65}},
                                                 {2, {47.35, 48.15}, {13.32, 14.32}},
                                                 {2, {50.35, 51.15}, {12.03, 13.03}},
                                                 {2, {53.35, 54.15}, {15.98, 16.98}},
                                                 {1, {56.75, 57.55}, {17.45, 18.45}}}};

// The network and its domains (read back after contract()).
struct Problem {
  std::shared_ptr<TubeVector> x, v;
  std::vector<std::shared_ptr<Tube>> y, w;      // per beacon
  std::vector<std::shared_ptr<Interval>> t, z;  // per measurement
  std::unique_ptr<ContractorNetwork> cn = std::make_unique<ContractorNetwork>();
};

// The three equations of beacon (b1, b2) on (y, w, x1, x2, v1, v2) = 0:
// y = g(x), w = ġ(x, v) as (5.19), and w = ġ(x, v) reformulated as (5.21).
inline Function beacon_function(double b1, double b2) {
  const std::string d1 = "(x1 - " + num(b1) + ")", d2 = "(x2 - " + num(b2) + ")";
  const std::string g = "sqrt(" + d1 + "^2 + " + d2 + "^2)";
  return Function({"y", "w", "x1", "x2", "v1", "v2"},
                  "(y - " + g + ", w - (" + d1 + "*v1 + " + d2 + "*v2)/" + g + ", w - (sign(" + d1 + ")/sqrt(1 + (" +
                      d2 + "/" + d1 + ")^2)*v1 + sign(" + d2 + ")/sqrt(1 + (" + d1 + "/" + d2 + ")^2)*v2))");
}

// The time domain: slices of dt, plus gates at the bounds of the [t_i]: they
// are exact, and a [t_i] that pokes an ulp into a slice would take in the
// whole slice (mean thickness 20.3 instead of 19.9).
inline std::shared_ptr<TDomain> make_tdomain(double dt) {
  const auto td = TDomain::create(0.0, kTf, dt);
  for (const Measurement& m : kMeasurements) {
    td->sample(cents(m.t).lb());
    td->sample(cents(m.t).ub());
  }
  return td;
}

// `observer` (optional) is added last, on (x1, x2).
inline Problem build(const std::shared_ptr<TDomain>& td, double ratio,
                     const std::shared_ptr<const NetworkCtc>& observer = nullptr) {
  Problem p;
  p.x = std::make_shared<TubeVector>(td, 4);
  p.v = std::make_shared<TubeVector>(td, 4);
  (*p.v)[2] = Tube(td, "-9/20*cos(t/5) + [-0.001, 0.001]");                     // v3 = u1 (5.16)
  (*p.v)[3] = Tube(td, "1/10 + sin(t/4) + [-0.001, 0.001]");                    // v4 = u2
  (*p.x)[2].set_gate(0, Interval::pi() / Interval(2) + Interval(-0.01, 0.01));  // (5.17)
  (*p.x)[3].set_gate(0, Interval(-0.01, 0.01));
  ContractorNetwork& cn = *p.cn;
  cn.set_ratio(ratio);
  const auto x = [&](std::size_t i) { return DomainRef::component(p.x, i); };
  const auto v = [&](std::size_t i) { return DomainRef::component(p.v, i); };
  cn.add(std::make_shared<CtcFunction>(Function({"v1", "x4", "x3"}, "v1 - x4*cos(x3)")), {v(0), x(3), x(2)});
  cn.add(std::make_shared<CtcFunction>(Function({"v2", "x4", "x3"}, "v2 - x4*sin(x3)")), {v(1), x(3), x(2)});
  cn.add(std::make_shared<CtcDeriv>(), {p.x, p.v});
  for (const Beacon& b : kBeacons) {
    auto y = std::make_shared<Tube>(td), w = std::make_shared<Tube>(td);
    // One contractor for the three equations of the beacon: one HC4 pass over
    // their shared DAG; same fixed point as three contractors, 1.7x faster.
    cn.add(std::make_shared<CtcFunction>(beacon_function(b.b1, b.b2)), {y, w, x(0), x(1), v(0), v(1)});
    cn.add(std::make_shared<CtcDeriv>(), {y, w});
    p.y.push_back(y);
    p.w.push_back(w);
  }
  for (const Measurement& m : kMeasurements) {
    p.t.push_back(std::make_shared<Interval>(cents(m.t)));
    p.z.push_back(std::make_shared<Interval>(cents(m.z)));
    cn.add(std::make_shared<CtcEval>(), {p.t.back(), p.z.back(), p.y[m.k], p.w[m.k]});
    const std::string i = std::to_string(p.t.size());  // "t" + a temporary: a false -Wrestrict of GCC 12
    cn.set_name(p.t.back(), std::string("t").append(i));
    cn.set_name(p.z.back(), std::string("z").append(i));
  }
  // Named as in lowcost_beacons.py, so that an empty network says which domain emptied.
  cn.set_name(p.x, "x");
  cn.set_name(p.v, "v");
  for (std::size_t k = 0; k < kBeacons.size(); ++k) {
    cn.set_name(p.y[k], std::string("y_") + kBeacons[k].name);
    cn.set_name(p.w[k], std::string("w_") + kBeacons[k].name);
  }
  if (observer) cn.add(observer, {x(0), x(1)});
  return p;
}

}  // namespace lowcost_beacons
