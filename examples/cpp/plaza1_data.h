#pragma once
// The CMU Plaza 1 data (../shared/data/plaza1, read in place; README there):
// an INS/GPS ground truth and one odometry increment per ground-truth step,
// plus the radio ranges to 4 beacons. Shared by the plaza1 examples.
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "example_data.h"
#include "sillage/error.h"
#include "sillage/io/csv.h"

namespace example {

struct Plaza1Data {
  std::vector<double> t, x, y, heading;  // ground truth at the time points (heading wrapped to (-pi, pi])
  // Odometry increment k covers [t_k, t_{k+1}]: a distance and two heading
  // changes: dpsi_ins equals the ground-truth increments (an INS-quality
  // heading), dpsi_drift drifts like a real gyro (column delta_heading_drp_rad).
  std::vector<double> dist, dpsi_ins, dpsi_drift;
  std::vector<double> rt, rid, r;  // ranges: time, beacon id, measured range
  std::map<int, std::pair<double, double>> beacons;
};

inline Plaza1Data load_plaza1(const std::filesystem::path& dir) {
  using sillage::CsvTable;
  Plaza1Data d;
  const CsvTable gt = CsvTable::read((dir / "ground_truth.csv").string());
  const CsvTable odo = CsvTable::read((dir / "odometry.csv").string());
  const CsvTable rg = CsvTable::read((dir / "ranges.csv").string());
  const CsvTable bc = CsvTable::read((dir / "beacons.csv").string());
  d.t = gt.values("t_s"), d.x = gt.values("x_m"), d.y = gt.values("y_m"), d.heading = gt.values("heading_rad");
  d.dist = odo.values("delta_dist_m");
  d.dpsi_ins = odo.values("delta_heading_rad"), d.dpsi_drift = odo.values("delta_heading_drp_rad");
  const std::vector<double> ot = odo.values("t_s");
  if (ot.size() + 1 != d.t.size() || ot.empty()) {
    throw sillage::Error(odo.source() + ": " + std::to_string(ot.size()) + " rows, expected one per step of " +
                         gt.source() + " (" + std::to_string(d.t.size()) + " rows, at least 2)");
  }
  for (std::size_t k = 0; k < ot.size(); ++k) {
    if (ot[k] != d.t[k + 1]) {
      throw sillage::Error(odo.where(k) + ": t_s = " + sillage::number_text(ot[k]) + ", expected the end of its step, " +
                           sillage::number_text(d.t[k + 1]) + " (" + gt.where(k + 1) + ")");
    }
  }
  d.rt = rg.values("t_s"), d.rid = rg.values("beacon_id"), d.r = rg.values("range_m");
  const auto ids = bc.values("beacon_id"), bx = bc.values("x_m"), by = bc.values("y_m");
  for (std::size_t i = 0; i < ids.size(); ++i) d.beacons[static_cast<int>(ids[i])] = {bx[i], by[i]};
  for (std::size_t j = 0; j < d.rid.size(); ++j) {
    if (d.rid[j] != static_cast<int>(d.rid[j]) || !d.beacons.count(static_cast<int>(d.rid[j]))) {
      throw sillage::Error(rg.where(j) + ": beacon " + sillage::number_text(d.rid[j]) + " is not in " + bc.source());
    }
  }
  return d;
}

// The data of --data DIR (by default the shared data folder known at build
// time; example_data.h), or nullopt when the example `name` is skipped.
inline std::optional<Plaza1Data> plaza1_from_args(int argc, char** argv, const std::string& name) {
  const auto dir = data_dir(argc, argv, name, "plaza1", {"ground_truth.csv", "odometry.csv", "ranges.csv", "beacons.csv"});
  if (!dir) return std::nullopt;
  return load_plaza1(*dir);
}

// The benchmarks' copy of the data in dir, read on first use; nullopt if the
// folder holds none (one folder per process).
inline const std::optional<Plaza1Data>& plaza1_once(const std::filesystem::path& dir) {
  static const std::optional<Plaza1Data> d =
      std::filesystem::exists(dir / "odometry.csv") ? std::optional(load_plaza1(dir)) : std::nullopt;
  return d;
}

}  // namespace example
