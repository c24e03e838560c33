#include "online_commands.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "sillage/error.h"
#include "sillage/problem/load_problem.h"
#include "sillage/problem/replay_problem.h"
#include "sillage/problem/stream_lines.h"
#include "sillage/problem/write_results.h"

namespace sillage::cli {

namespace {

constexpr int kDone = 0, kNoSolution = 1, kBadInput = 2;

std::optional<OnlineOptions> with_window(const Problem& p, std::optional<double> window) {
  if (!window) return std::nullopt;
  if (!(*window >= 0)) throw Error("--window: seconds >= 0 (0: everything), got " + number_text(*window));
  OnlineOptions o = online_options(p);
  o.window = *window > 0 ? *window : INFINITY;
  return o;
}

bool inconsistent(const OnlineProblem& op) {
  return op.estimator().last_update().summary.status == Status::NoSolution;
}

}  // namespace

int stream(const std::string& file, bool strict, std::optional<double> window) {
  const Problem p = load_problem(file);
  OnlineProblem op(p, with_window(p, window));
  double written = -INFINITY;
  op.on_update([&] {
    const double now = op.estimator().now();
    if (now - written < p.online.output_every && !inconsistent(op)) return;
    written = now;
    std::fputs((estimate_line(op) + "\n").c_str(), stdout);
    std::fflush(stdout);  // a pipe: each estimate as soon as it is known
  });
  std::size_t n = 0;
  for (std::string line; std::getline(std::cin, line);) {
    ++n;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      op.feed(parse_stream_line(line));
    } catch (const Error& e) {
      std::fprintf(stderr, "sillage stream: line %zu: %s\n", n, e.what());
      if (strict) return kBadInput;
      continue;
    }
    if (inconsistent(op)) {
      std::fprintf(stderr, "sillage stream: line %zu: no solution: %s\n", n,
                   op.estimator().last_update().summary.reason.c_str());
      return kNoSolution;
    }
  }
  return kDone;
}

int replay(const std::string& file, std::string out, double speed, std::optional<double> window, bool batch, bool quiet) {
  const Problem p = load_problem(file);
  if (out.empty()) out = (std::filesystem::path("out") / (std::filesystem::path(file).stem().string() + "_replay")).string();
  check_output_dir(p, out, {"online.jsonl", "replay.json", "replay.svg", "replay.html"});  // never an input overwritten
  std::filesystem::create_directories(out);
  const std::string jsonl = (std::filesystem::path(out) / "online.jsonl").string();
  std::FILE* f = std::fopen(jsonl.c_str(), "w");
  if (!f) throw Error("cannot write " + jsonl);
  ReplayOptions o;
  o.speed = speed;
  o.online = with_window(p, window);
  o.batch = batch;
  o.on_update = [&](const OnlineProblem& op) { std::fputs((estimate_line(op) + "\n").c_str(), f); };
  ReplayResult r;
  try {
    r = replay_problem(p, o);
  } catch (...) {
    std::fclose(f);
    throw;
  }
  std::fclose(f);
  write_text_file(out, "replay.json", replay_json(p, r));
  write_text_file(out, "replay.svg", replay_svg(p, r));
  write_text_file(out, "replay.html", replay_html(p, r));
  const bool empty = r.summary.status == Status::NoSolution;
  if (!quiet) {
    const double span = r.t.empty() ? 0 : r.t.back() - p.time.t0;
    std::printf("%s: %s online, %zu rows, %zu updates in %.3f s (%.0f x real time)\n", file.c_str(),
                empty ? "NO SOLUTION" : "replayed", r.rows, r.t.size(), r.seconds, r.seconds > 0 ? span / r.seconds : 0);
    std::printf("  per row: median %.0f us, p99 %.0f us, max %.0f us\n", 1e6 * r.latency_quantile(0.5),
                1e6 * r.latency_quantile(0.99), 1e6 * r.latency_quantile(1));
    if (empty) std::printf("  %s\n", r.summary.reason.c_str());
    if (!r.refused.empty()) std::printf("  %zu rows refused, first: %s\n", r.refused.size(), r.refused.front().c_str());
    if (p.output.truth)
      std::printf("  truth: %zu of %zu samples inside the online tubes, %zu in a box still unbounded, %zu outside%s\n",
                  r.truth_inside, r.truth_samples, r.truth_unbounded, r.truth_samples - r.truth_inside - r.truth_unbounded,
                  r.truth_misses.empty() ? "" : (", first: " + r.truth_misses.front()).c_str());
    if (r.batch_solve)
      std::printf("  batch solve: the online box holds it at %zu of %zu times; online/batch box side %.2f on average\n",
                  r.online_holds_batch(), r.batch.size(), r.mean_side_ratio(0));
    std::printf("  wrote %s/replay.html, online.jsonl, replay.json and replay.svg\n", out.c_str());
  }
  return empty ? kNoSolution : kDone;
}

}  // namespace sillage::cli
