#pragma once
// Figures of the loops_* examples: the t-plane with the true crossings, and
// the map with the true path, the crossings and the map boxes of the proven
// loops.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "loops_real_data.h"
#include "sillage/figures/loops_map_figure.h"
#include "sillage/figures/tplane_figure.h"

namespace example {

// Saves <stem>_tplane.svg and <stem>_map.svg into `out`, and lists them in
// `figures` (for the RESULT line). The map shows each proven loop as the
// true path over its [t1] and [t2], and as its map box when narrower than
// `max_box` metres (from v alone, a map box is dead reckoning from the start,
// relative to `origin`, the true position there: it widens without bound).
inline void save_loop_figures(const sillage::TPlane& tp, const Path& truth, const IntervalVector& origin,
                              const std::vector<sillage::PathCrossing>& crossings, const std::filesystem::path& out,
                              const std::string& stem, const std::string& title, double max_box,
                              std::vector<std::pair<std::string, std::string>>& figures) {
  sillage::tplane_figure(tp, &crossings, title + ": t-plane", nullptr, 700)
      .save((out / (stem + "_tplane.svg")).string());
  figures.push_back({stem + "_tplane.svg", title + ": t-plane and true crossings"});

  std::vector<sillage::MapLoop> loops;
  for (const sillage::Loop& l : tp.detections()) {
    if (!l.proven()) continue;
    const bool narrow = !l.map_box().is_empty() && l.map_box().max_diam() <= max_box;
    loops.push_back({narrow ? l.map_box() + origin : IntervalVector::empty(2), sillage::LoopStatus::Proven, l.t_box()});
  }
  std::vector<sillage::Vector> path;
  for (std::size_t i = 0; i < truth.t.size(); ++i) path.push_back(sillage::Vector{truth.x[i], truth.y[i]});
  // The title counts the proven loops: a run with none must not read as if it had some.
  const std::size_t n = loops.size();
  const std::string what = title + (n == 0   ? ": map, true path (no proven loop)"
                                    : n == 1 ? ": map, true path over [t1] and [t2] of the 1 proven loop"
                                             : ": map, true path over [t1] and [t2] of the " + std::to_string(n) +
                                                   " proven loops");
  sillage::loops_map_figure(loops, &path, &truth.t, nullptr, &crossings, what)
      .save((out / (stem + "_map.svg")).string());
  figures.push_back({stem + "_map.svg", what});
}

}  // namespace example
