// The reports of a replay (replay_problem.h): its figures of merit, the SVG
// figure, the JSON and the HTML page.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "sillage/error.h"
#include "sillage/figures/figure.h"
#include "sillage/problem/replay_problem.h"

namespace sillage {

namespace {

// The side of a box: its largest width (0 for an empty component).
double side(const IntervalVector& x) {
  double s = 0;
  for (std::size_t i = 0; i < x.size(); ++i) s = std::max(s, x[i].is_empty() ? 0.0 : x[i].diam());
  return s;
}

}  // namespace

double ReplayResult::latency_quantile(double q) const {
  if (latency.empty()) return 0;
  std::vector<double> x = latency;
  const auto i = static_cast<std::size_t>(std::min(q * static_cast<double>(x.size()), static_cast<double>(x.size() - 1)));
  std::nth_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(i), x.end());
  return x[i];
}

std::size_t ReplayResult::online_holds_batch() const {
  std::size_t n = 0;
  for (std::size_t k = 0; k < batch.size(); ++k) {
    bool holds = true;
    for (std::size_t j = 0; j < outputs.size(); ++j) {
      for (std::size_t i = 0; i < online[k][j].size(); ++i) {
        const Interval& on = online[k][j][i];
        const double slack = 1e-9 * std::max(1.0, on.mag());
        holds = holds && batch[k][j][i].is_subset(on + Interval(-slack, slack));
      }
    }
    n += holds;
  }
  return n;
}

double ReplayResult::mean_side_ratio(double after) const {
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < batch.size(); ++k) {
    if (t[k] < t.front() + after) continue;
    double on = 0, ba = 0;
    for (std::size_t j = 0; j < outputs.size(); ++j) on = std::max(on, side(online[k][j])), ba = std::max(ba, side(batch[k][j]));
    if (std::isfinite(on) && std::isfinite(ba) && ba > 0) sum += on / ba, ++n;
  }
  return n ? sum / static_cast<double>(n) : NAN;
}

std::string replay_svg(const Problem& p, const ReplayResult& r) {
  double lo = INFINITY, hi = 0;
  const auto each_side = [&](const std::vector<std::vector<IntervalVector>>& boxes, std::size_t j, auto&& f) {
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      const double s = side(boxes[k][j]);
      if (s > 0 && std::isfinite(s)) f(k, s);
    }
  };
  for (std::size_t j = 0; j < r.outputs.size(); ++j)
    for (const auto* b : {&r.online, &r.batch}) each_side(*b, j, [&](std::size_t, double s) { lo = std::min(lo, s), hi = std::max(hi, s); });
  if (!(lo <= hi)) lo = 1, hi = 10;
  const double y0 = std::floor(std::log10(lo)), y1 = std::ceil(std::log10(hi));
  const double t0 = r.t.empty() ? p.time.t0 : r.t.front(), t1 = r.t.empty() ? t0 + 1 : r.t.back();
  Figure fig(IntervalVector{{0, std::max(t1 - t0, 1e-9)}, {y0, y1 + (y1 == y0 ? 1 : 0)}}, 760, 340);
  fig.set_title("sillage replay " + p.file + ": box side now (online) against the batch solve");
  fig.set_labels("t - t0", "log10 box side (in each variable's unit)");
  static const char* colours[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  for (std::size_t j = 0; j < r.outputs.size(); ++j) {
    const std::string c = colours[j % 6];
    const auto curve = [&](const std::vector<std::vector<IntervalVector>>& boxes) {
      std::vector<Vector> pts;
      each_side(boxes, j, [&](std::size_t k, double s) { pts.push_back(Vector{r.t[k] - t0, std::log10(s)}); });
      return pts;
    };
    const Style online{"none", c, 1.4, 1, ""}, batch{"none", c, 0.7, 0.6, ""};
    fig.draw_polyline(curve(r.online), online);
    fig.add_legend(r.outputs[j] + " online (filtering)", online, LegendMark::Line);
    if (!r.batch.empty()) {
      fig.draw_polyline(curve(r.batch), batch);
      fig.add_legend(r.outputs[j] + " batch (smoothing), thin", batch, LegendMark::Line);
    }
  }
  return fig.svg();
}

std::string replay_json(const Problem& p, const ReplayResult& r) {
  nlohmann::ordered_json j;
  j["problem"] = p.file;
  j["status"] = status_name(r.summary.status);
  if (!r.summary.reason.empty()) j["reason"] = r.summary.reason;
  j["rows"] = r.rows;
  j["updates"] = r.t.size();
  j["seconds"] = r.seconds;
  const double span = r.t.empty() ? 0 : r.t.back() - p.time.t0;
  j["real_time_factor"] = r.seconds > 0 ? span / r.seconds : 0;
  j["latency_us"] = {{"median", 1e6 * r.latency_quantile(0.5)},
                     {"p90", 1e6 * r.latency_quantile(0.9)},
                     {"p99", 1e6 * r.latency_quantile(0.99)},
                     {"max", 1e6 * r.latency_quantile(1.0)}};
  j["refused"] = r.refused;
  if (p.output.truth)
    j["truth"] = {{"samples", r.truth_samples}, {"inside", r.truth_inside}, {"unbounded", r.truth_unbounded},
                  {"misses", r.truth_misses}};
  if (r.batch_solve) {
    j["batch"] = {{"status", status_name(r.batch_solve->summary.status)},
                  {"online_holds_batch", r.online_holds_batch()},
                  {"times", r.batch.size()},
                  {"mean_side_ratio", r.mean_side_ratio(0)}};
  }
  return j.dump(2) + "\n";
}

std::string replay_html(const Problem& p, const ReplayResult& r) {
  const auto us = [&](double q) { return std::to_string(static_cast<long long>(std::llround(1e6 * r.latency_quantile(q)))); };
  const auto row = [](const std::string& k, const std::string& v) { return "<tr><td>" + k + "</td><td>" + v + "</td></tr>\n"; };
  const bool empty = r.summary.status == Status::NoSolution;
  const double span = r.t.empty() ? 0 : r.t.back() - p.time.t0;
  char wall[64];
  std::snprintf(wall, sizeof wall, "%.3f s (%.0f × real time)", r.seconds, r.seconds > 0 ? span / r.seconds : 0.0);
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>sillage replay: " +
                  xml_escape(p.file) +
                  "</title>\n<style>body{font-family:sans-serif;max-width:1000px;margin:auto;padding:1em}"
                  "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:2px 6px;font-size:90%}"
                  ".empty{color:#b00;font-weight:bold}figcaption{font-size:90%;color:#444}</style></head><body>\n";
  h += "<h1>sillage replay " + xml_escape(p.file) + "</h1>\n";
  h += empty ? "<p class=\"empty\" id=\"status\">No solution: " + xml_escape(r.summary.reason) + "</p>\n"
             : "<p id=\"status\">Replayed online: the file's tables fed in stamp order (docs/online.md).</p>\n";
  h += "<table id=\"replay\">\n" + row("rows fed", std::to_string(r.rows)) + row("updates", std::to_string(r.t.size())) +
       row("wall clock", wall) +
       row("latency per row", "median " + us(0.5) + " µs, p90 " + us(0.9) + " µs, p99 " + us(0.99) + " µs, max " + us(1) + " µs") +
       row("rows refused", std::to_string(r.refused.size()));
  if (p.output.truth)
    h += row("truth", std::to_string(r.truth_inside) + " of " + std::to_string(r.truth_samples) +
                          " samples inside the online tubes, " + std::to_string(r.truth_unbounded) +
                          " in a box still unbounded, " +
                          std::to_string(r.truth_samples - r.truth_inside - r.truth_unbounded) + " outside");
  if (r.batch_solve) {
    char ratio[32];
    std::snprintf(ratio, sizeof ratio, "%.2f", r.mean_side_ratio(0));
    h += row("against the batch solve", "the online box holds the batch one at " + std::to_string(r.online_holds_batch()) +
                                            " of " + std::to_string(r.batch.size()) + " updates; online / batch box side " +
                                            ratio + " on average");
  }
  h += "</table>\n<figure>" + replay_svg(p, r) +
       "<figcaption>The side of each output's box now (online, filtering) against the batch box at the same "
       "time (smoothing: it knows the future), log scale.</figcaption></figure>\n";
  if (!r.truth_misses.empty() || !r.refused.empty()) {
    h += "<ul id=\"notes\">";
    for (const std::string& m : r.truth_misses) h += "<li>truth outside: " + xml_escape(m) + "</li>";
    for (std::size_t i = 0; i < r.refused.size() && i < 20; ++i) h += "<li>refused: " + xml_escape(r.refused[i]) + "</li>";
    h += "</ul>\n";
  }
  return h + "</body></html>\n";
}

}  // namespace sillage
