// Figures of chapter 6: the t-plane (paving, detections by status, diagonal,
// true crossings) and the map of loops (path, position tube, map boxes):
// well-formed SVG, the expected number of shapes of each kind, the status
// colours, the thinning of sub-pixel content, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "sillage/figures/loops_map_figure.h"
#include "sillage/figures/tplane_figure.h"
#include "sillage/paving/sivia.h"
#include "svg_check.h"

using namespace sillage;
using namespace sillage::test;

namespace {

bool has_fill(const std::vector<Element>& tags, const std::string& cls, const std::string& fill) {
  for (const auto& t : tags) {
    if (t.attributes.count("class") && t.attributes.at("class") == cls && t.attributes.count("fill") && t.attributes.at("fill") == fill) {
      return true;
    }
  }
  return false;
}

IntervalVector box(double a, double b, double c, double d) { return {Interval(a, b), Interval(c, d)}; }

// A paving of [0, 10]^2 whose outer approximation is a disk of radius 1
// around (3, 7), and three detections: the disk (proven), an L of two boxes
// (unproven), a box on the side of the square (partial).
struct Scene {
  Paving paving;
  std::vector<DetectionShape> detections;
  Scene() {
    const InclusionFunction f = [](const IntervalVector& x) {
      return IntervalVector{sqr(x[0] - Interval(3)) + sqr(x[1] - Interval(7))};
    };
    paving = sivia(box(0, 10, 0, 10), f, Interval(0, 1), 0.25);
    detections.push_back({paving.outer(), LoopStatus::Proven});
    detections.push_back({{box(6, 7, 8, 9), box(7, 8, 8, 8.5)}, LoopStatus::Unproven});
    detections.push_back({{box(0, 0.5, 9, 10)}, LoopStatus::Partial});
  }
};

std::size_t nb_contour_loops(const std::vector<DetectionShape>& ds) {
  std::size_t n = 0;
  for (const auto& d : ds) n += contour(d.boxes).size();
  return n;
}

}  // namespace

TEST(TPlaneFigure, DrawsLeavesDetectionsDiagonalAndCrossings) {
  const Scene s;
  const IntervalVector view = box(0, 10, 0, 10);
  Figure fig(view, 600);
  // The second crossing is out of view.
  const std::vector<PathCrossing> crossings{{3.0, 7.0, 0, 0, 0, 2}, {2.0, 12.0, 0, 0, 0, 2}};
  const std::size_t before = fig.nb_shapes();
  const TPlaneFigureCounts c = draw_tplane(fig, view, s.paving, s.detections, &crossings);
  const std::size_t nb_outer = s.paving.count(PavingTag::Inner) + s.paving.count(PavingTag::Boundary);
  ASSERT_GT(s.paving.count(PavingTag::Inner), 0u);
  ASSERT_GT(s.paving.count(PavingTag::Boundary), 0u);
  EXPECT_EQ(c.leaves, nb_outer);  // leaves of 15 px: all drawn
  EXPECT_EQ(c.components, 3u);
  EXPECT_EQ(c.markers, 0u);
  EXPECT_EQ(c.crossings, 1u);
  // Domain + leaves + diagonal + one polygon per contour loop + crossing.
  EXPECT_EQ(fig.nb_shapes() - before, 1 + nb_outer + 1 + nb_contour_loops(s.detections) + 1);

  const auto tags = parse_xml(fig.svg());
  EXPECT_EQ(count(tags, "rect", "outside"), 1u);
  EXPECT_EQ(count(tags, "rect", "inner"), s.paving.count(PavingTag::Inner));
  EXPECT_EQ(count(tags, "rect", "boundary"), s.paving.count(PavingTag::Boundary));
  EXPECT_EQ(count(tags, "polyline", "diagonal"), 1u);
  EXPECT_EQ(count(tags, "polygon", "proven"), 1u);
  EXPECT_EQ(count(tags, "polygon", "unproven"), 1u);
  EXPECT_EQ(count(tags, "polygon", "partial"), 1u);
  EXPECT_EQ(count(tags, "circle", "crossing"), 1u);
  EXPECT_TRUE(has_fill(tags, "proven", "#ff8c00"));
  EXPECT_TRUE(has_fill(tags, "unproven", "#000000"));
  EXPECT_TRUE(has_fill(tags, "partial", "#9e9e9e"));
  EXPECT_TRUE(has_fill(tags, "inner", paving_style(PavingTag::Inner).fill));
  EXPECT_TRUE(has_fill(tags, "boundary", paving_style(PavingTag::Boundary).fill));
  EXPECT_TRUE(has_fill(tags, "outside", paving_style(PavingTag::Outside).fill));
  // Proven last: drawn on top of the others.
  std::size_t last_unproven = 0, first_proven = 0;
  for (std::size_t k = 0; k < tags.size(); ++k) {
    const std::string cls = tags[k].attributes.count("class") ? tags[k].attributes.at("class") : "";
    if (cls == "unproven") last_unproven = k;
    if (cls == "proven" && first_proven == 0) first_proven = k;
  }
  EXPECT_LT(last_unproven, first_proven);
}

TEST(TPlaneFigure, SubPixelLeavesAreCoveredAndSmallComponentsMarked) {
  const Scene s;
  const IntervalVector view = box(0, 5000, 0, 5000);  // 0.12 px per unit: every leaf is sub-pixel
  Figure fig(view, 600);
  const TPlaneFigureCounts c = draw_tplane(fig, view, s.paving, s.detections);
  EXPECT_EQ(c.leaves, 0u);
  EXPECT_EQ(c.components, 3u);
  EXPECT_EQ(c.markers, 3u);
  const auto tags = parse_xml(fig.svg());
  EXPECT_EQ(count(tags, "circle", "proven-marker"), 1u);
  EXPECT_EQ(count(tags, "circle", "unproven-marker"), 1u);
  EXPECT_EQ(count(tags, "circle", "partial-marker"), 1u);
  EXPECT_EQ(count(tags, "rect", "inner"), 0u);
  // A smaller min_leaf_px brings the leaves back.
  Figure fig2(view, 600);
  TPlaneFigureOptions o;
  o.min_leaf_px = 0.01;
  EXPECT_EQ(draw_tplane(fig2, view, s.paving, s.detections, nullptr, o).leaves,
            s.paving.count(PavingTag::Inner) + s.paving.count(PavingTag::Boundary));
}

TEST(TPlaneFigure, AZoomDrawsOnlyWhatItSees) {
  const Scene s;
  const IntervalVector view = box(5.5, 7.5, 7.7, 9.5);  // part of the L only
  Figure fig(view, 400);
  const TPlaneFigureCounts c = draw_tplane(fig, view, s.paving, s.detections);
  EXPECT_EQ(c.components, 1u);
  EXPECT_EQ(c.leaves, 0u);  // the disk's leaves lie out of the view
  const auto tags = parse_xml(fig.svg());
  EXPECT_EQ(count(tags, "polygon", "unproven"), 1u);
  EXPECT_EQ(count(tags, "polyline", "diagonal"), 0u);  // t1 = t2 does not cross this view
}

TEST(TPlaneFigure, BadInputIsAnError) {
  const Scene s;
  Figure fig(box(0, 10, 0, 10), 300);
  EXPECT_THROW(draw_tplane(fig, IntervalVector{Interval(0, 10)}, s.paving, s.detections), Error);
  EXPECT_THROW(draw_tplane(fig, IntervalVector{Interval(0, 10), Interval::pos_reals()}, s.paving, s.detections),
               Error);
  TPlaneFigureOptions o;
  o.min_leaf_px = 0;
  EXPECT_THROW(draw_tplane(fig, box(0, 10, 0, 10), s.paving, s.detections, nullptr, o), Error);
  o = {};
  o.marker_px = std::nan("");
  EXPECT_THROW(draw_tplane(fig, box(0, 10, 0, 10), s.paving, s.detections, nullptr, o), Error);
}

TEST(LoopsMapFigure, DrawsPathTubeLoopsAndCrossings) {
  // A circle of radius 100 sampled 20000 times (sub-pixel steps).
  std::vector<Vector> path;
  for (int k = 0; k <= 20000; ++k) {
    const double a = 2 * std::numbers::pi * k / 20000.0;
    path.push_back({100 * std::cos(a), 100 * std::sin(a)});
  }
  std::vector<double> times;
  for (int k = 0; k <= 20000; ++k) times.push_back(k);
  // t-boxes: two pieces of the path each, except the last one (none).
  const std::vector<MapLoop> loops{{box(90, 110, -10, 10), LoopStatus::Proven, box(0, 100, 19900, 20000)},
                                   {box(-10, 10, 90, 110), LoopStatus::Unproven, box(4950, 5050, 14000, 14100)},
                                   {box(-110, -90, -10, 10), LoopStatus::Partial, box(9950, 10050, 10100, 10200)},
                                   {IntervalVector::empty(2), LoopStatus::Proven}};  // no map box: not drawn
  const std::vector<PathCrossing> crossings{{1, 2, 100, 0, 0, 2}};
  Figure fig = loops_map_figure(loops, &path, &times, nullptr, &crossings, "map", 500);
  const auto tags = parse_xml(fig.svg());
  EXPECT_EQ(count(tags, "rect", "proven"), 1u);
  EXPECT_EQ(count(tags, "rect", "unproven"), 1u);
  EXPECT_EQ(count(tags, "rect", "partial"), 1u);
  EXPECT_EQ(count(tags, "circle", "crossing"), 1u);
  EXPECT_TRUE(has_fill(tags, "proven", "#ff8c00"));
  EXPECT_TRUE(has_fill(tags, "unproven", "#000000"));
  ASSERT_EQ(count(tags, "polyline", "path"), 1u);
  EXPECT_EQ(count(tags, "polyline", "proven-projection"), 2u);
  EXPECT_EQ(count(tags, "polyline", "unproven-projection"), 2u);
  EXPECT_EQ(count(tags, "polyline", "partial-projection"), 2u);

  Figure f2(box(-120, 120, -120, 120), 500);
  LoopsMapOptions o;
  o.show_partial = false;
  const LoopsMapCounts c = draw_loops_map(f2, loops, &path, nullptr, nullptr, &crossings, o);
  EXPECT_EQ(c.loops, 2u);
  EXPECT_EQ(c.projections, 0u);  // no times: no projections
  EXPECT_EQ(c.crossings, 1u);
  // ~1300 px of circumference at >= 0.5 px per kept point: thinned, ends kept.
  EXPECT_LT(c.path_points, 3000u);
  EXPECT_GT(c.path_points, 600u);
}

TEST(LoopsMapFigure, PositionTubeIsDrawnAndFramed) {
  const auto td = TDomain::create(0.0, 10.0, 0.001);
  const TubeVector p(td, "(t + [-0.5, 0.5], 2*t + [-1, 1])");
  const std::vector<MapLoop> loops{{box(2, 3, 4, 6), LoopStatus::Proven}};
  Figure fig = loops_map_figure(loops, nullptr, nullptr, &p);
  const auto tags = parse_xml(fig.svg());
  EXPECT_GT(count(tags, "rect", "position"), 0u);
  EXPECT_LT(count(tags, "rect", "position"), 2000u);  // 10^4 sub-pixel slices aggregated
  EXPECT_EQ(count(tags, "rect", "proven"), 1u);
}

TEST(LoopsMapFigure, BadInputIsAnError) {
  Figure fig(box(0, 1, 0, 1), 100);
  const std::vector<Vector> bad_path{{0, 0}, {1, 1, 1}};
  EXPECT_THROW(draw_loops_map(fig, {}, &bad_path), DimensionError);
  const std::vector<MapLoop> bad_loops{{IntervalVector(3, Interval(0, 1)), LoopStatus::Proven}};
  EXPECT_THROW(draw_loops_map(fig, bad_loops), DimensionError);
  LoopsMapOptions o;
  o.path_px = -1;
  EXPECT_THROW(draw_loops_map(fig, {}, nullptr, nullptr, nullptr, nullptr, o), Error);
  const std::vector<Vector> path{{0, 0}, {1, 1}};
  const std::vector<double> short_times{0}, bad_times{1, 0};
  EXPECT_THROW(draw_loops_map(fig, {}, &path, &short_times), DimensionError);
  EXPECT_THROW(draw_loops_map(fig, {}, nullptr, &short_times), DimensionError);
  EXPECT_THROW(draw_loops_map(fig, {}, &path, &bad_times), Error);
}

TEST(TPlaneFigure, FromATPlaneOfALimacon) {
  // r = 1/2 + cos t: one crossing, at (2π/3, 4π/3); velocity known within 1e-3.
  const auto td = TDomain::create(0.0, 2 * std::numbers::pi, 0.01);
  const TubeVector v(td, "(-sin(t)/2 - sin(2*t) + [-0.001, 0.001], cos(t)/2 + cos(2*t) + [-0.001, 0.001])");
  TPlane tp(td);
  tp.compute_detections(0.01, v);
  tp.compute_proofs(v);
  ASSERT_GE(tp.nb_proofs(), 1u);
  const double pi = std::numbers::pi;
  const std::vector<PathCrossing> truth{{2 * pi / 3, 4 * pi / 3, 0, 0, 0, 2}};
  const auto tags = parse_xml(tplane_figure(tp, &truth, "limaçon").svg());
  EXPECT_EQ(count(tags, "polygon", "proven"), tp.nb_proofs());
  EXPECT_EQ(count(tags, "circle", "crossing"), 1u);
  EXPECT_EQ(detection_shapes(tp).size(), tp.nb_detections());
  const auto map = map_loops(tp);
  ASSERT_EQ(map.size(), tp.nb_detections());
  std::size_t proven_boxes = 0;
  for (const auto& m : map) proven_boxes += (m.status == LoopStatus::Proven && !m.map_box.is_empty()) ? 1 : 0;
  EXPECT_EQ(proven_boxes, tp.nb_proofs());
  const auto map_tags = parse_xml(loops_map_figure(tp).svg());
  EXPECT_EQ(count(map_tags, "rect", "proven"), tp.nb_proofs());
}
