#pragma once
// The network of the drifting clock example (thesis 5.3.2, CN (5.27)),
// shared by examples/cpp/drifting_clock.cpp and bench/bench_examples_ch5.cpp.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "table_values.h"

namespace drifting_clock {

using namespace sillage;
using example::cents;

inline constexpr double kTf = 13.0;
inline constexpr std::array<double, 8> kTau{1.57, 3.34, 5.32, 7.50, 9.88, 12.46, 15.25, 18.24};  // Table 5.3
inline const std::array<Interval, 8> kZ{{{152.47, 156.47},
                                  {34.67, 38.67},
                                  {102.38, 106.38},
                                  {184.45, 188.45},
                                  {167.09, 171.09},
                                  {60.03, 64.03},
                                  {78.76, 82.76},
                                  {175.88, 179.88}}};
inline const char* const kH = "0.045*t^2 + 0.98*t";                                    // (5.23), the truth
inline const char* const kPhi = "[0.08, 0.12]*t + [0.97, 1.08]";                       // (5.24)
inline const char* const kX = "([70, 90] + 100*cos(t), [10, 30] + 100*sin(t))";        // (5.25)
inline const char* const kV = "([-0.1, 0.1] - 100*sin(t), [-0.1, 0.1] + 100*cos(t))";  // (5.26)

struct Problem {
  std::shared_ptr<TubeVector> x, v;
  std::shared_ptr<Tube> y, w, h, phi;
  std::vector<std::shared_ptr<Interval>> t, z, tau;
  std::unique_ptr<ContractorNetwork> cn = std::make_unique<ContractorNetwork>();
};

inline Problem build(const std::shared_ptr<TDomain>& td, double ratio) {
  Problem p;
  p.x = std::make_shared<TubeVector>(td, kX);
  p.v = std::make_shared<TubeVector>(td, kV);
  p.y = std::make_shared<Tube>(td);
  p.w = std::make_shared<Tube>(td);
  p.h = std::make_shared<Tube>(td);
  p.h->set_gate(0, Interval(0.0));  // h(0) = 0
  p.phi = std::make_shared<Tube>(td, kPhi);
  ContractorNetwork& cn = *p.cn;
  cn.set_ratio(ratio);
  const auto x = [&](std::size_t i) { return DomainRef::component(p.x, i); };
  const auto v = [&](std::size_t i) { return DomainRef::component(p.v, i); };
  cn.add(std::make_shared<CtcDeriv>(), {p.x, p.v});
  cn.add(std::make_shared<CtcFunction>(Function({"y", "x1", "x2"}, "y - sqrt(x1^2 + x2^2 + 100)")), {p.y, x(0), x(1)});
  cn.add(std::make_shared<CtcFunction>(Function({"w", "y", "x1", "x2", "v1", "v2"}, "w - (x1*v1 + x2*v2)/y")),
         {p.w, p.y, x(0), x(1), v(0), v(1)});
  cn.add(std::make_shared<CtcDeriv>(), {p.y, p.w});
  cn.add(std::make_shared<CtcDeriv>(), {p.h, p.phi});
  for (std::size_t i = 0; i < kTau.size(); ++i) {
    p.t.push_back(std::make_shared<Interval>(td->t0_tf()));  // unknown reference time
    p.z.push_back(std::make_shared<Interval>(cents(kZ[i])));
    p.tau.push_back(std::make_shared<Interval>(cents(Interval(kTau[i]))));
    cn.add(std::make_shared<CtcEval>(), {p.t.back(), p.tau.back(), p.h, p.phi});  // τ_i = h(t_i)
    cn.add(std::make_shared<CtcEval>(), {p.t.back(), p.z.back(), p.y, p.w});      // z_i = y(t_i)
    const std::string i1 = std::to_string(i + 1);
    cn.set_name(p.t.back(), "t" + i1);
    cn.set_name(p.z.back(), "z" + i1);
    cn.set_name(p.tau.back(), "tau" + i1);
  }
  // Named as in drifting_clock.py, so that an empty network says which domain emptied.
  cn.set_name(p.x, "x");
  cn.set_name(p.v, "v");
  cn.set_name(p.y, "y");
  cn.set_name(p.w, "w");
  cn.set_name(p.h, "h");
  cn.set_name(p.phi, "phi");
  return p;
}

}  // namespace drifting_clock
