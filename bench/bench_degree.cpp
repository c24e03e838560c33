// The degree test T (thesis Alg. 7-9 with boundary refinement) on staircase
// regions of 10, 100 and 1000 boxes: column i is [i, i+1] x [0, i+1], so the
// boundary has 2n + 2 maximal edges, of total length 4n + 2. Two maps with
// their zero at (0.5, 0.5): the shifted identity (whole edges conclude) and a
// rotation-scaling (x + y - 1, y - x) + z^2 / 8 whose edges near the zero need
// refinement. Counter: time per boundary piece of the final cover.
#include <benchmark/benchmark.h>

#include "sillage/loops/topological_degree.h"

using namespace sillage;

namespace {

std::vector<IntervalVector> staircase(int n) {
  std::vector<IntervalVector> boxes;
  for (int i = 0; i < n; ++i) boxes.push_back({Interval(i, i + 1), Interval(0, i + 1)});
  return boxes;
}

IntervalVector shifted_identity(const IntervalVector& t) { return {t[0] - 0.5, t[1] - 0.5}; }

IntervalVector rotation_quadratic(const IntervalVector& t) {
  const Interval x = t[0] - 0.5, y = t[1] - 0.5;
  return {x + y + (sqr(x) - sqr(y)) / 8.0, y - x + (x * y) / 4.0};
}

void run(benchmark::State& state, const PlaneFunction& f) {
  const auto boxes = staircase(static_cast<int>(state.range(0)));
  const auto loops = contour(boxes);
  DegreeResult r;
  for (auto _ : state) {
    r = topological_degree(loops, f);
    benchmark::DoNotOptimize(r);
  }
  if (!r.degree || *r.degree != 1) state.SkipWithError("degree should be 1");
  state.counters["boxes"] = static_cast<double>(boxes.size());
  state.counters["pieces"] = static_cast<double>(r.nb_pieces);
  state.counters["evaluations"] = static_cast<double>(r.nb_evaluations);
  state.counters["time_per_piece"] = benchmark::Counter(static_cast<double>(r.nb_pieces),
                                                        benchmark::Counter::kIsIterationInvariantRate |
                                                            benchmark::Counter::kInvert);
}

void BM_DegreeIdentity(benchmark::State& state) { run(state, shifted_identity); }
void BM_DegreeRotationQuadratic(benchmark::State& state) { run(state, rotation_quadratic); }

// With the contour extraction included (what a caller with boxes pays).
void BM_DegreeFromBoxes(benchmark::State& state) {
  const auto boxes = staircase(static_cast<int>(state.range(0)));
  DegreeResult r;
  for (auto _ : state) {
    r = topological_degree(boxes, PlaneFunction(rotation_quadratic));
    benchmark::DoNotOptimize(r);
  }
  state.counters["time_per_piece"] = benchmark::Counter(static_cast<double>(r.nb_pieces),
                                                        benchmark::Counter::kIsIterationInvariantRate |
                                                            benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(BM_DegreeIdentity)->Arg(10)->Arg(100)->Arg(1000);
BENCHMARK(BM_DegreeRotationQuadratic)->Arg(10)->Arg(100)->Arg(1000);
BENCHMARK(BM_DegreeFromBoxes)->Arg(10)->Arg(100)->Arg(1000);
BENCHMARK_MAIN();
