// Loops of a survey mission, detected and proven from velocities only
// (thesis ch. 6, applications 6.4: the table λ_N / λ_T / λ* of 6.4.1).
//
// A synthetic AUV survey (looping_mission.h: lawn-mower legs along x, then
// cross-legs along y, 1.6 m/s, velocity measured every 0.1 s within
// e = 0.01 m/s per axis) is dead-reckoned from its velocity tube [v](.).
// The t-plane of f(t1, t2) = ∫_{t1}^{t2} v gives:
//   detections   the components Ω_i of the outer approximation of 𝕋
//                (Alg. 6, eps = (tf - t0)/2000 as in the thesis);
//   λ_N          complete detections proven by the interval Newton test N;
//   λ_T          complete detections proven by the topological degree test T;
//   λ*           true crossings (6.20) inside complete detections.
// The true crossings come from the true path (self_crossings on the path
// sampled every 0.05 s, refined by Newton on the closed-form path). Checks:
// every proven detection holds a true crossing (exactly one if proven by N,
// as many as its count when counted), every known degree (of a detection or
// a piece) is the sum of the indices of the true crossings inside, the
// pieces' degrees add up to their detection's, every true crossing lies in the outer
// approximation, and the tube holds the true velocity (sampled); the example
// exits with 1 if one fails.
//
// Options: --out DIR, --hours H (default 1), --eps-divisor D (default 2000),
// --e E (velocity error bound, default 0.01 m/s), --seed S (default 2017),
// --lissajous 1 (the open Lissajous path of bench_tplane instead of the
// survey), --study 1 (why each unproven true crossing is left: loops_study.h;
// 2: the same with the detail of every detection studied).
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "example_args.h"
#include "looping_mission.h"
#include "loops_study.h"
#include "sillage/figures/loops_map_figure.h"
#include "sillage/figures/tplane_figure.h"
#include "sillage/loops/tplane.h"
#include "sillage/tube/tube_integral.h"

using namespace sillage;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool contains(const Loop& loop, const PathCrossing& c) {
  for (const IntervalVector& b : loop.boxes()) {
    if (b[0].contains(c.t1) && b[1].contains(c.t2)) return true;
  }
  return false;
}

// Samples v*(t) at three inner points of every slice and at the gates: a
// sanity check of the generator (the tube is built to hold v* everywhere).
std::size_t velocity_misses(const looping_mission::Mission& m) {
  const TubeVector& v = m.velocity_tube();
  const TDomain& td = *m.tdomain();
  std::size_t misses = 0;
  for (std::size_t k = 0; k < td.nb_slices(); ++k) {
    const IntervalVector s = v.slice(k), g = v.gate(k);
    const auto vg = m.velocity(td.t(k));
    if (!g[0].contains(vg[0]) || !g[1].contains(vg[1])) ++misses;
    for (double f : {0.25, 0.5, 0.75}) {
      const auto vs = m.velocity(td.t(k) + f * (td.t(k + 1) - td.t(k)));
      if (!s[0].contains(vs[0]) || !s[1].contains(vs[1])) ++misses;
    }
  }
  return misses;
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const double hours = example::option_number(argc, argv, "--hours", 1.0);
  const double divisor = example::option_number(argc, argv, "--eps-divisor", 2000.0);
  const double e = example::option_number(argc, argv, "--e", 0.01), seed = example::option_number(argc, argv, "--seed", 2017);
  const bool lissajous = example::option_number(argc, argv, "--lissajous", 0) != 0;
  const double study = example::option_number(argc, argv, "--study", 0);
  if (!(hours > 0) || !(divisor >= 1) || !(e > 0) || !(seed >= 0)) {
    std::fprintf(stderr, "loops_survey: need --hours > 0, --eps-divisor >= 1, --e > 0 and --seed >= 0\n");
    return 2;
  }

  // ---- the mission ----
  auto clock = std::chrono::steady_clock::now();
  looping_mission::Parameters params;
  params.duration = 3600.0 * hours;
  params.e = e;
  params.seed = static_cast<std::uint64_t>(seed);
  // One of the two missions.
  std::unique_ptr<const looping_mission::Mission> mission;
  std::unique_ptr<const looping_mission::Lissajous> curve;
  if (lissajous) {
    curve = std::make_unique<const looping_mission::Lissajous>(params.duration, params.e, params.dt);
  } else {
    mission = std::make_unique<const looping_mission::Mission>(params);
  }
  const TubeVector& v = lissajous ? curve->velocity_tube() : mission->velocity_tube();
  const std::shared_ptr<TDomain>& tdomain = lissajous ? curve->tdomain() : mission->tdomain();
  const double tf = lissajous ? curve->tf() : mission->tf();
  const auto velocity = [&](double t) { return lissajous ? curve->velocity(t) : mission->velocity(t); };
  const double t_mission = seconds_since(clock);
  clock = std::chrono::steady_clock::now();
  const std::vector<PathCrossing> truth =
      lissajous ? curve->true_crossings(params.dt / 2) : mission->true_crossings(params.dt / 2);
  const double t_truth = seconds_since(clock);
  if (lissajous) {
    std::printf("Mission: Lissajous path, %.0f s, %zu slices, e = %g m/s\n", tf, v.nb_slices(), params.e);
  } else {
    std::printf("Mission: %.0f s, %zu blocks, %zu pieces, %.0f m of track, %zu slices, e = %g m/s\n", tf,
                mission->nb_blocks(), mission->pieces().size(), mission->path_length(), v.nb_slices(), params.e);
  }
  std::printf("  generated in %.3f s; %zu true crossings found in %.3f s (path sampled every %g s)\n", t_mission,
              truth.size(), t_truth, params.dt / 2);

  // ---- detections and proofs ----
  const double eps = tf / divisor;
  TPlane tplane(tdomain);
  clock = std::chrono::steady_clock::now();
  tplane.compute_detections(eps, v);
  const double t_detect = seconds_since(clock);
  clock = std::chrono::steady_clock::now();
  tplane.compute_proofs(v);
  const double t_prove = seconds_since(clock);

  // ---- the table of 6.4.1, and the checks ----
  std::size_t lambda_star = 0, in_proven = 0, outside = 0, bad_proofs = 0, bad_counts = 0, counted = 0;
  std::size_t loops_counted = 0, degree_sum = 0, in_proven_pieces = 0;
  std::vector<std::size_t> unproven_by_crossings(4, 0);  // unproven complete detections holding 0, 1, 2, 3+ crossings
  std::vector<int> crossing_component(truth.size(), -1);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    for (std::size_t c = 0; c < tplane.detections().size(); ++c) {
      if (contains(tplane.detections()[c], truth[i])) {
        crossing_component[i] = int(c);
        break;
      }
    }
    if (crossing_component[i] < 0) {
      ++outside;
      std::printf("  CHECK FAILED: true crossing (%.3f, %.3f) at (%.2f, %.2f) is outside the outer approximation\n",
                  truth[i].t1, truth[i].t2, truth[i].x, truth[i].y);
      continue;
    }
    const Loop& l = tplane.detections()[crossing_component[i]];
    if (l.complete()) {
      ++lambda_star;
      bool in_piece = false;
      for (const Loop& p : l.pieces()) in_piece = in_piece || (p.proven() && contains(p, truth[i]));
      if (l.proven() || in_piece) ++in_proven;
      if (!l.proven() && in_piece) ++in_proven_pieces;
    }
  }
  // The index of each true crossing: the degree of a region is the sum of
  // the indices of the crossings inside it (checked below).
  std::vector<int> index(truth.size());
  for (std::size_t i = 0; i < truth.size(); ++i) index[i] = loops_study::orientation(truth[i], velocity);
  auto net_index = [&](const Loop& l) {
    int net = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) net += contains(l, truth[i]) ? index[i] : 0;
    return net;
  };
  std::size_t bad_degrees = 0;
  auto check_degree = [&](const Loop& l, const char* what) {
    if (!l.complete() || !l.degree() || *l.degree() == net_index(l)) return;
    ++bad_degrees;
    std::printf("  CHECK FAILED: %s t in %s has degree %d, its true crossings add up to %d\n", what,
                l.t_box().str().c_str(), *l.degree(), net_index(l));
  };
  // The pieces of split detections (component_split.h): the same checks, and
  // the split keeps the degree (the pieces' degrees add up to the detection's).
  for (const Loop& l : tplane.detections()) {
    check_degree(l, "detection");
    std::optional<int> sum = l.pieces().empty() ? std::nullopt : std::optional<int>(0);
    for (const Loop& p : l.pieces()) sum = sum && p.degree() ? std::optional<int>(*sum + *p.degree()) : std::nullopt;
    if (sum && l.degree() && *sum != *l.degree()) {
      ++bad_degrees;
      std::printf("  CHECK FAILED: the pieces of detection t in %s add up to degree %d, not %d\n",
                  l.t_box().str().c_str(), *sum, *l.degree());
    }
    for (const Loop& p : l.pieces()) {
      check_degree(p, "piece");
      std::size_t inside = 0;
      for (const PathCrossing& c : truth) inside += contains(p, c) ? 1 : 0;
      if ((p.proven() && inside == 0) || (p.count() && *p.count() != inside)) {
        ++bad_proofs;
        std::printf("  CHECK FAILED: a piece of detection t in %s, t in %s, claims %s but holds %zu true crossings\n",
                    l.t_box().str().c_str(), p.t_box().str().c_str(), p.count() ? "a count" : "a loop", inside);
      }
    }
  }
  for (std::size_t c = 0; c < tplane.detections().size(); ++c) {
    const Loop& l = tplane.detections()[c];
    std::size_t inside = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) inside += crossing_component[i] == int(c) ? 1 : 0;
    if ((l.proven() || l.proven_newton()) && inside == 0) {
      ++bad_proofs;
      std::printf("  CHECK FAILED: detection %zu, t in %s, is proven but holds no true crossing\n", c,
                  l.t_box().str().c_str());
    }
    if (l.proven_newton() && inside != 1) {  // N proves a unique loop in the component
      ++bad_proofs;
      std::printf("  CHECK FAILED: detection %zu is proven by Newton but holds %zu true crossings\n", c, inside);
    }
    if (l.proven()) degree_sum += std::size_t(std::abs(*l.degree()));
    if (l.complete() && !l.proven_split()) ++unproven_by_crossings[std::min<std::size_t>(inside, 3)];
    if (l.count()) {
      ++counted;
      loops_counted += *l.count();
      if (*l.count() != inside) {
        ++bad_counts;
        std::printf("  CHECK FAILED: detection %zu counts %zu loops, the truth has %zu\n", c, *l.count(), inside);
      }
    }
  }
  const std::size_t misses = lissajous ? 0 : velocity_misses(*mission);
  if (misses) std::printf("  CHECK FAILED: the velocity tube misses v* at %zu sampled times\n", misses);

  const std::size_t nb_det = tplane.nb_detections(), nb_complete = tplane.nb_complete_detections();
  const double ratio = lambda_star ? 100.0 * double(in_proven) / double(lambda_star) : 100.0;
  std::printf("\nt-plane: eps = %.3f s, %zu leaves (%zu inner, %zu boundary)\n", eps, tplane.paving().nb_leaves(),
              tplane.paving().count(PavingTag::Inner), tplane.paving().count(PavingTag::Boundary));
  std::printf("detections: %zu (%zu complete, %zu partial)\n", nb_det, nb_complete, nb_det - nb_complete);
  std::printf("\n  lambda_N  complete detections proven by Newton      %4zu\n", tplane.nb_newton_proofs());
  std::printf("  lambda_T  complete detections proven by the degree  %4zu   (sum |deg| = %zu)\n", tplane.nb_proofs(),
              degree_sum);
  std::printf("  lambda*   true crossings in complete detections     %4zu   (%zu crossings in all)\n", lambda_star,
              truth.size());
  std::printf("            of which inside proven detections         %4zu   (%.1f %%)\n", in_proven, ratio);
  std::printf("            ... proven only in pieces of split detections %zu (%zu proven sub-loops in all)\n",
              in_proven_pieces, tplane.proofs().size());
  std::printf("            unproven complete detections holding 0 / 1 / 2 / 3+ true crossings: %zu / %zu / %zu / %zu\n",
              unproven_by_crossings[0], unproven_by_crossings[1], unproven_by_crossings[2], unproven_by_crossings[3]);
  std::printf("  counted   detections with an exact count (Alg. 10)  %4zu   (%zu loops)\n", counted, loops_counted);
  std::printf("\ntimes (wall clock): detections %.3f s, proofs %.3f s, total %.3f s\n", t_detect, t_prove,
              t_detect + t_prove);
  if (study > 0) {
    const loops_study::Totals s = loops_study::Study(tplane, v, truth, velocity, study >= 2).run();
    std::printf("\nstudy: %zu true crossings in complete detections, %zu proven, %zu left:", s.in_complete, s.proven,
                s.in_complete - s.proven);
    for (std::size_t r = 0; r < s.by_reason.size(); ++r) {
      std::printf("%s %zu %s", r ? "," : "", s.by_reason[r], loops_study::kReasonNames[r]);
    }
    std::printf("\n");
  }

  // ---- figures ----
  std::vector<std::pair<std::string, std::string>> figures;
  char title[200];
  std::snprintf(title, sizeof title, "t-plane: %zu detections, %zu proven (orange), %zu unproven (black)", nb_det,
                tplane.nb_proofs(), nb_complete - tplane.nb_proofs());
  tplane_figure(tplane, &truth, title).save((out / "loops_survey_tplane.svg").string());
  figures.emplace_back("loops_survey_tplane.svg",
                       "t-plane of the survey (Fig. 6.13): detections proven by the degree test in orange, unproven in "
                       "black, partial in grey; true crossings in blue");
  // A zoom (Fig. 6.17) on the first unproven complete detection, else on the
  // largest complete one, with its neighbours.
  const Loop* focus = nullptr;
  for (const Loop& l : tplane.detections()) {
    if (!l.complete()) continue;
    if (!l.proven()) {
      focus = &l;
      break;
    }
    if (!focus || l.boxes().size() > focus->boxes().size()) focus = &l;
  }
  if (focus) {
    const IntervalVector& h = focus->t_box();
    const double w = std::max(10 * eps, 2.5 * std::max(h[0].diam(), h[1].diam()));
    auto around = [&](const Interval& x) {
      const double lo = std::max(0.0, x.mid() - w), hi = std::min(tf, lo + 2 * w);
      return Interval(std::max(0.0, hi - 2 * w), hi);
    };
    const IntervalVector zoom{around(h[0]), around(h[1])};
    tplane_figure(tplane, &truth,
                  focus->proven() ? "t-plane, zoom on the largest detection"
                                  : "t-plane, zoom on an "
                                    "unproven detection",
                  &zoom, 500)
        .save((out / "loops_survey_tplane_zoom.svg").string());
    figures.emplace_back("loops_survey_tplane_zoom.svg",
                         "Zoom on one detection (Fig. 6.17): inner (green) and boundary (yellow) leaves, the outline "
                         "of the component, the true crossing(s)");
  }
  std::vector<Vector> path;
  looping_mission::Mission::Samples samples;
  if (lissajous) {
    for (double t = 0; t <= tf; t += 0.5) {
      const auto q = curve->position(t);
      samples.t.push_back(t), samples.x.push_back(q[0]), samples.y.push_back(q[1]);
    }
  } else {
    samples = mission->true_path(0.5);
  }
  for (std::size_t k = 0; k < samples.t.size(); ++k) path.push_back({samples.x[k], samples.y[k]});
  const Tube p1 = primitive(v[0]), p2 = primitive(v[1]);
  const TubeVector positions({p1, p2});
  std::snprintf(title, sizeof title, "Map: %zu loops proven (orange), %zu unproven (black)", tplane.nb_proofs(),
                nb_complete - tplane.nb_proofs());
  // As the thesis draws it: the true path over [t1] and [t2] of each detection.
  LoopsMapOptions projections;
  projections.boxes = false;
  loops_map_figure(tplane, &path, &samples.t, &positions, &truth, title, 700, projections)
      .save((out / "loops_survey_map.svg").string());
  figures.emplace_back("loops_survey_map.svg",
                       "Map (Fig. 6.12): dead-reckoned position tube, true path, detections "
                       "projected on the path over [t1] and [t2], true crossings in red");
  // The guaranteed projections: map boxes, hulls of p([t1]) and p([t2]).
  LoopsMapOptions boxes;
  boxes.projections = false;
  loops_map_figure(tplane, &path, nullptr, nullptr, &truth, title, 700, boxes)
      .save((out / "loops_survey_map_boxes.svg").string());
  figures.emplace_back("loops_survey_map_boxes.svg",
                       "Map with the map boxes of the detections (hulls of the "
                       "dead-reckoned positions over [t1] and [t2])");

  const bool ok = outside == 0 && bad_proofs == 0 && bad_counts == 0 && bad_degrees == 0 && misses == 0;
  char result[300];
  std::snprintf(result, sizeof result,
                "%.0f h: lambda_N=%zu lambda_T=%zu lambda*=%zu, %zu detections (%zu complete), %.1f%% of lambda* "
                "proven, %.2f s",
                hours, tplane.nb_newton_proofs(), tplane.nb_proofs(), lambda_star, nb_det, nb_complete, ratio,
                t_detect + t_prove);
  std::printf("\n%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
  example::print_result("loops_survey", result, ok, figures);
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }
