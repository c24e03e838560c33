// The sillage command (docs/cli.md, docs/online.md):
//   sillage solve PROBLEM.toml [--out DIR] [--delta auto|VALUE] [--refine halving|regions]
//                 [--scheduling fifo|priority] [--threads N] [--max-runs N] [--max-seconds S]
//                 [--quiet] [--save-tubes] [--full-tubes] [--explain-seconds S]
//   sillage explain PROBLEM.toml [--delta auto|VALUE] [--seconds S] [--threads N] [--max-runs N] [--max-seconds S]
//   sillage check PROBLEM.toml
//   sillage show TUBEFILE
//   sillage plot TUBEFILE --out F.svg
//   sillage stream PROBLEM.toml [--strict] [--window S]     (online_commands.h)
//   sillage replay PROBLEM.toml [--out DIR] [--speed N] [--window S] [--no-batch] [--quiet]
// Exit codes: 0 solved (or valid), 1 no solution (an empty domain, explained), 2 bad input,
// 3 stopped by a budget before the fixed point.
#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "explain_command.h"
#include "online_commands.h"
#include "python_commands.h"

#include "sillage/problem/check_summary.h"
#include "sillage/problem/bound_audit.h"
#include "sillage/problem/var_sizes.h"
#include "sillage/figures/tube_figure.h"
#include "sillage/problem/load_problem.h"
#include "sillage/problem/report_html.h"
#include "sillage/problem/solve_problem.h"
#include "sillage/problem/write_results.h"
#include "sillage/threads.h"
#include "sillage/tube/tube_io.h"

using namespace sillage;

namespace {

// 3: a budget (--max-runs, --max-seconds) ran out before the fixed point.
constexpr int kSolved = 0, kNoSolution = 1, kBadInput = 2, kStopped = 3;

// At most 10^15 contractor runs: years of work, and far from the size_t limit
// that a number written past it would wrap around.
constexpr unsigned long long kMaxRuns = 1'000'000'000'000'000ULL;

// An option's value written as a whole number from min to max (no sign, no
// exponent: "-1" and "1e20" are refused, not wrapped or truncated).
CLI::Validator whole_number(const std::string& what, unsigned long long min, unsigned long long max) {
  const std::string range = std::to_string(min) + " to " + std::to_string(max);
  return CLI::Validator(
      [=](std::string& v) {
        unsigned long long n = 0;
        const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
        const bool ok = ec == std::errc() && end == v.data() + v.size() && n >= min && n <= max;  // no sign, no wrap
        const std::string shown = v.size() > 40 ? v.substr(0, 40) + "..." : v;
        return ok ? std::string() : "found \"" + shown + "\", expected " + what + " from " + range;
      },
      "N in " + range);
}

std::optional<double> parse_delta(const std::string& s, bool& is_auto) {
  is_auto = s == "auto";
  if (is_auto || s.empty()) return std::nullopt;
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.size() || !(v > 0) || !std::isfinite(v))
    throw Error("--delta: found \"" + s + "\", expected \"auto\" or a slice width > 0");
  return v;
}

// --save-tubes: each tube variable as DIR/NAME.tube (tube_io), for sillage show / plot
// and load_tube in C++ or Python; a tube stays a Tube, a tube_vector a TubeVector.
void save_tubes(const SolveResult& r, const std::string& out) {
  for (const VarDomain& v : r.built.vars) {
    if (!v.tubes) continue;
    const std::string path = (std::filesystem::path(out) / (v.spec->name + ".tube")).string();
    if (v.spec->kind == VarKind::Tube) save((*v.tubes)[0], path);
    else save(*v.tubes, path);
  }
}

SolveOptions solve_options(const std::string& delta_text, bool regions, const std::string& scheduling, const Budget& budget) {
  SolveOptions o;
  o.budget = budget;
  o.delta = parse_delta(delta_text, o.auto_delta);
  if (regions) o.refinement = DeltaRefinement::Regions;
  if (!scheduling.empty()) o.scheduling = scheduling == "priority" ? Scheduling::Priority : Scheduling::Fifo;
  return o;
}

int solve(const std::string& file, std::string out, SolveOptions o, int threads, bool quiet, bool tubes,
          bool full_tubes, double explain_seconds) {
  std::optional<ThreadLimit> limit;
  if (threads > 0) limit.emplace(static_cast<std::size_t>(threads));
  const auto start = std::chrono::steady_clock::now();
  const Problem p = load_problem(file);
  check_solve_options(p, o, "--");
  if (out.empty()) out = (std::filesystem::path("out") / std::filesystem::path(file).stem()).string();
  check_output_dir(p, out, tubes);  // before the solve: never an input overwritten, nor time lost
  const bool progress = !quiet && isatty(STDERR_FILENO);
  if (progress)
    o.on_step = [&](const ScheduleStep& s) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "\rδ = %g (%zu slices): %zu rounds, %zu contractor runs, %.2f s   ", s.delta, s.slices,
                   s.stats.iterations, s.stats.contractor_calls, elapsed);
    };
  const SolveResult r = solve_problem(p, o);
  if (progress) std::fprintf(stderr, "\n");
  for (const std::string& w : r.warnings) std::fprintf(stderr, "sillage: warning: %s\n", w.c_str());
  // No solution: which statements to relax, unless --explain-seconds 0.
  std::optional<Explanation> e;
  if (r.empty && explain_seconds > 0) {
    try {
      e = cli::explain_failure(p, r, explain_seconds, o.budget, quiet);
    } catch (const Error& x) {  // the answer (no solution) and its outputs stand without it
      std::fprintf(stderr, "sillage: no explanation: %s\n", x.what());
    }
  }
  OutputOptions written;
  if (full_tubes) written.max_slices = 0;
  write_results(p, r, out, written, e ? &*e : nullptr);
  write_text_file(out, "report.html", report_html(p, r, e ? &*e : nullptr));
  if (tubes) save_tubes(r, out);
  if (!quiet) {
    const ScheduleStep& last = r.schedule.back();
    std::printf("%s: %s with δ = %g (%zu slices), %zu contractor runs, build %.3f s, contraction %.3f s\n",
                file.c_str(), r.empty ? "NO SOLUTION" : r.stopped.empty() ? "solved" : "STOPPED", last.delta, last.slices, last.stats.contractor_calls,
                r.build_seconds(), r.contract_seconds());
    if (r.empty) std::printf("  %s\n", r.why_empty.c_str());
    if (e) std::fputs(e->str().c_str(), stdout);
    if (!r.stopped.empty()) std::printf("  STOPPED before the fixed point (the domains are enclosures): %s\n", r.stopped.c_str());
    if (p.output.truth && !r.empty) {
      const TruthCheck c = check_truth(p, r.built);
      std::printf("  truth: %zu of %zu time points inside%s\n", c.inside, c.samples,
                  c.first_misses.empty() ? "" : (", first miss: " + c.first_misses.front()).c_str());
    }
    if (p.output.truth) {  // a bound the truth needs beyond 100 % voids the guarantee
      std::printf("  bound audit: how much of each stated bound the truth used\n");
      for (const AuditLine& l : audit_problem(p)) std::printf("    %s\n", audit_text(l).c_str());
    }
    if (!r.empty) {  // what a user reads first: how well each variable is known
      std::printf("  sizes: box diameter (the largest width over the components), mean / median / max\n");
      const std::string table = sizes_table(var_sizes(p, r.built));
      for (std::size_t a = 0, e; a < table.size(); a = e + 1) {
        e = table.find('\n', a);
        std::printf("    %s\n", table.substr(a, e - a).c_str());
      }
    }
    std::printf("  wrote %s/report.html, results.json and one CSV%s per tube\n", out.c_str(),
                tubes ? " and one .tube file" : "");
  } else if (r.empty) {  // quiet drops the summary, never the answer's explanation
    std::printf("%s: NO SOLUTION\n  %s\n", file.c_str(), r.why_empty.c_str());
    if (e) std::fputs(e->str().c_str(), stdout);
  }
  if (!r.stopped.empty()) {
    std::fprintf(stderr, "sillage: stopped before the fixed point: %s (sillage solve --max-runs N / --max-seconds S)\n",
                 r.stopped.c_str());
    return kStopped;
  }
  return r.empty ? kNoSolution : kSolved;
}

int check(const std::string& file) {
  const Problem p = load_problem(file);
  std::fputs(check_summary(p).c_str(), stdout);
  return kSolved;
}

// Tube files hold a Tube (kind 1) or a TubeVector (kind 2): read the kind word.
bool is_tube_vector_file(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return false;  // load_tube says why
  unsigned char head[16] = {};
  const std::size_t n = std::fread(head, 1, sizeof head, f);
  std::fclose(f);
  return n == sizeof head && head[12] == 2;
}

