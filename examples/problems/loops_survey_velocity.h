#pragma once
// The velocity table of the synthetic survey of examples/cpp/loops_survey.cpp
// (examples/cpp/looping_mission.h, default parameters: one hour, e = 0.01 m/s,
// seed 2017) as two CSV files for examples/problems/loops_survey.toml:
// loops_survey_times.csv, the time points t_k (one row each), and
// loops_survey_velocity.csv, one row per slice [t_k, t_k+1] with the bounds
// of the velocity tube's slice per axis. Shared by the generator
// (loops_survey_velocity.cpp, run at build time into the build folder: the
// tables are not committed) and the test that compares the file with the
// example.
#include <cstdio>
#include <string>

#include "../cpp/looping_mission.h"

namespace loops_survey {

// Writes both tables of `mission` into dir; false if one cannot be written.
inline bool write_velocity_csv(const looping_mission::Mission& mission, const std::string& dir) {
  const sillage::TubeVector& v = mission.velocity_tube();
  const sillage::TDomain& td = *mission.tdomain();
  std::FILE* times = std::fopen((dir + "/loops_survey_times.csv").c_str(), "w");
  std::FILE* slices = std::fopen((dir + "/loops_survey_velocity.csv").c_str(), "w");
  bool ok = times && slices;
  if (ok) {
    // %.17g: every double reads back exactly.
    std::fprintf(times, "t\n");
    for (std::size_t k = 0; k <= td.nb_slices(); ++k) std::fprintf(times, "%.17g\n", td.t(k));
    std::fprintf(slices, "vx_lb,vx_ub,vy_lb,vy_ub\n");
    for (std::size_t k = 0; k < td.nb_slices(); ++k) {
      const sillage::IntervalVector s = v.slice(k);
      std::fprintf(slices, "%.17g,%.17g,%.17g,%.17g\n", s[0].lb(), s[0].ub(), s[1].lb(), s[1].ub());
    }
  }
  for (std::FILE* f : {times, slices})
    if (f && std::fclose(f) != 0) ok = false;
  return ok;
}

}  // namespace loops_survey
