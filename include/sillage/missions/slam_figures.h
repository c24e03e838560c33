#pragma once
// SVG figures of a temporal SLAM run (thesis 7.3.2):
//  - the thickness graph (Fig. 7.17): the diagonal of [p1] x [p2] per slice
//    for several tubes (dead reckoning, fast, accurate) on one time axis;
//  - the mission map (Fig. 7.16): the dead-reckoning tube, the SLAM tube, the
//    truth and the successive boxes [p](t_f), one per iteration.
#include <string>
#include <vector>

#include "sillage/figures/figure.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/missions/bathymetry_mission.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// One curve of the thickness graph: the tube (its components 0 and 1), a
// legend and an SVG colour.
struct ThicknessCurve {
  // The tube (components 0 and 1 measured).
  TubeVector p;
  // The legend.
  std::string label;
  // The SVG colour.
  std::string colour;
};

// Every curve on a shared TDomain (DimensionError otherwise), a step curve
// each (per pixel column: the max of the slices it covers), with a legend.
Figure slam_thickness_figure(const std::vector<ThicknessCurve>& curves,
                             const std::string& title = "Thickness of [p](t): diagonal of [p1] x [p2]",
                             double width_px = 700, double height_px = 300);

// Dead reckoning (grey), SLAM (blue), truth (dark line), the boxes [p](t_f)
// of `tf_boxes` (2-D; the first is dead reckoning's) in red, thinner when
// later.
Figure slam_map_figure(const BathymetryMission& m, const TubeVector& dead_reckoning, const TubeVector& slam,
                       const std::vector<IntervalVector>& tf_boxes,
                       const std::string& title = "Temporal SLAM: dead reckoning, SLAM, truth, [p](t_f)",
                       double width_px = 600);

}  // namespace sillage
