#pragma once
// Thickness graph d(t) of a tube (thesis Fig. 3.12): for each slice a width
// of the slice codomain, drawn as a step curve over time.
#include <string>
#include <vector>

#include "sillage/figures/figure.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// How the thickness of a tube vector's slice is measured.
enum class ThicknessMeasure {
  MaxDiameter,  // max over components of the slice diameters
  Diagonal,     // sqrt(sum of squared diameters): the d of thesis Fig. 3.12
};

// One value per slice (0 for an empty slice, +inf for an unbounded one).
std::vector<double> thickness_values(const Tube& x);
// Per slice: the max diameter over the components, or the diagonal of the slice box (Diagonal).
std::vector<double> thickness_values(const TubeVector& x, ThicknessMeasure m = ThicknessMeasure::MaxDiameter);

// d(t) as a step curve (per pixel column: the max over the slices it covers,
// so the curve is an upper envelope). Infinite thicknesses are clipped to the
// top of the window and the title says so.
Figure thickness_figure(const Tube& x, const std::string& title = "Thickness d(t)", double width_px = 600,
                        double height_px = 250);
// The thickness d(t) of a tube vector (see thickness_values) as a step curve; axis 't (s)'.
Figure thickness_figure(const TubeVector& x, ThicknessMeasure m = ThicknessMeasure::MaxDiameter,
                        const std::string& title = "Thickness d(t)", double width_px = 600, double height_px = 250);

// The step curve of per-slice values over the time points of a TDomain
// (values.size() == nb_slices, DimensionError otherwise).
Figure step_figure(const TDomain& td, const std::vector<double>& values, const std::string& title, double width_px,
                   double height_px);

}  // namespace sillage
