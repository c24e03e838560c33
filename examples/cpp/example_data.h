#pragma once
// The --data folder of the examples on real data (../shared/data, read in
// place). A folder named with --data must hold the data set: a missing
// folder or file is bad input (status 2, saying what is missing). Without
// --data the folder known at build time is read; when it is absent (a
// checkout without the data sets) the example says so and reports itself
// skipped, which examples/run_demo.py shows as such, never as ok.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "example_args.h"

namespace example {

// The folder of `dataset` holding `files` (paths inside it), or nullopt after
// the skipped RESULT line of the example `name` when the default folder is absent.
inline std::optional<std::filesystem::path> data_dir(int argc, char** argv, const std::string& name,
                                                     const std::string& dataset, const std::vector<std::string>& files) {
  namespace fs = std::filesystem;
  const std::string given = option_value(argc, argv, "--data", "");
  const fs::path dir = given.empty() ? fs::path(SILLAGE_SHARED_DIR) / "data" / dataset : fs::path(given);
  const std::string what = (given.empty() ? "the data folder " : "--data ") + dir.string();
  if (given.empty() && !fs::exists(dir)) {
    std::printf("no %s data at %s (pass --data DIR)\n", dataset.c_str(), dir.string().c_str());
    print_result(name, "skipped: no data", true);
    return std::nullopt;
  }
  if (!fs::is_directory(dir)) usage_error(name, what + ": no such folder (expected the " + dataset + " data set)");
  std::string missing;
  for (const std::string& f : files) {
    if (!fs::is_regular_file(dir / f)) missing += (missing.empty() ? "" : ", ") + f;
  }
  if (!missing.empty()) usage_error(name, what + ": not the " + dataset + " data set (missing " + missing + ")");
  return dir;
}

}  // namespace example
