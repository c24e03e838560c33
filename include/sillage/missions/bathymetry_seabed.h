#pragma once
// A synthetic seabed like the Rade de Brest survey area (thesis Fig. 7.20),
// deterministic from a seed: a regional slope, sandbanks, sand waves, a few
// rocks and a smoother western part where the bathymetry carries little
// information (the weakness of the 19 October mission, thesis 7.3.4), and on
// request channel flanks (steep monotone steps of 10-20 m), sampled
// on a grid (BathymetryDem) with a small node roughness, quantized to the
// millimetre as a surveyed DEM would be.
//
// Its class (SeabedClass) is stated from the generator's parameters, not
// measured on the result: the smooth part g of the seabed (everything but the
// node roughness) has |Hessian| <= curvature and |grad g| <= slope everywhere,
// and every node is g + n with |n| <= roughness. Those bounds are what the
// altitude footprint filter and the observation tube rely on.
#include <cstdint>
#include <string>
#include <vector>

#include "sillage/interval/interval_vector.h"
#include "sillage/missions/bathymetry_dem.h"

namespace sillage {

// A channel flank: the seabed deepens by height (m) across the smooth step
// height (1 + tanh(s / width)) / 2, s the signed distance (m) along direction
// (deg, counter-clockwise from east: downslope) from the line through (x, y).
// About 80 % of the drop lies within 1.1 width of that line; its steepest
// slope is |height| / (2 width) and its curvature at most 0.385 |height| / width^2.
struct ChannelBank {
  double height = 15;    // m (negative: the seabed rises)
  double width = 30;     // m
  double direction = 0;  // deg
  double x = 250;        // m, a point of the mid-line
  double y = 250;        // m
};

// Options of generate_seabed (area, grid, depth, smooth strip, counts).
struct SeabedOptions {
  double size = 500;          // side of the square area (m), from (0, 0)
  double cell = 1;            // grid step (m)
  double base_depth = 21;     // depth at the origin (m, below chart datum)
  double smooth_width = 170;  // width of the smooth western strip (m)
  // Number of rocks.
  int nb_rocks = 7;
  // Number of sandbanks.
  int nb_banks = 2;
  double relief = 1;          // factor on every relief amplitude (slope, banks, rocks, waves, swell, flanks)
  double rock_height_min = 0.8;  // m, rocks (they stand at least 8 rock_sigma_max apart)
  double rock_height_max = 1.5;  // m
  double rock_sigma_min = 8;     // m, Gaussian sigma of a rock
  double rock_sigma_max = 12;    // m
  // A field of sand waves at the scale of a drift window (0: none): three
  // trains of wavelengths 10-16, 18-26 and 28-40 m in random directions, whose
  // amplitudes sum to dune_height (m, crest above the mean level), in the rough part.
  double dune_height = 0;
  // Channel flanks (none by default): steep, smooth, monotone steps of the seabed.
  std::vector<ChannelBank> channel_banks;
};

// A coastal seabed with information at the scale of the drift (tens of
// metres): a sand-wave field of 10-40 m wavelengths about 1 m high and rocky
// outcrops 1.5-3 m high every ~70 m in the east, the smooth western strip
// kept. The default SeabedOptions are the smoother seabed.
SeabedOptions coastal_seabed_options();

// The bank seabed: the smoother seabed of the defaults and two flanks of a
// channel that bends around the north-west of the area, under the transects
// and the last rails of bank_mission_options: one drops 15 m to the west
// across x = 110 m (width 30 m: slope up to 25 %), the other 12 m to the
// north across y = 350 m (width 24 m: 25 %). A crossing on a flank pins the
// position's component along its gradient; both gradients lie along the axes,
// the only components a box holds.
SeabedOptions bank_seabed_options();

// Stated bounds of a generated seabed: curvature (Hessian norm), slope, node roughness.
struct SeabedClass {
  double curvature;  // bound on the Hessian norm of the smooth seabed (1/m)
  double slope;      // bound on its gradient norm
  double roughness;  // bound on the node roughness (m), quantization included
};

// A generated seabed: its DEM, its stated class and its smooth strip.
struct Seabed {
  // The BathymetryDem.
  BathymetryDem dem;
  // The SeabedClass.
  SeabedClass bounds;
  IntervalVector smooth_region;  // the low-information strip
};

// Error if the options are not finite and positive where they must be, or the
// grid would not be exact (see BathymetryDem).
Seabed generate_seabed(std::uint64_t seed, const SeabedOptions& options = {});

std::string repr(const SeabedClass& c);

}  // namespace sillage
