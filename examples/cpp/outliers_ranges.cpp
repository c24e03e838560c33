// Outliers (issue 11 §3): a robot localised from ranges to 20 beacons, three
// of which are wrong (a sensor glitch, a multipath echo). The strict
// intersection of the 20 rings is empty: the data are inconsistent. GOMNE
// relaxes it: the smallest q for which "at most q ranges are wrong" is
// consistent is found, the wrong ranges are named, and the robot is located.
// Exits non-zero if q, the outliers or the truth check disagree.
#include <algorithm>
#include <cstdio>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "example_args.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/gomne.h"
#include "sillage/figures/figure.h"
#include "sillage/paving/sivia.h"

using namespace sillage;

namespace {

struct Beacon {
  int x, y;
  double range;  // measured; the sensor promises +-0.1
};

// Truth (3.25, -1.5); ranges 4, 11 and 16 are off by +9, -6.5 and +12.
const Beacon kBeacons[] = {{-15, 16, 25.27}, {1, 25, 26.57},   {-32, 25, 44.1},   {-26, -10, 30.5},
                           {10, 27, 38.31},  {-40, -30, 51.83}, {-9, -22, 23.92},  {-23, -5, 26.53},
                           {26, 24, 34.16},  {35, -27, 40.76},  {-2, -12, 11.77},  {22, 24, 25.18},
                           {27, 5, 24.64},   {-32, -23, 41.25}, {-21, -34, 40.57}, {-10, 17, 22.8},
                           {30, -26, 48.31}, {-32, 13, 38.09},  {-16, 6, 20.65},   {5, -5, 3.87}};
const Vector kTruth{3.25, -1.5};
const std::vector<std::size_t> kWrong{4, 11, 16};

Interval range_of(const Beacon& b) { return Interval(b.range - 0.1, b.range + 0.1); }

std::vector<CtcPtr> range_contractors() {
  std::vector<CtcPtr> ctcs;
  for (const Beacon& b : kBeacons) {
    const Function d({"x1", "x2"}, "sqrt((x1 - (" + std::to_string(b.x) + "))^2 + (x2 - (" + std::to_string(b.y) +
                                       "))^2)");
    ctcs.push_back(std::make_shared<CtcFunction>(d, range_of(b)));
  }
  return ctcs;
}

std::string indices(const std::vector<std::size_t>& v) {
  std::string s;
  for (std::size_t i : v) s += (s.empty() ? "" : ", ") + std::to_string(i);
  return "{" + s + "}";
}

void draw_scene(Figure& fig, const GomneResult& r) {
  const Style ok_ring{"#9ecae1", "none", 0, 0.35, ""}, bad_ring{"#fc9272", "none", 0, 0.6, ""};
  for (std::size_t i = 0; i < std::size(kBeacons); ++i) {
    const bool wrong = std::find(r.outliers.begin(), r.outliers.end(), i) != r.outliers.end();
    const Vector c{double(kBeacons[i].x), double(kBeacons[i].y)};
    fig.draw_ring(c, range_of(kBeacons[i]), wrong ? bad_ring : ok_ring);
    fig.draw_point(c, 3.0, {wrong ? "red" : "navy", "none", 0, 1, ""});
  }
  fig.draw_boxes(r.leaves, {"#ffd92f", "black", 0.5, 1, ""});
  fig.draw_box(r.box, {"none", "black", 1.2, 1, ""});
  fig.draw_point(kTruth, 3.0, {"black", "none", 0, 1, ""});
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const double eps = example::option_number(argc, argv, "--eps", 0.1);
  if (!(eps > 0)) {
    std::fprintf(stderr, "outliers_ranges: --eps must be > 0\n");
    return 2;
  }
  const IntervalVector x0{{-50, 50}, {-50, 50}};
  const auto ctcs = range_contractors();

  // The strict intersection, paved: empty, the data are inconsistent.
  const Paving strict = sivia(x0, CtcInter(ctcs), eps);
  const bool inconsistent = strict.outer().empty();
  std::printf("Range-only localisation, %zu beacons, ranges +-0.1, X0 = %s, eps = %g\n", ctcs.size(),
              x0.str().c_str(), eps);
  std::printf("  strict intersection of the %zu rings: %s\n", ctcs.size(),
              inconsistent ? "empty -> inconsistent data" : "not proven empty");

  GomneOptions o;
  o.eps = eps;
  const GomneResult r = gomne(ctcs, x0, o);
  const bool truth_in = r.box.contains(kTruth);
  std::printf("  GOMNE: q = %d (at least %d ranges are wrong; S_q not empty)\n", r.q, r.q);
  std::printf("  proven outliers (if at most q are wrong): %s, injected: %s\n", indices(r.outliers).c_str(),
              indices(kWrong).c_str());
  std::printf("  robot in %s (%zu leaves), truth (%.2f, %.2f) inside: %s\n", r.box.str().c_str(), r.leaves.size(),
              kTruth[0], kTruth[1], truth_in ? "yes" : "NO");
  const bool ok = inconsistent && r.q == int(kWrong.size()) && r.outliers == kWrong && truth_in;

  Figure all(x0);
  all.set_title("20 ranges, 3 wrong (red): GOMNE q = " + std::to_string(r.q));
  draw_scene(all, r);
  all.save((out / "outliers_ranges.svg").string());
  Figure zoom(r.box.inflate(1.0));
  zoom.set_title("q-relaxed set (yellow), its hull (black), the truth (dot)");
  draw_scene(zoom, r);
  zoom.save((out / "outliers_ranges_zoom.svg").string());

  std::ostringstream result;
  result << "strict: " << (inconsistent ? "inconsistent" : "?") << "; q = " << r.q << ", outliers "
         << indices(r.outliers);
  example::print_result("outliers_ranges", result.str(), ok,
                        {{"outliers_ranges.svg", "Rings of the 20 ranges, the 3 proven outliers in red"},
                         {"outliers_ranges_zoom.svg", "Paving of the q-relaxed set around the robot"}});
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }
