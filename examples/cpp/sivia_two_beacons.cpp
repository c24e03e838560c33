// Set inversion for the two-beacon range-only problem of thesis 2.4.3
// (Table 2.2): the robot at (0, 0) cannot be told from its mirror image across
// the line of the beacons; SIVIA (Alg. 1) characterizes both parts. Three
// variants, as in Fig. 2.13: plain SIVIA, SIVIA contracting each undetermined
// box before bisecting it (the thesis' coupling), and SIVIA with separators.
// SIVIA uses every thread of the machine; on one thread (ThreadLimit) the
// paving is the same.
#include <chrono>
#include <cstdio>
#include <sstream>

#include "example_args.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/sep_function.h"
#include "sillage/figures/figure.h"
#include "sillage/paving/sivia_function.h"
#include "sillage/threads.h"

using namespace sillage;

namespace {

struct Run {
  std::string label;
  Paving paving;
  double seconds;
};

template <class F>
Run timed(const std::string& label, F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  Paving p = f();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {label, std::move(p), s};
}

}  // namespace

int example_main(int argc, char** argv) {
  const auto out = example::out_dir(argc, argv);
  const double eps = 0.01;
  const IntervalVector x0{{-10, 14}, {-10, 10}};
  // (8.0, 5.0) with [9.03, 9.83] and (7.0, 2.2) with [6.94, 7.74].
  const Function g({"x1", "x2"}, "(sqrt((x1 - 8)^2 + (x2 - 5)^2), sqrt((x1 - 7)^2 + (x2 - 2.2)^2))");
  const IntervalVector y{{9.03, 9.83}, {6.94, 7.74}};
  const CtcFunction ctc(g, y);
  const SepFunction sep(g, y);

  // Mirror image of (0, 0) across the line of the beacons: the ambiguity of Fig. 2.13.
  const double dx = 7.0 - 8.0, dy = 2.2 - 5.0, t = ((0 - 8.0) * dx + (0 - 5.0) * dy) / (dx * dx + dy * dy);
  const Vector mirror{2 * (8.0 + t * dx), 2 * (5.0 + t * dy)};

  const Run runs[] = {
      timed("plain SIVIA", [&] { return sivia(x0, g, y, eps); }),
      timed("SIVIA + contractors", [&] { return sivia(x0, g, y, ctc, eps); }),
      timed("SIVIA + separators", [&] { return sivia(x0, sep, eps); }),
  };

  std::printf("Two-beacon set inversion, thesis Table 2.2 / Fig. 2.13, X0 = %s, eps = %g\n", x0.str().c_str(), eps);
  std::printf("  %-22s %9s %9s %9s %9s %10s %10s\n", "variant", "leaves", "inner", "boundary", "outside",
              "vol(X-)", "vol(X+)");
  bool ok = true;
  std::vector<std::pair<std::string, std::string>> figures;
  const char* files[] = {"sivia_plain.svg", "sivia_contractors.svg", "sivia_separators.svg"};
  std::ostringstream result;
  for (std::size_t k = 0; k < 3; ++k) {
    const Run& r = runs[k];
    const Paving& p = r.paving;
    std::printf("  %-22s %9zu %9zu %9zu %9zu %10.4f %10.4f   %.1f ms\n", r.label.c_str(), p.nb_leaves(),
                p.count(PavingTag::Inner), p.count(PavingTag::Boundary), p.count(PavingTag::Outside),
                p.volume(PavingTag::Inner), p.outer_volume(), r.seconds * 1e3);
    // The robot (0, 0) and its mirror image across the beacons' line must be in X+.
    for (const Vector& q : {Vector{0.0, 0.0}, mirror}) {
      const auto tag = p.tag_at(q);
      ok = ok && tag && *tag != PavingTag::Outside;
    }
    Figure fig(x0);
    fig.set_title(r.label + " (eps = 0.01)");
    fig.draw_paving(p);
    fig.draw_point({0.0, 0.0}, 3.0);
    fig.draw_point(mirror, 3.0, {"red", "none", 0, 1, ""});
    fig.save((out / files[k]).string());
    figures.push_back({files[k], "Fig. 2.13, " + r.label + ": inner green, boundary yellow, outside blue"});
    result << (k ? "; " : "") << r.label << ": " << p.nb_leaves() << " boxes";
  }
  std::printf("  (0, 0) and its mirror image (%.3f, %.3f) lie in the outer approximation: %s\n", mirror[0],
              mirror[1], ok ? "yes" : "NO");
  const std::size_t threads = ThreadLimit::current();
  const Run alone = [&] {
    const ThreadLimit one(1);
    return timed("plain SIVIA, one thread", [&] { return sivia(x0, g, y, eps); });
  }();
  const bool same = alone.paving == runs[0].paving;
  std::printf("  plain SIVIA on 1 thread (ThreadLimit) against %zu: the same paving: %s (%.1f ms against %.1f ms)\n",
              threads, same ? "yes" : "NO", alone.seconds * 1e3, runs[0].seconds * 1e3);
  ok = ok && same;
  example::print_result("sivia_two_beacons", result.str(), ok, figures);
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }
