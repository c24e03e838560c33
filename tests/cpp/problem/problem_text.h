#pragma once
// Helpers of the problem tests: the example problems' directory, a problem
// text parsed under a name in that directory (so data paths resolve), the
// message of the error it gives.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "sillage/problem/load_problem.h"
#include "sillage/problem/solve_problem.h"

namespace problem_test {

inline std::string problems_dir() { return std::string(SILLAGE_SOURCE_DIR) + "/examples/problems"; }

inline std::string read_file(const std::string& path) {
  std::ifstream is(path, std::ios::binary);
  std::ostringstream ss;
  ss << is.rdbuf();
  return ss.str();
}

inline sillage::Problem parse(const std::string& text) {
  return sillage::parse_problem(text, problems_dir() + "/test.toml");
}

// The problem `text` (parsed as by parse()) solved with its own options.
inline sillage::SolveResult solve_text(const std::string& text) { return sillage::solve_problem(parse(text)); }

// The message of the ProblemError that parsing `text` throws ("" if none).
inline std::string error_of(const std::string& text) {
  try {
    (void)parse(text);
  } catch (const sillage::ProblemError& e) {
    return e.what();
  }
  return "";
}

// Parsing `text` fails with a message that contains `part`.
inline void expect_error(const std::string& text, const std::string& part) {
  const std::string msg = error_of(text);
  EXPECT_NE(msg.find(part), std::string::npos) << msg;
}

}  // namespace problem_test
