#pragma once
// Tiny shared helpers of the C++ examples: the --out folder and the RESULT line
// that examples/run_demo.py reads.
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace example {

inline std::filesystem::path out_dir(int argc, char** argv) {
  std::filesystem::path out = "out";
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::string(argv[i]) == "--out") out = argv[i + 1];
  }
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
