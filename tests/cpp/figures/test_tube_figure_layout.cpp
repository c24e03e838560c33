// Tube figures as a reader sees them: axes named after the variables, map
// windows that hold the landmarks, the truth drawn over the tube.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sillage/figures/tube_figure.h"
#include "svg_check.h"

using namespace sillage;
using namespace sillage::test;

namespace {

// The text of the first <text> element of class `cls` (empty if none).
std::string text_of(const std::string& svg, const std::string& cls) {
  const auto at = svg.find("class=\"" + cls + "\"");
  if (at == std::string::npos) return "";
  const auto open = svg.find('>', at) + 1;
  return svg.substr(open, svg.find("</text>", open) - open);
}

}  // namespace

TEST(TubeFigureLayout, AxisLabelsNameTheVariables) {
  auto td = TDomain::create(0, 1, 0.1);
  Tube v(td, Interval(0, 1));
  EXPECT_EQ(text_of(tube_figure(v, "v", {}, nullptr, 600, 300, "v (m/s)").svg(), "y-label"), "v (m/s)");
  EXPECT_EQ(text_of(tube_figure(v).svg(), "x-label"), "t (s)");
  TubeVector x(td, "(t, 2 * t, 3 * t)");
  const std::string map = tube_vector_figure(x, 0, 2).svg();
  EXPECT_EQ(text_of(map, "x-label"), "x1");
  EXPECT_EQ(text_of(map, "y-label"), "x3");
  const std::string named = tube_vector_figure(x, 0, 1, "", {}, nullptr, nullptr, 600, nullptr, "east (m)", "north (m)").svg();
  EXPECT_EQ(text_of(named, "x-label"), "east (m)");
  EXPECT_EQ(text_of(named, "y-label"), "north (m)");
}

TEST(TubeFigureLayout, MapWindowHoldsEveryLandmark) {
  auto td = TDomain::create(0, 6, 0.1);
  TubeVector x(td, "(cos(t) + [-0.1, 0.1], sin(t) + [-0.1, 0.1])");
  const std::vector<Vector> marks{{3.0, 0.5}, {-2.0, -4.0}, {0.0, 0.0}};
  Figure fig = tube_vector_figure(x, 0, 1, "map", {}, nullptr, nullptr, 400, &marks);
  const auto els = parse_xml(fig.svg());
  Element frame;
  std::vector<Element> dots;
  for (const auto& e : els) {
    if (!e.attributes.count("class")) continue;
    if (e.attributes.at("class") == "frame") frame = e;
    if (e.attributes.at("class") == "landmark") dots.push_back(e);
  }
  ASSERT_EQ(dots.size(), marks.size());
  const double fx = std::stod(frame.attributes.at("x")), fy = std::stod(frame.attributes.at("y"));
  const double fw = std::stod(frame.attributes.at("width")), fh = std::stod(frame.attributes.at("height"));
  for (const auto& d : dots) {
    const double cx = std::stod(d.attributes.at("cx")), cy = std::stod(d.attributes.at("cy"));
    EXPECT_TRUE(cx >= fx && cx <= fx + fw && cy >= fy && cy <= fy + fh) << cx << ", " << cy;
  }
  // Landmarks and truth: distinct styles, both in the legend.
  const TubeStyle st;
  EXPECT_NE(st.landmarks.fill, st.truth.stroke);
  const std::vector<Vector> in_3d{{1.0, 2.0, 3.0}};
  EXPECT_THROW(tube_vector_figure(x, 0, 1, "", {}, nullptr, nullptr, 400, &in_3d), DimensionError);
}

TEST(TubeFigureLayout, TruthDrawnOverTheTubeAndTranslucentGates) {
  auto td = TDomain::create(0, 6, 0.5);
  TubeVector x(td, "(cos(t) + [-0.1, 0.1], sin(t) + [-0.1, 0.1])");
  Trajectory a("cos(t)", Interval(0, 6)), b("sin(t)", Interval(0, 6));
  const std::string svg = tube_vector_figure(x, 0, 1, "path", {}, &a, &b).svg();
  const auto truth = svg.find("class=\"truth\"");
  ASSERT_NE(truth, std::string::npos);
  EXPECT_GT(truth, svg.rfind("class=\"slice\""));
  EXPECT_GT(truth, svg.find("class=\"final\""));
  const TubeStyle st;
  EXPECT_LT(st.final.opacity, 0.5);
  EXPECT_LT(st.initial.opacity, 0.5);
}
