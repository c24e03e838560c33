// SVG figures: well-formedness (parsed back by a tiny XML checker), element
// counts, coordinates, escaping and the HTML index.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "sillage/figures/figure.h"
#include "sillage/figures/html.h"
#include "sillage/paving/sivia.h"
#include "svg_check.h"

using namespace sillage;
using namespace sillage::test;

namespace {

IntervalVector box(double a, double b, double c, double d) { return {Interval(a, b), Interval(c, d)}; }

}  // namespace

TEST(Figure, EmptyFigureIsWellFormed) {
  Figure fig(box(-10, 10, -5, 5), 400);
  fig.set_title("A <title> & more");
  fig.set_labels("x1", "x2");
  const auto els = parse_xml(fig.svg());
  ASSERT_FALSE(els.empty());
  EXPECT_EQ(els[0].name, "svg");
  EXPECT_EQ(count(els, "rect", "background"), 1u);
  EXPECT_EQ(count(els, "rect", "frame"), 1u);
  // Ticks every 5 on x (-10..10) and every 2 on y (-4..4).
  EXPECT_EQ(count(els, "line"), 5u + 5u);
  EXPECT_NE(fig.svg().find("A &lt;title&gt; &amp; more"), std::string::npos);
  EXPECT_EQ(fig.px(-10), 60.0);
  EXPECT_EQ(fig.px(10), 460.0);
  EXPECT_EQ(fig.py(5), 36.0);
  EXPECT_EQ(fig.py(-5), 236.0);  // the aspect ratio is kept: 200 px high
}

TEST(Figure, BoxesAreClippedAndCounted) {
  Figure fig(box(0, 10, 0, 10), 100, 100);
  fig.draw_box(box(1, 2, 3, 5), {"red", "black", 1, 0.5, "mine"});
  fig.draw_box(box(20, 30, 0, 1));                                  // out of view: nothing
  fig.draw_box(IntervalVector::empty(2));                           // nothing
  fig.draw_box(IntervalVector{Interval::pos_reals(), Interval(2, 3)});  // clipped to x in [0, 10]
  EXPECT_EQ(fig.nb_shapes(), 2u);
  const auto els = parse_xml(fig.svg());
  ASSERT_EQ(count(els, "rect", "mine"), 1u);
  for (const auto& e : els) {
    if (e.name == "rect" && e.attributes.count("class") && e.attributes.at("class") == "mine") {
      EXPECT_EQ(e.attributes.at("x"), "70.00");
      EXPECT_EQ(e.attributes.at("y"), "86.00");
      EXPECT_EQ(e.attributes.at("width"), "10.00");
      EXPECT_EQ(e.attributes.at("height"), "20.00");
      EXPECT_EQ(e.attributes.at("fill"), "red");
      EXPECT_EQ(e.attributes.at("fill-opacity"), "0.50");
    }
  }
  EXPECT_THROW(fig.draw_box(IntervalVector{Interval(0, 1)}), DimensionError);
}

TEST(Figure, PavingHasOneRectPerLeafWithThesisColours) {
  auto f = [](const IntervalVector& x) { return IntervalVector{sqr(x[0]) + sqr(x[1])}; };
  auto p = sivia(box(-2, 2, -2, 2), f, Interval(0, 1), 0.1);
  Figure fig(box(-2, 2, -2, 2), 300);
  fig.draw_paving(p);
  fig.draw_contour(p.components()[0].contour());
  const auto els = parse_xml(fig.svg());
  EXPECT_EQ(count(els, "rect", "inner"), p.count(PavingTag::Inner));
  EXPECT_EQ(count(els, "rect", "boundary"), p.count(PavingTag::Boundary));
  EXPECT_EQ(count(els, "rect", "outside"), p.count(PavingTag::Outside));
  EXPECT_EQ(count(els, "polygon"), 1u);
  EXPECT_EQ(paving_style(PavingTag::Inner).css_class, "inner");
  Figure no_outside(box(-2, 2, -2, 2), 300);
  no_outside.draw_paving(p, false);
  EXPECT_EQ(no_outside.nb_shapes(), p.outer().size());
}

TEST(Figure, RingsPointsPolylinesAndText) {
  Figure fig(box(-10, 10, -10, 10), 200);
  fig.draw_ring({8.0, 5.0}, Interval(9.03, 9.83), {"#ffcc00", "none", 0, 0.4, "ring"});
  fig.draw_ring({7.0, 2.2}, Interval(-1, 2));  // a disk
  fig.draw_ring({0.0, 0.0}, Interval::empty());
  fig.draw_point({0.0, 0.0}, 4);
  fig.draw_polyline({{0, 0}, {1, 1}, {2, 0}}, {"none", "blue", 2, 1, ""});
  fig.draw_polyline({{0, 0}, {1, 1}, {2, 0}}, {}, true);
  fig.draw_text({1.0, 1.0}, "robot <R>");
  const auto els = parse_xml(fig.svg());
  ASSERT_EQ(count(els, "path"), 2u);
  EXPECT_EQ(count(els, "path", "ring"), 1u);
  EXPECT_EQ(count(els, "circle"), 1u);
  EXPECT_EQ(count(els, "polyline"), 1u);
  EXPECT_EQ(count(els, "polygon"), 1u);
  for (const auto& e : els) {
    if (e.name == "path" && e.attributes.count("class")) {
      // Two ellipses (outer and inner radius) in an even-odd path.
      const std::string& d = e.attributes.at("d");
      EXPECT_EQ(std::count(d.begin(), d.end(), 'M'), 2);
      EXPECT_EQ(e.attributes.at("fill-rule"), "evenodd");
    }
  }
  EXPECT_NE(fig.svg().find("robot &lt;R&gt;"), std::string::npos);
  EXPECT_THROW(fig.draw_ring({0.0}, Interval(1, 2)), DimensionError);
  EXPECT_THROW(fig.draw_ring({0.0, 0.0}, Interval::pos_reals()), Error);
  EXPECT_THROW(fig.draw_point({std::nan(""), 0.0}), Error);
}

TEST(Figure, ProjectionAndInvalidViews) {
  Figure fig(box(0, 1, 0, 1), 100, 100);
  fig.set_projection(2, 0);
  fig.draw_box(IntervalVector{Interval(0, 0.5), Interval(5, 6), Interval(0.5, 1)});
  EXPECT_EQ(fig.nb_shapes(), 1u);
  EXPECT_THROW(fig.draw_box(box(0, 1, 0, 1)), DimensionError);
  EXPECT_THROW(fig.set_projection(1, 1), Error);
  EXPECT_THROW(Figure(IntervalVector{Interval(0, 1)}), DimensionError);
  EXPECT_THROW(Figure(box(0, 0, 0, 1)), Error);
  EXPECT_THROW(Figure(IntervalVector{Interval(0, 1), Interval::pos_reals()}), Error);
  EXPECT_THROW(Figure(box(0, 1, 0, 1), -5), Error);
  EXPECT_THROW(Figure(box(0, 1, 0, 1), std::nan("")), Error);
}

TEST(Html, IndexGathersFiguresWithCaptions) {
  Figure a(box(0, 1, 0, 1)), b(box(0, 2, 0, 1));
  a.draw_box(box(0.2, 0.4, 0.2, 0.4));
  Html html("Set inversion & friends");
  html.add(a, "a.svg", "A box <small>");
  html.add_text("Some words.");
  html.add(b, "b.svg", "Nothing");
  EXPECT_EQ(html.nb_figures(), 2u);
  EXPECT_THROW(html.add(a, "a.svg", "again"), Error);
  EXPECT_THROW(html.add(a, "../x.svg", "escape"), Error);
  EXPECT_THROW(html.add(a, "x.png", "not svg"), Error);
  const std::string index = html.index();
  const auto els = parse_xml(index);  // also well-formed XML (void elements self-closed)
  EXPECT_EQ(count(els, "img"), 2u);
  EXPECT_EQ(count(els, "figcaption"), 2u);
  EXPECT_NE(index.find("<img src=\"a.svg\""), std::string::npos);
  EXPECT_NE(index.find("Figure 2: Nothing"), std::string::npos);
  EXPECT_NE(index.find("A box &lt;small&gt;"), std::string::npos);
  const auto dir = std::filesystem::temp_directory_path() / "sillage_test_html";
  std::filesystem::remove_all(dir);
  html.save(dir.string());
  EXPECT_TRUE(std::filesystem::exists(dir / "index.html"));
  std::ifstream f(dir / "a.svg");
  std::stringstream ss;
  ss << f.rdbuf();
  EXPECT_EQ(ss.str(), a.svg());
  EXPECT_EQ(count(parse_xml(ss.str()), "rect"), 4u);  // background, clip, box, frame
  std::filesystem::remove_all(dir);
  EXPECT_THROW(html.save("/proc/sillage_cannot_write_here"), Error);
}
