#pragma once
// One row of thesis Table 7.2 / 7.3: what one iteration of C_{p⇒z} (or of
// the temporal SLAM) did.
#include <cstddef>
#include <string>

namespace sillage {

struct SlamRow {
  std::size_t iteration = 0;      // 1, 2, ... (over fast then accurate iterations)
  bool fast = false;              // Alg. 14 (true) or Alg. 13 (false)
  std::size_t nb_detections = 0;  // complete detections Ω_i of 𝕋_p
  std::size_t nb_proofs = 0;      // of which proven to hold a loop (degree test)
  double seconds = 0.0;           // of this iteration (wall clock)
  // Time since the first iteration.
  double cumulated_seconds = 0.0;
  // 1 - width([p](t)) / width of the input [p](t) (summed over components;
  // 0: nothing gained, 1: down to a point), at t_f and at t_0.
  double contraction_tf = 0.0;
  // The same at t_0.
  double contraction_t0 = 0.0;
  std::size_t nb_atoms_touched = 0;  // gates and slices C_Ω worked on (its cost)
};

// "SlamRow(iteration=1, fast=True, ...)".
std::string to_string(const SlamRow& r);

}  // namespace sillage
