#pragma once
// Tiny shared helpers of the C++ examples: `--name value` options, the --out
// folder and the RESULT line that examples/run_demo.py reads.
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace example {

// The value following `name` on the command line, or `fallback` if absent.
inline std::string option_value(int argc, char** argv, const std::string& name, const std::string& fallback) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::string(argv[i]) == name) return argv[i + 1];
  }
  return fallback;
}

// A numeric option; text that is not a number reads as 0 (examples check their ranges).
inline double option_number(int argc, char** argv, const std::string& name, double fallback) {
  const std::string v = option_value(argc, argv, name, "");
  return v.empty() ? fallback : std::atof(v.c_str());
}

inline std::filesystem::path out_dir(int argc, char** argv) {
  const std::filesystem::path out = option_value(argc, argv, "--out", "out");
  std::filesystem::create_directories(out);
  return out;
}

inline std::string json_escape(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '"' || c == '\\') r += '\\';
    r += c;
  }
  return r;
}

// Prints the machine-readable summary line of an example.
inline void print_result(const std::string& name, const std::string& result, bool check,
                         const std::vector<std::pair<std::string, std::string>>& figures = {}) {
  std::cout << "RESULT {\"name\": \"" << json_escape(name) << "\", \"result\": \"" << json_escape(result)
            << "\", \"check\": " << (check ? "true" : "false") << ", \"figures\": [";
  for (std::size_t i = 0; i < figures.size(); ++i) {
    std::cout << (i ? ", " : "") << "[\"" << json_escape(figures[i].first) << "\", \""
              << json_escape(figures[i].second) << "\"]";
  }
  std::cout << "]}" << std::endl;
}

}  // namespace example
