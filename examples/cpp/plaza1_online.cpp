// Online estimation on real data (docs/online.md): the plaza1 log replayed in
// stamp order through OnlineEstimator, as the robot would have fed it while
// it drove: each period's odometry when it ends, each range once time has
// reached its stamp. At every time the filtering estimate, the box of the
// position now, must hold the ground truth; it is drawn against the batch
// solve of the same data (which knows the future), with the per-update cost.
// --window S: the seconds of past kept (default 60; 0: everything).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "example_args.h"
#include "plaza1_network.h"
#include "plaza1_online.h"
#include "sillage/figures/figure.h"

using namespace sillage;

namespace {

// The side of the position box: the larger of its two widths, m.
double side(const IntervalVector& p) { return std::max(p[0].diam(), p[1].diam()); }

// Box side over time, online (filtering) and batch (smoothing), log scale.
Figure sizes_figure(const std::vector<double>& t, const std::vector<double>& online, const std::vector<double>& batch,
                    double window) {
  double lo = INFINITY, hi = 0;
  for (const auto* s : {&online, &batch}) {
    for (const double x : *s) {
      if (x > 0 && std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    }
  }
  const double y0 = std::floor(std::log10(lo)), y1 = std::ceil(std::log10(hi));
  Figure fig(IntervalVector{{0, t.back() - t.front()}, {y0, y1 + (y1 == y0 ? 1 : 0)}}, 700, 300);
  fig.set_title("plaza1 online (W = " + (std::isfinite(window) ? std::to_string(static_cast<int>(window)) + " s" : std::string("inf")) +
                "): position box side now, against the batch solve");
  fig.set_labels("t - t0 (s)", "log10 box side (m)");
  const auto curve = [&](const std::vector<double>& y) {
    std::vector<Vector> pts;
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (y[k] > 0 && std::isfinite(y[k])) pts.push_back(Vector{t[k] - t.front(), std::log10(y[k])});
    }
    return pts;
  };
  const Style online_style{"none", "#d62728", 1.2, 1, ""}, batch_style{"none", "#1f77b4", 1.2, 1, ""};
  fig.draw_polyline(curve(online), online_style);
  fig.draw_polyline(curve(batch), batch_style);
  fig.add_legend("online: the box of p at now (filtering)", online_style, LegendMark::Line);
  fig.add_legend("batch: all the data known (smoothing)", batch_style, LegendMark::Line);
  return fig;
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const auto data = example::plaza1_from_args(argc, argv, "plaza1_online");
  if (!data) return 0;
  const example::Plaza1Data& d = *data;
  const plaza1::Bounds b = plaza1::bounds_from_args(argc, argv, d);
  const double w = example::option_number(argc, argv, "--window", 60);
  if (!(w >= 0) || !std::isfinite(w)) {
    std::fprintf(stderr, "plaza1_online: --window takes seconds >= 0 (0: everything), got %g\n", w);
    return 2;
  }
  const double window = w > 0 ? w : INFINITY;

  auto est = plaza1::online_estimator(d, b, window);
  std::size_t inside = 0, checked = 0;
  const plaza1::Replay r = plaza1::replay(*est, d, b, [&](std::size_t k) {
    const IntervalVector p = est->now("p");
    inside += p[0].contains(d.x[k + 1]) && p[1].contains(d.y[k + 1]);
    ++checked;
  });
  const OnlineStats st = est->stats();
  double total = 0;
  for (const double x : r.latency) total += x;
  std::printf("plaza1 online, window %s: %zu periods, %zu ranges, %zu updates in %.2f s (%.0f x real time)\n",
              std::isfinite(window) ? (std::to_string(static_cast<int>(window)) + " s").c_str() : "inf", r.t.size(),
              r.ranges, r.latency.size(), total, (d.t.back() - d.t.front()) / total);
  std::printf("  per update: median %.0f us, p99 %.0f us, max %.0f us (per advance: median %.0f us, p99 %.0f us); %zu "
              "slices in memory at the end, %zu observations retired\n",
              1e6 * plaza1::quantile(r.latency, 0.5), 1e6 * plaza1::quantile(r.latency, 0.99),
              1e6 * plaza1::quantile(r.latency, 1.0), 1e6 * plaza1::quantile(r.advance_latency, 0.5),
              1e6 * plaza1::quantile(r.advance_latency, 0.99), st.slices, st.retired);
  std::printf("  ground truth inside the online box at %zu / %zu times\n", inside, checked);

  // The batch solve of the same data and model (the gyro's bias free at every step, as online):
  // it knows the future, so it is as tight or tighter, up to where each propagation stopped
  // (the ratio 0.01 of both networks).
  plaza1::Bounds same = b;
  same.gyro_drift = same.gyro_bias;
  const auto batch = plaza1::solve(d, same, true, -1, plaza1::kHeadingWindow);
  std::vector<double> online_side, batch_side;
  double ratio = 0;
  std::size_t n = 0, contains_batch = 0;
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    const IntervalVector g = batch.p->gate(k + 1);
    online_side.push_back(side(r.now[k]));
    batch_side.push_back(side(g));
    contains_batch += g.is_subset(r.now[k]);
    if (r.t[k] >= d.t.front() + 60 && side(g) > 0) ratio += side(r.now[k]) / side(g), ++n;
  }
  std::printf("  online box contains the batch box at %zu / %zu times; online/batch box side after 60 s: mean %.2f\n",
              contains_batch, r.t.size(), n ? ratio / static_cast<double>(n) : NAN);
  const std::string name = "plaza1_online_sizes.svg";
  sizes_figure(r.t, online_side, batch_side, window).save((out / name).string());

  const bool ok = r.consistent && inside == checked && !batch.stats.empty;
  char summary[300];
  std::snprintf(summary, sizeof summary,
                "W = %s: truth inside %zu / %zu, median update %.0f us, p99 %.0f us, %.0f x real time, online/batch "
                "box %.2f",
                std::isfinite(window) ? (std::to_string(static_cast<int>(window)) + " s").c_str() : "inf", inside,
                checked, 1e6 * plaza1::quantile(r.latency, 0.5), 1e6 * plaza1::quantile(r.latency, 0.99),
                (d.t.back() - d.t.front()) / total, n ? ratio / static_cast<double>(n) : NAN);
  example::print_result("plaza1_online", summary, ok, {{name, "plaza1 online: box side over time, online vs batch"}});
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }
