// Static range-only localization of thesis 2.3.3 (Table 2.1): three beacons,
// bounded ranges, an unknown position x in [-inf, inf]^2, one contractor per
// range constraint (2.35), propagated to the fixed point by a ContractorNetwork.
#include <chrono>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "example_args.h"
#include "example_bound.h"
#include "example_check.h"
#include "sillage/figures/figure.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/expr/function.h"

using namespace sillage;

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  struct Beacon {
    double x1, x2;
    Interval rho;
  };
  const std::vector<Beacon> beacons = {
      {-0.5, 4.0, example::bound(Interval(3.63, 4.43))},
      {-2.5, -2.5, example::bound(Interval(3.13, 3.93))},
      {2.5, -0.5, example::bound(Interval(2.15, 2.95))}};

  ContractorNetwork cn;
  auto x = cn.create_dom(IntervalVector(2), "x");  // unknown position; named for the emptiness explanation
  std::vector<std::shared_ptr<Interval>> rho;
  for (const auto& b : beacons) {
    std::ostringstream g;  // (2.35): rho = sqrt((x1 - x1k)^2 + (x2 - x2k)^2)
    g.precision(17);
    g << "sqrt((x1 - " << b.x1 << ")^2 + (x2 - " << b.x2 << ")^2) - rho";
    rho.push_back(cn.create_dom(b.rho, "rho" + std::to_string(rho.size() + 1)));
    cn.add(std::make_shared<CtcFunction>(Function({"x1", "x2", "rho"}, g.str())), {x, rho.back()});
  }

  const ContractStats stats = cn.contract();
  if (stats.empty) return example::empty_exit("beacons_static", stats);
  const bool ok = example::enclosure_ok(*x) && x->contains({0.0, 0.0});
  std::printf("Static range-only localization, thesis Table 2.1 (robot at (0, 0))\n");
  std::printf("  final box:   %s\n", x->str().c_str());
  std::printf("  contains (0, 0): %s\n", ok ? "yes" : "NO");
  std::printf("  iterations:  %zu (the thesis reports 7), contractor calls: %zu, time: %.3g ms\n",
              stats.iterations, stats.contractor_calls, stats.time * 1e3);

  // Figure 2.9: the rings of the three measurements, the beacons and the contracted box.
  Figure fig(IntervalVector{{-7.5, 7.5}, {-7.5, 9.0}});
  fig.set_title("Static range-only localization (Table 2.1)");
  fig.set_labels("x1", "x2");
  for (const auto& b : beacons) fig.draw_ring({b.x1, b.x2}, b.rho, {"#4a90d9", "#2a5f9e", 0.5, 0.25, ""});
  fig.draw_box(*x, {"#ffd24d", "#a07800", 1.5, 0.8, ""});
  for (const auto& b : beacons) fig.draw_box(IntervalVector{{b.x1 - 0.2, b.x1 + 0.2}, {b.x2 - 0.2, b.x2 + 0.2}},
                                             {"#d62728", "black", 1, 1, ""});
  fig.draw_point({0.0, 0.0}, 3.0);
  const std::string fig_name = "beacons_static.svg";
  fig.save((out / fig_name).string());

  std::ostringstream result;
  result.precision(4);
  result << stats.iterations << " iterations, box " << *x;
  example::print_result("beacons_static", result.str(), ok,
                        {{fig_name, "Table 2.1: rings of the three range measurements and the contracted box"}});
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }
