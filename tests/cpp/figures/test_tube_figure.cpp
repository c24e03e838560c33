// Tube figures: well-formed SVG, one rectangle per slice for small tubes,
// aggregation of many slices that still covers every slice, unbounded tubes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sillage/figures/tube_figure.h"
#include "svg_check.h"

using namespace sillage;
using namespace sillage::test;

namespace {

struct Rect {
  double x0, y0, x1, y1;  // pixels
};

std::vector<Rect> rects(const Figure& fig, const std::string& cls) {
  std::vector<Rect> r;
  for (const auto& t : parse_xml(fig.svg())) {
    if (t.name != "rect" || !t.attributes.count("class") || t.attributes.at("class") != cls) continue;
    const double x = std::stod(t.attributes.at("x")), y = std::stod(t.attributes.at("y"));
    r.push_back({x, y, x + std::stod(t.attributes.at("width")), y + std::stod(t.attributes.at("height"))});
  }
  return r;
}

// Every slice (clipped to the window [lo, hi] in x) lies in one of the slice
// rectangles, up to the 0.01 px rounding of the SVG coordinates.
void expect_covered(const Figure& fig, const Tube& x, double lo, double hi) {
  const auto rs = rects(fig, "slice");
  const auto& td = *x.tdomain();
  const double tol = 0.02;
  std::size_t r = 0;
  for (std::size_t k = 0; k < x.nb_slices(); ++k) {
    const Interval v = x.slice(k) & Interval(lo, hi);
    if (v.is_empty()) continue;
    const double a = fig.px(td.t(k)), b = fig.px(td.t(k + 1)), top = fig.py(v.ub()), bottom = fig.py(v.lb());
    auto covers = [&](const Rect& q) {
      return q.x0 <= a + tol && q.x1 >= b - tol && q.y0 <= top + tol && q.y1 >= bottom - tol;
    };
    while (r < rs.size() && rs[r].x1 < b - tol) ++r;  // rectangles come in time order
    ASSERT_LT(r, rs.size()) << "slice " << k << " not drawn";
    // Within the rounding tolerance the previous rectangle may end there too.
    EXPECT_TRUE(covers(rs[r]) || (r + 1 < rs.size() && covers(rs[r + 1]))) << "slice " << k << " not covered";
  }
}

TubeStyle merge(double px) {
  TubeStyle s;
  s.merge_px = px;
  return s;
}

std::shared_ptr<TDomain> domain(double tf, double dt) { return TDomain::create(0, tf, dt); }

}  // namespace

TEST(TubeFigure, OneRectanglePerSliceForSmallTubes) {
  auto td = domain(10, 1);
  Tube x(td, std::vector<Interval>{{0, 1}, {1, 3}, {2, 4}, {0, 2}, {-1, 1}, {0, 1}, {2, 3}, {1, 5}, {0, 4}, {1, 2}});
  Figure fig = tube_figure(x, "a <small> tube");
  const auto tags = parse_xml(fig.svg());
  ASSERT_FALSE(tags.empty());
  EXPECT_EQ(tags[0].name, "svg");
  EXPECT_EQ(rects(fig, "slice").size(), 10u);
  EXPECT_NE(fig.svg().find("a &lt;small&gt; tube"), std::string::npos);
  expect_covered(fig, x, -1e9, 1e9);
}

TEST(TubeFigure, IdenticalConsecutiveSlicesMerge) {
  auto td = domain(10, 1);
  Tube x(td, Interval(-1, 1));
  x.set(Interval(0, 3), 5);
  Figure fig = tube_figure(x);
  EXPECT_EQ(draw_tube(fig, x, merge(0)), 3u);  // [0,5], 5, [6,10]
  EXPECT_EQ(rects(fig, "slice").size(), 6u);                      // twice: tube_figure drew it too
}

TEST(TubeFigure, ThinSliceIsNotHiddenInAThickNeighbour) {
  // Each slice inside the first one: merging them would be rigorous but useless.
  auto td = domain(4, 1);
  Tube x(td, std::vector<Interval>{{-10, 10}, {-1, 1}, {-0.5, 0.5}, {-0.5, 0.5}});
  Figure fig = tube_figure(x);
  EXPECT_EQ(rects(fig, "slice").size(), 3u);
  expect_covered(fig, x, -1e9, 1e9);
}

TEST(TubeFigure, GatesAndTruth) {
  auto td = domain(6.28, 0.5);
  Tube x(td, "sin(t) + [-0.2, 0.2]");
  Trajectory truth("sin(t)", Interval(0, 6.28));
  TubeStyle st = merge(0);
  st.show_gates = true;
  Figure fig = tube_figure(x, "sin", st, &truth);
  EXPECT_EQ(rects(fig, "slice").size(), x.nb_slices());
  EXPECT_EQ(rects(fig, "gate").size(), x.nb_slices() + 1);
  std::size_t polylines = 0;
  for (const auto& t : parse_xml(fig.svg())) polylines += t.name == "polyline" && t.attributes.at("class") == "truth";
  EXPECT_EQ(polylines, 1u);
  EXPECT_TRUE(x.contains(truth));
}

TEST(TubeFigure, ManySlicesAreAggregatedAndStillCovered) {
  auto td = domain(10, 1e-4);  // 10^5 slices
  ASSERT_EQ(td->nb_slices(), 100000u);
  Tube x(td, "cos(t) * t / 3 + [-0.1, 0.1] * (1 + t)");
  TubeStyle st;
  st.show_gates = true;
  Figure fig = tube_figure(x, "10^5 slices", st);
  const auto rs = rects(fig, "slice");
  EXPECT_LE(rs.size(), 2000u);
  EXPECT_EQ(rects(fig, "gate").size(), 0u);  // gates would paint the whole tube
  EXPECT_LT(fig.svg().size(), 400000u);
  expect_covered(fig, x, -1e9, 1e9);
}

TEST(TubeFigure, UnboundedTubeIsClipped) {
  auto td = domain(4, 1);
  Tube x(td, std::vector<Interval>{Interval(), Interval(0, rounding::kInf), Interval(-1, 2), Interval::empty()});
  Figure fig = tube_figure(x, "unbounded");
  EXPECT_NE(fig.svg().find("clipped"), std::string::npos);
  EXPECT_EQ(rects(fig, "slice").size(), 3u);  // the empty slice draws nothing
  expect_covered(fig, x, -1.75, 2.75);        // window [-1, 2] with a 25 % margin
  Tube all(td);  // no finite bound at all
  EXPECT_NO_THROW(tube_figure(all).svg());
  EXPECT_NO_THROW(thickness_figure(all).svg());
}

TEST(TubeFigure, TubeVector2d) {
  auto td = domain(6, 0.5);
  TubeVector x(td, "(cos(t) + [-0.1, 0.1], sin(t) + [-0.2, 0.2], t)");
  Trajectory a("cos(t)", Interval(0, 6)), b("sin(t)", Interval(0, 6));
  Figure fig = tube_vector_figure(x, 0, 1, "path", merge(0), &a, &b);
  EXPECT_EQ(rects(fig, "slice").size(), x.nb_slices());
  EXPECT_EQ(rects(fig, "initial").size(), 1u);
  EXPECT_EQ(rects(fig, "final").size(), 1u);
  EXPECT_THROW(tube_vector_figure(x, 1, 1), DimensionError);
  EXPECT_THROW(tube_vector_figure(x, 0, 3), DimensionError);
  Figure f2(IntervalVector{Interval(-2, 2), Interval(-2, 2)});
  EXPECT_THROW(draw_tube(f2, x[0], merge(-1)), Error);
}

TEST(TubeFigure, TubeVector2dAggregatesTinyBoxes) {
  auto td = domain(6, 1e-4);  // 60000 thin slices along a circle
  TubeVector x(td, "(cos(t) + [-0.001, 0.001], sin(t) + [-0.001, 0.001])");
  Figure fig = tube_vector_figure(x);
  const auto rs = rects(fig, "slice");
  EXPECT_LE(rs.size(), 3000u);
  EXPECT_GT(rs.size(), 100u);
  // Every slice box lies in one of the drawn boxes (larger boxes are drawn first: any order).
  const double tol = 0.02;
  for (std::size_t k = 0; k < x.nb_slices(); ++k) {
    const double a = fig.px(x[0].slice(k).lb()), b = fig.px(x[0].slice(k).ub());
    const double top = fig.py(x[1].slice(k).ub()), bottom = fig.py(x[1].slice(k).lb());
    auto covers = [&](const Rect& q) {
      return q.x0 <= a + tol && q.x1 >= b - tol && q.y0 <= top + tol && q.y1 >= bottom - tol;
    };
    ASSERT_TRUE(std::any_of(rs.begin(), rs.end(), covers)) << "slice " << k << " not covered";
  }
}

TEST(TubeFigure, Thickness) {
  auto td = domain(4, 1);
  TubeVector x(td, 2, Interval(0, 1));
  x[1].set(Interval(0, 3), 2);
  x[0].set(Interval(0, 4), 2);
  const auto dmax = thickness_values(x), ddiag = thickness_values(x, ThicknessMeasure::Diagonal);
  EXPECT_EQ(dmax, (std::vector<double>{1, 1, 4, 1}));
  EXPECT_DOUBLE_EQ(ddiag[2], 5.0);
  EXPECT_DOUBLE_EQ(ddiag[0], std::sqrt(2.0));
  Figure fig = thickness_figure(x);
  std::size_t curves = 0;
  for (const auto& t : parse_xml(fig.svg())) curves += t.name == "polyline" && t.attributes.at("class") == "thickness";
  EXPECT_EQ(curves, 1u);
  EXPECT_THROW(step_figure(*td, {1, 2}, "bad", 600, 200), DimensionError);
  auto big = domain(10, 1e-4);
  Tube y(big, "[-0.1, 0.1] * (1 + t^2)");
  EXPECT_LT(thickness_figure(y).svg().size(), 100000u);
}

TEST(TubeFigure, NonUniformDomainSampledTruthAndUnboundedVector) {
  auto td = TDomain::create(std::vector<double>{0, 0.1, 0.5, 2, 2.05, 4});
  Tube x(td, "t + [-0.5, 0.5]");
  Trajectory truth(std::vector<double>{0, 1, 3, 4}, std::vector<double>{0, 1.2, 2.8, 4});
  TubeStyle st = merge(0);
  st.show_gates = true;
  Figure fig = tube_figure(x, "non-uniform", st, &truth);
  EXPECT_EQ(rects(fig, "slice").size(), 5u);
  expect_covered(fig, x, -1e9, 1e9);
  std::size_t truths = 0;
  for (const auto& t : parse_xml(fig.svg())) truths += t.name == "polyline" && t.attributes.at("class") == "truth";
  EXPECT_EQ(truths, 1u);

  TubeVector v(td, 2, Interval(0, 1));
  v[1].set(Interval(0, rounding::kInf), 2);
  Figure f2 = tube_vector_figure(v, 1, 0, "half-line");
  EXPECT_NE(f2.svg().find("clipped"), std::string::npos);
  EXPECT_EQ(rects(f2, "initial").size(), 1u);
}
