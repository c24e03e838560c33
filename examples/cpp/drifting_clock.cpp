// Reliable correction of a drifting clock (thesis 5.3.2): an underwater beacon
// at (0, 0, -10) reads its own clock τ = h(t) (truth 0.045t² + 0.98t, (5.23),
// unknown to the solver), with h(0) = 0 and ḣ ∈ [0.08, 0.12]t + [0.97, 1.08]
// (5.24). A boat follows the ephemeris (5.25)-(5.26) and 8 ranges [z_i] are
// stamped with the beacon's clock τ_i (Table 5.3).
//
// The network is CN (5.27): x' = v (CtcDeriv), y = sqrt(x1² + x2² + 10²) and
// w = (x1 v1 + x2 v2) / y pointwise, y' = w and h' = φ (CtcDeriv), and two
// CtcEval per measurement sharing the unknown time t_i: z_i = y(t_i) and
// τ_i = h(t_i). The [t_i] start as the whole domain: the first τ_i = h(t_i)
// gives [h]⁻¹(τ_i), the ranges contract them, and [h] follows.
//
// The time domain [0, 13] holds every t_i: at t = 13 the lowest admissible
// clock, 0.04t² + 0.97t, already exceeds the last τ_i = 18.24.
//
// Truth: h(t) = 0.045t² + 0.98t and the boat at (90, 20) + 100 (cos t, sin t)
// (the ephemeris centre is (80, 20); (90, 20) reproduces Table 5.3 to 0.01);
// both must stay inside their tubes and the true t_i = h⁻¹(τ_i) inside [t_i].
#include <array>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

#include "drifting_clock_network.h"
#include "example_args.h"
#include "example_bound.h"
#include "example_check.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/figures/tube_figure.h"

using namespace sillage;
using namespace drifting_clock;

namespace {


double true_time(double tau) { return (-0.98 + std::sqrt(0.98 * 0.98 + 4 * 0.045 * tau)) / (2 * 0.045); }

std::string iv(const Interval& a, int digits = 4) {
  char buf[80];
  std::snprintf(buf, sizeof buf, "[%.*f, %.*f]", digits, a.lb(), digits, a.ub());
  return buf;
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const double dt = example::option_number(argc, argv, "--dt", 0.01);
  const double ratio = example::option_number(argc, argv, "--ratio", 0.0);
  const auto td = TDomain::create(0.0, kTf, dt);

  // The a priori [h] (h(0) = 0 and ḣ ∈ [φ] only) and its inverses, for comparison.
  Tube h0(td), phi0(td, kPhi);
  h0.set_gate(0, Interval(0.0));
  CtcDeriv().contract(h0, phi0);

  const double c0 = static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
  Problem p = build(td, ratio);
  p.h->set_gate(0, example::bound(Interval(0.0)));  // h(0) = 0, tightened as in drifting_clock.py
  const ContractStats s = p.cn->contract();
  const double cpu = static_cast<double>(std::clock()) / CLOCKS_PER_SEC - c0;

  std::printf("Drifting clock (thesis 5.3.2), t in [0, %g], dt = %g (%zu slices)\n", kTf, dt, td->nb_slices());
  std::printf("  network: %zu contractors, ratio %g\n", p.cn->nb_ctc(), ratio);
  std::printf("  %zu iterations, %zu contractor calls, %.4f s wall, %.4f s CPU (build + contract), empty = %d\n",
              s.iterations, s.contractor_calls, s.time, cpu, s.empty);
  std::printf("  thesis: 5 steps in less than 2 s; reference library: 0.8 s\n");
  if (s.empty) return example::empty_exit("drifting_clock", s);

  // Fixed point: one more contract() runs every contractor once and must change nothing.
  const Tube h_fp = *p.h;
  const ContractStats again = p.cn->contract();
  const bool fixed = again.iterations == 1 && *p.h == h_fp;
  std::printf("  fixed point verified (a second contract() changes nothing): %s\n", fixed ? "yes" : "NO");

  const Trajectory h_true(kH, td->t0_tf());
  bool ok = example::enclosure_ok(*p.h) && (fixed || ratio > 0) &&
            p.h->contains(h_true);  // a ratio > 0 stops earlier
  const Trajectory b1("90 + 100*cos(t)", td->t0_tf()), b2("20 + 100*sin(t)", td->t0_tf());
  const Trajectory y_true("sqrt((90 + 100*cos(t))^2 + (20 + 100*sin(t))^2 + 100)", td->t0_tf());
  const bool boat_in = p.x->contains({b1, b2}) && p.y->contains(y_true);
  ok = ok && boat_in;
  std::printf("  i  tau_i  a priori [h]^-1(tau_i)  contracted [t_i]       true t_i  contracted [z_i]\n");
  double width0 = 0, width1 = 0;
  for (std::size_t i = 0; i < kTau.size(); ++i) {
    const Interval a = h0.inverse(cents(Interval(kTau[i])), phi0);
    const double tt = true_time(kTau[i]);
    const bool in = p.t[i]->contains(tt);
    ok = ok && in;
    width0 += a.diam() / kTau.size();
    width1 += p.t[i]->diam() / kTau.size();
    std::printf("  %zu  %5.2f  %s      %s  %.4f %s  %s\n", i + 1, kTau[i], iv(a).c_str(), iv(*p.t[i]).c_str(), tt,
                in ? "in " : "OUT", iv(*p.z[i], 2).c_str());
  }
  std::printf("  mean width of [t_i]: %.4f a priori -> %.4f contracted\n", width0, width1);
  std::printf("  [h](13): a priori %s -> %s; max thickness of [h]: %.4f -> %.4f\n",
              iv(h0.gate(td->nb_slices())).c_str(), iv(p.h->gate(td->nb_slices())).c_str(), h0.max_thickness(),
              p.h->max_thickness());
  std::printf("  truth h(t) inside [h]: %s; true boat inside [x] and [y]: %s\n", p.h->contains(h_true) ? "yes" : "NO",
              boat_in ? "yes" : "NO");

  // Fig. 5.13: [h] with the a priori tube, the truth and the (τ_i, [t_i]) boxes.
  TubeStyle grey;
  grey.slices = {"#e6e6e6", "#bdbdbd", 0.3, 1.0, "slice"};
  Figure fh = tube_figure(h0, "Clock drift [h](t), truth in red (Fig. 5.13)", grey, nullptr, 700, 350);
  fh.set_labels("t", "tau = h(t)");
  draw_tube(fh, *p.h, {}, &h_true);
  for (std::size_t i = 0; i < kTau.size(); ++i) {
    fh.draw_box(IntervalVector{h0.inverse(cents(Interval(kTau[i])), phi0), Interval(kTau[i]).inflate(0.15)},
                {"#4a90d9", "#2a5f9e", 0.6, 0.5, ""});
    fh.draw_box(IntervalVector{*p.t[i], Interval(kTau[i]).inflate(0.15)}, {"#d62728", "#8b0000", 0.6, 0.9, ""});
  }
  fh.save((out / "drifting_clock_h.svg").string());

  // Fig. 5.12: [y] with the measurement boxes, a priori (blue) and contracted (red).
  Figure fy = tube_figure(*p.y, "Boat-beacon distance [y](t) and the measurements (Fig. 5.12)", {}, &y_true, 700, 350);
  fy.set_labels("t", "y(t)");
  for (std::size_t i = 0; i < kTau.size(); ++i) {
    fy.draw_box(IntervalVector{h0.inverse(cents(Interval(kTau[i])), phi0), cents(kZ[i])},
                {"#4a90d9", "#2a5f9e", 0.6, 0.35, ""});
    fy.draw_box(IntervalVector{*p.t[i], *p.z[i]}, {"#d62728", "#8b0000", 0.6, 0.9, ""});
  }
  fy.save((out / "drifting_clock_y.svg").string());

  // Fig. 5.11: the ephemeris tube seen from above, the beacon at the origin.
  Figure fx = tube_vector_figure(*p.x, 0, 1, "Ephemeris [x](t) around the beacon (Fig. 5.11)", {}, &b1, &b2, 500);
  fx.draw_box(IntervalVector{{-3, 3}, {-3, 3}}, {"#d62728", "black", 1, 1, ""});
  fx.save((out / "drifting_clock_x.svg").string());

  std::string summary = std::to_string(s.iterations) + " iterations; [t_i] =";
  for (const auto& t : p.t) {
    summary += ' ';
    summary += iv(*t, 3);
  }
  example::print_result("drifting_clock", summary, ok,
                        {{"drifting_clock_h.svg", "Drifting clock (5.3.2): [h] with the truth (Fig. 5.13)"},
                         {"drifting_clock_y.svg", "Distances [y] and measurements (Fig. 5.12)"},
                         {"drifting_clock_x.svg", "Ephemeris of the boat (Fig. 5.11)"}});
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }
