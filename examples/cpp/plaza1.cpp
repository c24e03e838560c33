// Real data: CMU "Plaza 1" (../shared/data/plaza1, read in place). A robot
// drives a lawn-mower path in an open plaza; odometry gives a distance and a
// (drifting) heading change per period of about 0.2 s, and a radio measures
// ranges to 4 surveyed beacons, biased long. Two guaranteed estimates:
//   1. dead reckoning from the odometry alone;
//   2. the same plus the 3529 ranges, each at an uncertain time (CtcEval).
// The stated error bounds (kBounds below) are the model; the check is that
// every ground-truth sample lies in the position tube.
//
// The network, on the time points of the data (one slice per odometry period):
//   ψ(t_{k+1}) − ψ(t_k) ∈ Δψ_k + δ_k [−b, b]        (CtcIncrement: gyro bias b)
//   ψ' ∈ [−ω_max, ω_max]                             (CtcDeriv: the slices of ψ)
//   i(k) = d (cos [ψ](k), sin [ψ](k)), d ∈ d_k [1 − ε, 1 + ε] + [−a, a]  (slice by slice)
//   p(t_{k+1}) − p(t_k) ∈ i(k)                       (CtcIncrement)
//   v = s (cos ψ, sin ψ), s ∈ [0, s_max]; p' = v     (pointwise; CtcDeriv: slices)
//   for each range j: q_j = p(t_j), t_j ∈ stamp ± τ  (CtcEval)
//                     |q_j − beacon| ∈ r_j − [e⁻, e⁺] (pointwise on the box q_j)
// ∫ d cos ψ over a slice lies in d_k cos([ψ](k)) since the speed is >= 0.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "example_args.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/figures/tube_figure.h"
#include "sillage/interval/elementary.h"
#include "sillage/io/csv.h"

using namespace sillage;
namespace fs = std::filesystem;

namespace {

// The error model, and why.
struct Bounds {
  double pos0 = 0.1;        // m: the start is the ground-truth origin
  double heading0 = 0.05;   // rad: initial heading from the ground truth
  double gyro_bias = 5e-4;  // rad/s: the heading of the odometry drifts by -0.35 mrad/s on average
  double turn_max = 0.8;    // rad/s: the odometry turn rates stay within [-0.71, 0.60]
  double dist_rel = 0.02;   // odometer scale error (the total distance is within 0.12 % of the truth)
  // m per period: the odometry may count distance the robot did not travel. Standing still at the
  // start it counts 0.17 m in 229 periods, up to 7 cm in one, while the ground truth moves by 7 mm
  // (wheel slip); so the true distance may be up to dist_over less than counted, never negative.
  double dist_over = 0.07, dist_under = 0.001;
  double speed_max = 5.0;   // m/s: the robot's speed (mean per period <= 4.4 m/s, time-stamp jitter included)
  // Range error measured - true in [err_lo, err_hi]: the radio ranges are biased long by about 2.8 m; over
  // this run the error spans [-0.63, 6.57] m (antenna offset and timing included), widened by 0.4 m.
  double range_err_lo = -1.0, range_err_hi = 7.0;
  double time_err = 0.2;  // s: range time stamps (the best time shift is 0 to within 0.25 s)
};

struct Data {
  std::vector<double> t, x, y, heading;  // ground truth at the time points
  std::vector<double> dist, dpsi;        // odometry increment k covers [t_k, t_{k+1}]
  std::vector<double> rt, rid, r;        // ranges
  std::map<int, std::pair<double, double>> beacons;
};

Data load(const fs::path& dir) {
  Data d;
  const CsvTable gt = CsvTable::read((dir / "ground_truth.csv").string());
  const CsvTable odo = CsvTable::read((dir / "odometry.csv").string());
  const CsvTable rg = CsvTable::read((dir / "ranges.csv").string());
  const CsvTable bc = CsvTable::read((dir / "beacons.csv").string());
  d.t = gt.values("t_s"), d.x = gt.values("x_m"), d.y = gt.values("y_m"), d.heading = gt.values("heading_rad");
  d.dist = odo.values("delta_dist_m"), d.dpsi = odo.values("delta_heading_drp_rad");
  const std::vector<double> ot = odo.values("t_s");
  if (ot.size() + 1 != d.t.size()) throw Error("plaza1: expected one odometry row per ground-truth step");
  for (std::size_t k = 0; k < ot.size(); ++k) {
    if (ot[k] != d.t[k + 1]) throw Error("plaza1: odometry row " + std::to_string(k) + " does not end at t_{k+1}");
  }
  d.rt = rg.values("t_s"), d.rid = rg.values("beacon_id"), d.r = rg.values("range_m");
  const auto ids = bc.values("beacon_id"), bx = bc.values("x_m"), by = bc.values("y_m");
  for (std::size_t i = 0; i < ids.size(); ++i) d.beacons[static_cast<int>(ids[i])] = {bx[i], by[i]};
  return d;
}

// A tube of per-slice values; its gates are the hulls of the two neighbouring
// slices (they carry no information of their own).
Tube slice_tube(const std::shared_ptr<TDomain>& td, const std::vector<Interval>& s) {
  std::vector<Interval> g(s.size() + 1);
  for (std::size_t k = 0; k <= s.size(); ++k) g[k] = (k > 0 ? s[k - 1] : s[k]) | (k < s.size() ? s[k] : s[k - 1]);
  return Tube(td, s, g);
}

struct Result {
  std::shared_ptr<TubeVector> p;
  ContractStats stats;
  double cpu = 0;
  std::size_t inside = 0, nb_ranges = 0;
  double mean_diam = 0, max_diam = 0;
};

Result solve(const Data& d, const Bounds& b, bool with_ranges) {
  const double start = static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
  const auto td = TDomain::create(d.t);
  const std::size_t n = td->nb_slices();
  std::vector<Interval> dpsi(n), dist(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Interval w = td->slice_width(k);
    dpsi[k] = Interval(d.dpsi[k]) + w * Interval(-b.gyro_bias, b.gyro_bias);
    dist[k] = (Interval(d.dist[k]) * Interval(1 - b.dist_rel, 1 + b.dist_rel) + Interval(-b.dist_over, b.dist_under)) &
              Interval(0, INFINITY);
  }
  auto psi = std::make_shared<Tube>(td);
  psi->set_gate(0, Interval(d.heading[0]) + Interval(-b.heading0, b.heading0));
  auto dpsi_t = std::make_shared<Tube>(slice_tube(td, dpsi));
  auto omega = std::make_shared<Tube>(td, Interval(-b.turn_max, b.turn_max));
  auto speed = std::make_shared<Tube>(td, Interval(0, b.speed_max));
  auto v = std::make_shared<TubeVector>(td, 2);
  Result res;
  res.p = std::make_shared<TubeVector>(td, 2);
  res.p->set_gate(0, IntervalVector{{d.x[0] - b.pos0, d.x[0] + b.pos0}, {d.y[0] - b.pos0, d.y[0] + b.pos0}});

  // The heading first: nothing flows back to it from the positions.
  ContractorNetwork heading;
  heading.add(std::make_shared<CtcIncrement>(), {psi, dpsi_t});
  heading.add(std::make_shared<CtcDeriv>(), {psi, omega});
  heading.contract();
  // Increments of p over each slice: per-slice quantities, not values of a
  // continuous function of time, so computed slice by slice (not as a tube
  // constraint, whose gates would tie neighbouring slices together).
  std::vector<Interval> inc1(n), inc2(n);
  for (std::size_t k = 0; k < n; ++k) {
    inc1[k] = dist[k] * cos(psi->slice(k));
    inc2[k] = dist[k] * sin(psi->slice(k));
  }
  auto inc = std::make_shared<TubeVector>(std::vector<Tube>{slice_tube(td, inc1), slice_tube(td, inc2)});

  ContractorNetwork cn;
  cn.add(std::make_shared<CtcFunction>(Function({"a", "s", "h"}, "a - s*cos(h)")),
         {DomainRef::component(v, 0), speed, psi});
  cn.add(std::make_shared<CtcFunction>(Function({"a", "s", "h"}, "a - s*sin(h)")),
         {DomainRef::component(v, 1), speed, psi});
  cn.add(std::make_shared<CtcIncrement>(), {res.p, inc});
  cn.add(std::make_shared<CtcDeriv>(), {res.p, v});

  std::vector<std::shared_ptr<Interval>> times;
  std::vector<std::shared_ptr<IntervalVector>> boxes;
  if (with_ranges) {
    const auto eval = std::make_shared<CtcEval>();
    for (std::size_t j = 0; j < d.rt.size(); ++j) {
      const Interval tj = Interval(d.rt[j] - b.time_err, d.rt[j] + b.time_err) & td->t0_tf();
      if (tj.is_empty()) continue;
      const auto [bx, by] = d.beacons.at(static_cast<int>(d.rid[j]));
      times.push_back(std::make_shared<Interval>(tj));
      boxes.push_back(std::make_shared<IntervalVector>(2));
      const Interval range = Interval(d.r[j] - b.range_err_hi, d.r[j] - b.range_err_lo) & Interval(0, INFINITY);
      const Function dist_to_beacon({"q1", "q2"}, "sqrt((q1 - " + number_text(bx) + ")^2 + (q2 - " +
                                                      number_text(by) + ")^2)");
      cn.add(eval, {times.back(), boxes.back(), res.p, v});
      cn.add(std::make_shared<CtcFunction>(dist_to_beacon, range), {boxes.back()});
    }
  }
  res.nb_ranges = times.size();
  res.stats = cn.contract();
  res.cpu = static_cast<double>(std::clock()) / CLOCKS_PER_SEC - start;

  // Ground truth at every time point, and the size of the position boxes.
  for (std::size_t k = 0; k <= n; ++k) {
    const IntervalVector g = res.p->gate(k);
    const bool in = g[0].contains(d.x[k]) && g[1].contains(d.y[k]);
    if (!in && k - res.inside < 5) {  // the first misses, if any: which bound is too tight shows there
      std::printf("  miss k=%zu t=%.3f truth (%.3f, %.3f) box [%.3f, %.3f] x [%.3f, %.3f]\n", k, d.t[k], d.x[k], d.y[k],
                  g[0].lb(), g[0].ub(), g[1].lb(), g[1].ub());
    }
    res.inside += in;
    const double diam = std::max(g[0].diam(), g[1].diam());
    res.mean_diam += diam / static_cast<double>(n + 1);
    res.max_diam = std::max(res.max_diam, diam);
  }
  return res;
}

fs::path data_dir(int argc, char** argv) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::string(argv[i]) == "--data") return argv[i + 1];
  }
  return fs::path(SILLAGE_SHARED_DIR) / "data" / "plaza1";
}

}  // namespace

int main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const fs::path dir = data_dir(argc, argv);
  if (!fs::exists(dir / "odometry.csv")) {
    std::printf("no plaza1 data at %s (pass --data DIR)\n", dir.string().c_str());
    example::print_result("plaza1", "skipped: no data", true);
    return 0;
  }
  const Data d = load(dir);
  const Bounds b;
  bool ok = true;
  std::string summary;
  std::vector<std::pair<std::string, std::string>> figures;
  const Trajectory tx(d.t, d.x), ty(d.t, d.y);
  for (const bool with_ranges : {false, true}) {
    const Result r = solve(d, b, with_ranges);
    const std::size_t n = d.t.size();
    const char* label = with_ranges ? "odometry + ranges" : "odometry only";
    std::printf("%s: %zu ranges, %zu rounds, %zu contractor runs, %.2f s CPU, empty = %d\n", label, r.nb_ranges,
                r.stats.iterations, r.stats.contractor_calls, r.cpu, r.stats.empty);
    if (r.stats.empty) std::printf("  empty: %s\n", r.stats.empty_domain.c_str());
    std::printf("  ground truth inside at %zu / %zu time points (%.1f %%); position box diameter mean %.2f m, max %.2f m\n",
                r.inside, n, 100.0 * static_cast<double>(r.inside) / static_cast<double>(n), r.mean_diam, r.max_diam);
    ok = ok && r.inside == n && !r.stats.empty;
    char buf[200];
    std::snprintf(buf, sizeof buf, "%s: truth inside %.1f %%, mean/max box diameter %.2f/%.2f m, %.2f s; ", label,
                  100.0 * static_cast<double>(r.inside) / static_cast<double>(n), r.mean_diam, r.max_diam, r.cpu);
    summary += buf;
    const std::string tag = with_ranges ? "ranges" : "odometry";
    Figure fig = tube_vector_figure(*r.p, 0, 1, std::string("plaza1: position tube, ") + label, {}, &tx, &ty);
    for (const auto& [id, xy] : d.beacons) {
      fig.draw_point(Vector{xy.first, xy.second}, 5.0, {"#d62728", "black", 1, 1, ""});
    }
    fig.save((out / ("plaza1_map_" + tag + ".svg")).string());
    figures.push_back({"plaza1_map_" + tag + ".svg", std::string("plaza1 map, ") + label + " (beacons in red)"});
    thickness_figure(*r.p, ThicknessMeasure::MaxDiameter, std::string("plaza1: position box diameter, ") + label)
        .save((out / ("plaza1_thickness_" + tag + ".svg")).string());
    figures.push_back({"plaza1_thickness_" + tag + ".svg", std::string("plaza1 thickness, ") + label});
  }
  example::print_result("plaza1", summary, ok, figures);
  return ok ? 0 : 1;
}