TubeVector load_any(const std::string& path) {
  if (is_tube_vector_file(path)) return load_tube_vector(path);
  return TubeVector({load_tube(path)});
}

int show(const std::string& path) {
  const TubeVector x = load_any(path);
  const TDomain& td = *x.tdomain();
  std::printf("%s: %s of %zu component(s), %zu slices over [%g, %g]\n", path.c_str(),
              is_tube_vector_file(path) ? "TubeVector" : "Tube", x.size(), td.nb_slices(), td.t0(), td.tf());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Interval c = x[i].codomain();
    std::printf("  [%zu] codomain [%.6g, %.6g], volume %.6g, max thickness %.6g%s\n", i, c.lb(), c.ub(),
                x[i].volume(), x[i].max_thickness(), x[i].is_empty() ? ", EMPTY" : "");
  }
  return kSolved;
}

int plot(const std::string& path, const std::string& out) {
  std::error_code ec;  // false with an error when out does not exist yet
  if (std::filesystem::equivalent(out, path, ec))
    throw Error("--out " + out + " is the tube file read: choose another file for the figure");
  const TubeVector x = load_any(path);
  const std::string title = std::filesystem::path(path).filename().string();
  // A tube file holds no variable name: its stem names the axes (v.tube: v, or v[0] and v[1]).
  const std::string name = std::filesystem::path(path).stem().string();
  const Figure f = x.size() >= 2 ? tube_vector_figure(x, 0, 1, title, {}, nullptr, nullptr, 600, nullptr, name + "[0]", name + "[1]")
                                 : tube_figure(x[0], title, {}, nullptr, 600, 300, name);
  f.save(out);
  std::printf("wrote %s\n", out.c_str());
  return kSolved;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sillage: guaranteed state estimation from a problem file (docs/cli.md)"};
  app.require_subcommand(1);
  std::string problem, out, delta, tube_file, refine = "halving", scheduling;
  int threads = 0;
  Budget budget;
  bool quiet = false, save_tube_files = false, full_tubes = false;
  double explain_seconds = 30;
  auto* s = app.add_subcommand("solve", "solve a problem file; write DIR/report.html, results.json, NAME.csv");
  s->add_option("problem", problem, "the problem file (TOML)")->required();
  s->add_option("--out", out, "output directory (default out/<problem name>)");
  s->add_option("--delta", delta, "slice width: auto or a value (default: the file's)");
  s->add_option("--refine", refine, "how the automatic delta refines: halving (every slice) or regions (the thick ones)")
      ->check(CLI::IsMember({"halving", "regions"}));
  s->add_option("--scheduling", scheduling, "the order within a round: fifo or priority (default: the file's)")
      ->check(CLI::IsMember({"fifo", "priority"}));
  s->add_option("--threads", threads, "worker threads (default: all)")
      ->check(whole_number("a number of threads", 1, 1 << 16));
  s->add_option("--max-runs", budget.max_boxes,
                "contractor runs of one contraction before it stops, exit status 3 (default 10000000; 0: no limit)")
      ->check(whole_number("a number of contractor runs (0: no limit)", 0, kMaxRuns));
  s->add_option("--max-seconds", budget.max_seconds,
                "wall-clock seconds of one contraction before it stops, exit status 3 (default 0: no limit)")
      ->check(CLI::NonNegativeNumber);
  s->add_flag("--save-tubes", save_tube_files, "also write each tube as DIR/NAME.tube (for sillage show, load_tube)");
  s->add_flag("--full-tubes", full_tubes,
              "write every slice in results.json and the CSV files (default: at most 10000 per tube, hulls of "
              "consecutive slices beyond)");
  s->add_flag("--quiet", quiet, "no progress line, no summary (a NO SOLUTION is still explained)");
  s->add_option("--explain-seconds", explain_seconds,
                "no solution: seconds to search for the statements to relax (default 30; 0: no search)")
      ->check(CLI::NonNegativeNumber);
  auto* ex = app.add_subcommand("explain", "solve a problem file; without solution, print which statements to relax");
  ex->add_option("problem", problem, "the problem file (TOML)")->required();
  ex->add_option("--delta", delta, "slice width: auto or a value (default: the file's)");
  ex->add_option("--seconds", explain_seconds, "seconds of the search (default 30; 0: no limit)")
      ->check(CLI::NonNegativeNumber);
  ex->add_option("--threads", threads, "worker threads (default: all)")
      ->check(whole_number("a number of threads", 1, 1 << 16));
  ex->add_option("--max-runs", budget.max_boxes, "contractor runs of each contraction (default 10000000; 0: no limit)")
      ->check(whole_number("a number of contractor runs (0: no limit)", 0, kMaxRuns));
  ex->add_option("--max-seconds", budget.max_seconds, "wall-clock seconds of each contraction (default 0: no limit)")
      ->check(CLI::NonNegativeNumber);
  auto* c = app.add_subcommand("check", "validate a problem file and print the network it would build");
  c->add_option("problem", problem, "the problem file (TOML)")->required();
  auto* sh = app.add_subcommand("show", "summary of a tube file (tube_io)");
  sh->add_option("tubefile", tube_file, "a file written by save()")->required();
  auto* pl = app.add_subcommand("plot", "SVG figure of a tube file");
  pl->add_option("tubefile", tube_file, "a file written by save()")->required();
  pl->add_option("--out", out, "the SVG file")->required();
  bool strict = false, no_batch = false;
  double speed = 0;
  std::optional<double> window;
  auto* st = app.add_subcommand("stream", "run a problem online: rows as JSON Lines on stdin, estimates on stdout");
  st->add_option("problem", problem, "the problem file (TOML)")->required();
  st->add_flag("--strict", strict, "stop at the first bad line (exit status 2) instead of reporting it and going on");
  st->add_option("--window", window, "seconds of past kept (0: everything; default: the file's [online] window)")
      ->check(CLI::NonNegativeNumber);
  auto* rp = app.add_subcommand("replay", "feed a problem's own tables online in stamp order; compare with the batch solve");
  rp->add_option("problem", problem, "the problem file (TOML)")->required();
  rp->add_option("--out", out, "output directory (default out/<problem name>_replay)");
  rp->add_option("--speed", speed, "N x real time (default 0: as fast as possible)")->check(CLI::NonNegativeNumber);
  rp->add_option("--window", window, "seconds of past kept (0: everything; default: the file's [online] window)")
      ->check(CLI::NonNegativeNumber);
  rp->add_flag("--no-batch", no_batch, "do not solve the file in batch for the comparison");
  rp->add_flag("--quiet", quiet, "no summary");
  // Listed in --help; their arguments are Python's (sillage batch --help).
  app.add_subcommand("batch", "solve many problem files as Dask tasks (docs/distributed.md)")->allow_extras();
  app.add_subcommand("sweep", "solve a problem over a grid of values of its keys (--set KEY=V1,V2) as Dask tasks")
      ->allow_extras();
  if (argc > 1 && cli::is_python_command(argv[1])) return cli::run_python_command(argc, argv);
  // A mistyped command is named (CLI11 would only say that one is required).
  const std::string first = argc > 1 ? argv[1] : "";
  if (!first.empty() && first[0] != '-' && first != "solve" && first != "explain" && first != "check" && first != "show" && first != "plot" &&
      first != "stream" && first != "replay") {
    std::fprintf(stderr, "sillage: found the command '%s', expected solve, explain, check, show, plot, stream, replay, batch or sweep (sillage --help)\n",
                 argv[1]);
    return kBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kBadInput;
  }
  try {
    if (*s)
      return solve(problem, out, solve_options(delta, refine == "regions", scheduling, budget), threads, quiet,
                   save_tube_files, full_tubes, explain_seconds);
    if (*ex) {
      std::optional<ThreadLimit> limit;
      if (threads > 0) limit.emplace(static_cast<std::size_t>(threads));
      return cli::explain(problem, solve_options(delta, false, "", budget), explain_seconds);
    }
    if (*c) return check(problem);
    if (*sh) return show(tube_file);
    if (*pl) return plot(tube_file, out);
    if (*st) return cli::stream(problem, strict, window);
    if (*rp) return cli::replay(problem, out, speed, window, !no_batch, quiet);
  } catch (const Error& e) {
    std::fprintf(stderr, "sillage: %s\n", e.what());
    return kBadInput;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "sillage: out of memory: the tubes and the network do not fit (sillage check gives an "
                         "estimate); a larger --delta\n");
    return kBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sillage: %s\n", e.what());
    return kBadInput;
  }
  return kBadInput;
}
