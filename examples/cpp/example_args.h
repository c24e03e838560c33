#pragma once
// Tiny shared helpers of the C++ examples: their entry (run), `--name value`
// options, the --out folder and the RESULT line that examples/run_demo.py
// reads. --help (or -h) prints the usage line and exits 0. A bad command line (unknown option, missing value, text where a
// number is expected) prints the problem and a usage line and exits with
// status 2, as the Python examples' argparse does; so does bad data (run).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sillage/error.h"

// The bound options of the plaza1 examples (plaza1_bounds.h checks that its table matches).
#define PLAZA1_BOUND_OPTIONS "--start-x=X", "--start-y=X", "--start-heading=X", "--start-pos-err=X", "--start-heading-err=X", "--gyro-turn-on-bias=X", "--gyro-in-run-drift=X", "--turn-max=X", "--odo-scale=X", "--odo-over=X", "--odo-under=X", "--speed-max=X", "--range-short=X", "--range-long=X", "--time-jitter=X", "--track-err=X", "--turn-accel=X"

namespace example {

// The options of each example beyond --out, by program name (without the
// "example_" prefix of the binary): add an example's options here, or they
// are rejected as unknown. Options ending in "=X" take a number.
inline const std::vector<std::pair<std::string, std::vector<std::string>>>& program_options() {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> table = {
      {"drifting_clock", {"--dt=X", "--ratio=X"}},
      {"lowcost_beacons", {"--dt=X", "--ratio=X"}},
      {"plaza1", {"--data", "--unknown-start=X", "--start-heading-pieces=X", "--q-ranges=X", "--heading-window=X", PLAZA1_BOUND_OPTIONS}},
      {"plaza1_slam", {"--data", "--eps=X", "--heading-window=X", PLAZA1_BOUND_OPTIONS}},
      {"plaza1_online", {"--data", "--window=X", PLAZA1_BOUND_OPTIONS}},
      {"loops_plaza1", {"--data", "--eps-div=X", "--reverse-below=X", "--glitch-above=X", PLAZA1_BOUND_OPTIONS}},
      {"loops_survey", {"--hours=X", "--eps-divisor=X", "--e=X", "--seed=X", "--lissajous=X", "--study=X"}},
      {"loops_utias", {"--data", "--robot"}},
      {"outliers_ranges", {"--eps=X"}},
      {"bathymetry_mission", {"--seed=X", "--dt=X"}},
      {"bathymetry_slam", {"--seed=X", "--dt=X", "--eps=X", "--duration=X", "--scenario=X", "--relief=X", "--beam-angle=X", "--vehicle-depth=X", "--study=X", "--seabed=X", "--beam-spread=X", "--transects=X", "--dune-height=X", "--tie-lines=X"}},
  };
  return table;
}

inline std::string program_name(const char* argv0) {
  std::string name = std::filesystem::path(argv0 ? argv0 : "example").filename().string();
  if (name.rfind("example_", 0) == 0) name.erase(0, 8);
  return name;
}

// "--out" and the program's options.
inline std::vector<std::string> accepted_options(const std::string& program) {
  std::vector<std::string> r{"--out"};
  for (const auto& [name, options] : program_options()) {
    if (name == program) r.insert(r.end(), options.begin(), options.end());
  }
  return r;
}

// "usage: <program> [--out DIR] [--name X] ...".
inline void print_usage(std::ostream& os, const std::string& program) {
  os << "usage: " << program;
  for (const auto& o : accepted_options(program)) {
    const auto eq = o.find('=');
    const char* value = eq != std::string::npos ? " X" : o == "--out" ? " DIR" : " VALUE";
    os << " [" << o.substr(0, eq) << value << "]";
  }
  os << std::endl;
}

// Prints "<program>: <message>" and the usage line, and exits with status 2.
[[noreturn]] inline void usage_error(const std::string& program, const std::string& message) {
  std::cerr << program << ": " << message << "\n";
  print_usage(std::cerr, program);
  std::exit(2);
}

// The entry of every example: `int main(int argc, char** argv) { return
// example::run(argc, argv, example_main); }`. A sillage::Error that escapes
// the example is bad input (a data file with a missing column, no rows, a
// cell that is not a number: CsvTable names the file, line and column): its
// message on stderr and status 2, as for a bad command line, not an abort.
// An empty result is not an Error: the examples print it and exit 1.
inline int run(int argc, char** argv, int (*example_main)(int, char**)) {
  try {
    return example_main(argc, argv);
  } catch (const sillage::Error& e) {
    std::cout.flush();
    std::cerr << program_name(argc > 0 ? argv[0] : nullptr) << ": " << e.what() << std::endl;
    return 2;
  }
}

// A finite number written whole (no trailing text), else nullopt.
inline std::optional<double> parse_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(x)) return std::nullopt;
  return x;
}

// Checks the whole command line once: `--name value` pairs of known options
// only, numbers where numbers are expected; otherwise usage_error (exit 2).
inline void check_args(int argc, char** argv) {
  static bool checked = false;
  if (checked) return;
  checked = true;
  const std::string program = program_name(argc > 0 ? argv[0] : nullptr);
  const std::vector<std::string> accepted = accepted_options(program);
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {  // as the Python examples' argparse: the usage, status 0
      print_usage(std::cout, program);
      std::exit(0);
    }
    std::string spec;
    for (const auto& o : accepted) {
      if (o.substr(0, o.find('=')) == arg) spec = o;
    }
    if (spec.empty()) usage_error(program, "unknown option '" + arg + "'");
    if (i + 1 >= argc || std::string(argv[i + 1]).rfind("--", 0) == 0) {
      usage_error(program, "option " + arg + " needs a value");
    }
    const std::string value = argv[++i];
    if (spec.find('=') != std::string::npos && !parse_number(value)) {
      usage_error(program, "option " + arg + " expects a number, got '" + value + "'");
    }
  }
}

// The value following `name` on the command line, or `fallback` if absent.
inline std::string option_value(int argc, char** argv, const std::string& name, const std::string& fallback) {
  check_args(argc, argv);
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::string(argv[i]) == name) return argv[i + 1];
  }
  return fallback;
}

// A numeric option (check_args has made sure it is a number).
inline double option_number(int argc, char** argv, const std::string& name, double fallback) {
  const std::string v = option_value(argc, argv, name, "");
  return v.empty() ? fallback : *parse_number(v);
}

inline std::filesystem::path out_dir(int argc, char** argv) {
  const std::filesystem::path out = option_value(argc, argv, "--out", "out");
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) {
    usage_error(program_name(argc > 0 ? argv[0] : nullptr),
                "cannot create --out " + out.string() + ": " + ec.message());
  }
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
