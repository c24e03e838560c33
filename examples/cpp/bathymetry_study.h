#pragma once
// What limits the bathymetric temporal SLAM, measured per proven detection on
// the dead-reckoning tube (the first iteration of C_p=>z): the width of the
// component Omega_i in t1 and t2, the fraction of its area the observation
// removes (Omega_i minus T_z), the t1- and t2-widths of the hull of what is
// left (what the fast algorithm contracts with), and the seabed's true depth
// variation over the t1 window against the mean gate width of [z] there.
// Contraction needs T_z to keep a short piece of the t1 or of the t2 window:
// the seabed must vary along one of the passes by several gate widths of [z].
#include <algorithm>
#include <cstdio>
#include <vector>

#include "sillage/loops/tplane.h"
#include "sillage/paving/sivia.h"
#include "sillage/missions/bathymetry_mission.h"
#include "sillage/missions/bathymetry_tubes.h"

namespace example {

inline double box_area(const sillage::IntervalVector& b) { return b[0].diam() * b[1].diam(); }

// Prints one line per proven detection and a summary; returns the mean
// fraction of Omega removed by T_z.
inline double bathymetry_study(const sillage::BathymetryMission& m, const sillage::TubeVector& p,
                               const sillage::TubeVector& w, const sillage::Tube& z, double eps) {
  using namespace sillage;
  TPlane tp(p.tdomain());
  tp.compute_detections(eps, p, w);
  ProofOptions po;
  po.newton = false;
  po.count = false;
  tp.compute_proofs(p, w, po);
  const Trajectory zt = bathymetry_truth_observation(m);
  const Interval dom = z.tdomain()->t0_tf();
  const KernelBounds fz = [&](const IntervalVector& t) {
    const Interval d = z(t[0] & dom) - z(t[1] & dom);
    return std::make_pair(IntervalVector{d}, IntervalVector{d});
  };
  const auto depth_range = [&](const Interval& t) {  // true seabed depth range over a window
    Interval r = Interval::empty();
    for (double s = t.lb(); s <= t.ub(); s += m.options().step) r |= Interval(zt(s));
    return r.diam();
  };
  const auto mean_gate = [&](const Interval& t) {
    const auto td = z.tdomain();
    double s = 0;
    std::size_t n = 0;
    for (std::size_t k = td->slice_index(t.lb()); k <= td->slice_index(t.ub()); ++k, ++n) s += z.gate(k).diam();
    return n ? s / static_cast<double>(n) : 0.0;
  };
  std::printf("  study: %zu detections, %zu proofs\n", tp.nb_complete_detections(), tp.nb_proofs());
  std::printf("  %8s %8s %7s %7s %9s %7s %7s %9s %9s\n", "t1 mid", "t2 mid", "w t1", "w t2", "removed", "b t1",
              "b t2", "dz t1 win", "gate z");
  double removed_sum = 0, ratio1 = 0, ratio2 = 0;
  std::size_t n = 0;
  SiviaOptions so;
  so.parallel = false;
  for (const Loop& l : tp.detections()) {
    if (!l.proven()) continue;
    IntervalVector hull(2, Interval::empty()), kept(2, Interval::empty());
    double area = 0, kept_area = 0;
    for (const IntervalVector& b : l.boxes()) {
      hull |= b;
      area += box_area(b);
      for (const IntervalVector& k : kernel_sivia(b, fz, eps, so).outer()) kept |= k, kept_area += box_area(k);
    }
    const double removed = area > 0 ? 1 - kept_area / area : 0;
    const double b1 = kept.is_empty() ? 0.0 : kept[0].diam(), b2 = kept.is_empty() ? 0.0 : kept[1].diam();
    removed_sum += removed, ++n;
    ratio1 += b1 / hull[0].diam(), ratio2 += b2 / hull[1].diam();
    std::printf("  %8.0f %8.0f %7.0f %7.0f %8.0f%% %7.0f %7.0f %9.2f %9.2f\n", hull[0].mid(), hull[1].mid(),
                hull[0].diam(), hull[1].diam(), 100 * removed, b1, b2, depth_range(hull[0]), mean_gate(hull[0]));
  }
  const double mean = n ? removed_sum / static_cast<double>(n) : 0, nn = n ? static_cast<double>(n) : 1;
  std::printf("  study: mean fraction of Omega removed by T_z %.0f%% over %zu proofs; hull of Omega and T_z over "
              "Omega, mean: %.2f in t1, %.2f in t2\n", 100 * mean, n, ratio1 / nn, ratio2 / nn);
  return mean;
}

}  // namespace example
