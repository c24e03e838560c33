#pragma once
// Command-line options of the C++ examples beyond --out: `--name value` pairs.
#include <string>

namespace example {

// The value following `name` on the command line, or `fallback` if absent.
inline std::string option_value(int argc, char** argv, const std::string& name, const std::string& fallback) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::string(argv[i]) == name) return argv[i + 1];
  }
  return fallback;
}

}  // namespace example
