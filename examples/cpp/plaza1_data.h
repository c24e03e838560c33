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

#include "example_args.h"
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
  if (ot.size() + 1 != d.t.size()) throw sillage::Error("plaza1: expected one odometry row per ground-truth step");
  for (std::size_t k = 0; k < ot.size(); ++k) {
    if (ot[k] != d.t[k + 1]) {
      throw sillage::Error("plaza1: odometry row " + std::to_string(k) + " does not end at t_{k+1}");
    }
  }
  d.rt = rg.values("t_s"), d.rid = rg.values("beacon_id"), d.r = rg.values("range_m");
  const auto ids = bc.values("beacon_id"), bx = bc.values("x_m"), by = bc.values("y_m");
  for (std::size_t i = 0; i < ids.size(); ++i) d.beacons[static_cast<int>(ids[i])] = {bx[i], by[i]};
  return d;
}

// The data of --data DIR (by default the shared data folder known at build
// time), or nullopt when the folder holds none: the example `name` then says
// so and reports itself skipped.
inline std::optional<Plaza1Data> plaza1_from_args(int argc, char** argv, const std::string& name) {
  const std::filesystem::path dir =
      option_value(argc, argv, "--data", (std::filesystem::path(SILLAGE_SHARED_DIR) / "data" / "plaza1").string());
  if (!std::filesystem::exists(dir / "odometry.csv")) {
    std::printf("no plaza1 data at %s (pass --data DIR)\n", dir.string().c_str());
    print_result(name, "skipped: no data", true);
    return std::nullopt;
  }
  return load_plaza1(dir);
}

}  // namespace example
