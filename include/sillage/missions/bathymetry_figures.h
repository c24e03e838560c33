#pragma once
// SVG figures of the synthetic bathymetric mission:
//  - the DEM with the path (thesis Fig. 7.20): the depth as colour over blocks
//    of `block` metres (each block coloured by the mean of its nodes), the
//    low-information strip outlined, the path drawn in white;
//  - the mission map (Fig. 7.16): the dead-reckoning tube [p1] x [p2], the
//    truth and the final box [p](t_f) (see tube_vector_figure);
//  - the observation tube (Fig. 7.14) with the true observation.
// The thickness graph (Fig. 7.17) is thickness_figure(p.subvector(0, 1), Diagonal).
#include <string>
#include <vector>

#include "sillage/figures/figure.h"
#include "sillage/missions/bathymetry_mission.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// The colour of a depth within [lo, hi]: light (shallow) to dark blue (deep).
std::string depth_colour(double depth, double lo, double hi);

// The DEM coloured by depth with the path (x, y) (Fig. 7.20), an SVG Figure.
Figure bathymetry_dem_figure(const BathymetryDem& dem, const std::vector<double>& x, const std::vector<double>& y,
                             const std::string& title = "Seabed DEM and path", double block = 5,
                             double width_px = 600);
// The mission map: tube [p1] x [p2] and the truth (Fig. 7.16), an SVG Figure.
Figure bathymetry_map_figure(const BathymetryMission& m, const TubeVector& p,
                             const std::string& title = "Mission map: dead reckoning and truth", double width_px = 600);
// The observation tube with the true observation (Fig. 7.14), an SVG Figure.
Figure bathymetry_observation_figure(const BathymetryMission& m, const Tube& z,
                                     const std::string& title = "Observation tube [z](t) and truth",
                                     double width_px = 700);

}  // namespace sillage
