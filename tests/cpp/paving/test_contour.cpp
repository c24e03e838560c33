// Contours of hand-made unions of boxes (the getContour of thesis Alg. 7) and
// a property test on random unions of grid cells.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "sillage/paving/component.h"
#include "sillage/paving/contour.h"

using namespace sillage;

namespace {

IntervalVector box(double a, double b, double c, double d) { return {Interval(a, b), Interval(c, d)}; }

std::vector<Point2> pts(std::initializer_list<std::pair<double, double>> l) {
  std::vector<Point2> r;
  for (auto [x, y] : l) r.push_back({x, y});
  return r;
}

void expect_closed(const ContourLoop& loop) {
  ASSERT_FALSE(loop.edges.empty());
  for (std::size_t k = 0; k < loop.edges.size(); ++k) {
    const auto& e = loop.edges[k];
    const auto& f = loop.edges[(k + 1) % loop.edges.size()];
    EXPECT_EQ(e.b, f.a) << "loop not closed at edge " << k;
    EXPECT_TRUE(e.a.x == e.b.x || e.a.y == e.b.y) << "edge not axis-aligned";
    EXPECT_NE(e.a, e.b);
  }
}

double signed_area(const ContourLoop& loop) {
  double s = 0;
  for (const auto& e : loop.edges) s += e.a.x * e.b.y - e.b.x * e.a.y;
  return s / 2;
}

// Bounded 4-connected components of the complement of the cells in the n x n grid.
std::size_t bounded_gaps(const std::set<std::pair<int, int>>& cells, int n) {
  std::set<std::pair<int, int>> seen;
  std::size_t count = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      if (cells.count({i, j}) || seen.count({i, j})) continue;
      bool bounded = true;
      std::vector<std::pair<int, int>> stack{{i, j}};
      seen.insert({i, j});
      while (!stack.empty()) {
        auto [a, c] = stack.back();
        stack.pop_back();
        for (auto [da, dc] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          const std::pair<int, int> q{a + da, c + dc};
          if (q.first < 0 || q.second < 0 || q.first >= n || q.second >= n) {
            bounded = false;
          } else if (!cells.count(q) && seen.insert(q).second) {
            stack.push_back(q);
          }
        }
      }
      count += bounded;
    }
  }
  return count;
}

}  // namespace

TEST(Contour, SingleBox) {
  auto loops = contour({box(0, 1, 0, 2)});
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_FALSE(loops[0].is_hole);
  EXPECT_EQ(loops[0].vertices(), pts({{0, 0}, {1, 0}, {1, 2}, {0, 2}}));
  expect_closed(loops[0]);
  EXPECT_EQ(loops[0].length(), 6.0);
  EXPECT_EQ(signed_area(loops[0]), 2.0);
  // Edges as degenerate boxes [b]: the first one is the bottom side.
  EXPECT_EQ(loops[0].edges[0].box(), box(0, 1, 0, 0));
}

TEST(Contour, LShapeMergesCollinearEdges) {
  const auto expected = pts({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  auto two = contour({box(0, 2, 0, 1), box(0, 1, 1, 2)});
  ASSERT_EQ(two.size(), 1u);
  EXPECT_EQ(two[0].vertices(), expected);
  // The same L made of three unit cells: internal sides cancel, sides merge.
  auto three = contour({box(1, 2, 0, 1), box(0, 1, 1, 2), box(0, 1, 0, 1)});
  ASSERT_EQ(three.size(), 1u);
  EXPECT_EQ(three[0].vertices(), expected);
  EXPECT_FALSE(three[0].is_hole);
  EXPECT_EQ(signed_area(three[0]), 3.0);
}

TEST(Contour, TJunctionsOfANonRegularPaving) {
  auto loops = contour({box(0, 2, 0, 1), box(0, 1, 1, 2), box(1, 2, 1, 2)});
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].vertices(), pts({{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
}

TEST(Contour, RingWithAHole) {
  std::vector<IntervalVector> ring;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (i != 1 || j != 1) ring.push_back(box(i, i + 1, j, j + 1));
    }
  }
  auto loops = contour(ring);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_FALSE(loops[0].is_hole);
  EXPECT_EQ(loops[0].vertices(), pts({{0, 0}, {3, 0}, {3, 3}, {0, 3}}));
  EXPECT_TRUE(loops[1].is_hole);  // clockwise
  EXPECT_EQ(loops[1].vertices(), pts({{1, 1}, {1, 2}, {2, 2}, {2, 1}}));
  EXPECT_EQ(signed_area(loops[0]) + signed_area(loops[1]), 8.0);
  EXPECT_EQ(connected_components(ring).size(), 1u);
}

TEST(Contour, TwoBoxesTouchingAtACorner) {
  std::vector<IntervalVector> b{box(1, 2, 1, 2), box(0, 1, 0, 1)};
  auto loops = contour(b);
  // The union is connected through (1, 1): one outer loop, through the pinch twice.
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_FALSE(loops[0].is_hole);
  EXPECT_EQ(loops[0].vertices(), pts({{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {1, 2}, {1, 1}, {0, 1}}));
  expect_closed(loops[0]);
  EXPECT_EQ(signed_area(loops[0]), 2.0);
  // A corner is enough to connect: one component.
  auto comps = connected_components(b);
  ASSERT_EQ(comps.size(), 1u);
  EXPECT_EQ(comps[0].hull, box(0, 2, 0, 2));
  EXPECT_EQ(comps[0].volume, 2.0);
  EXPECT_EQ(comps[0].boxes, b);
  EXPECT_EQ(comps[0].contour().size(), 1u);
  // Apart, they are two components with one loop each.
  auto apart = connected_components({box(0, 1, 0, 1), box(1.5, 2, 1.5, 2)});
  ASSERT_EQ(apart.size(), 2u);
  EXPECT_EQ(apart[1].boxes[0], box(1.5, 2, 1.5, 2));
}

TEST(Contour, HolePinchedAtACorner) {
  // 3x3 grid without the centre and without the top-right cell: the hole
  // touches the outside at the corner (2, 2), which belongs to the union.
  std::vector<IntervalVector> b;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if ((i == 1 && j == 1) || (i == 2 && j == 2)) continue;
      b.push_back(box(i, i + 1, j, j + 1));
    }
  }
  auto loops = contour(b);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_FALSE(loops[0].is_hole);
  EXPECT_EQ(loops[0].vertices(), pts({{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 3}, {0, 3}}));
  EXPECT_TRUE(loops[1].is_hole);
  EXPECT_EQ(loops[1].vertices(), pts({{1, 1}, {1, 2}, {2, 2}, {2, 1}}));
  EXPECT_EQ(signed_area(loops[0]), 8.0);
  EXPECT_EQ(signed_area(loops[1]), -1.0);
}

TEST(Contour, DegenerateAndEmptyBoxesAreIgnored) {
  auto loops = contour({box(0, 1, 0, 1), box(1, 1, 0, 5), IntervalVector::empty(2)});
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].edges.size(), 4u);
  EXPECT_TRUE(contour({}).empty());
}

TEST(Contour, InvalidInput) {
  EXPECT_THROW(contour({IntervalVector{Interval(0, 1)}}), DimensionError);
  EXPECT_THROW(contour({box(0, 1, 0, 1), IntervalVector{Interval(0, 1), Interval(0, 1), Interval(0, 1)}}),
               DimensionError);
  EXPECT_THROW(contour({IntervalVector{Interval(0, 1), Interval::pos_reals()}}), Error);
  EXPECT_THROW(contour({box(0, 2, 0, 1), box(1, 3, 0, 1)}), Error);  // overlapping sides
}

TEST(Contour, RandomGridUnions) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 6;
    std::set<std::pair<int, int>> cells;
    std::vector<IntervalVector> b;
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        if (rng() % 2) {
          cells.insert({i, j});
          b.push_back(box(i, i + 1, j, j + 1));
        }
      }
    }
    auto inside = [&](double x, double y) {
      return cells.count({static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y))}) > 0;
    };
    auto loops = contour(b);
    double area = 0, length = 0;
    for (const auto& l : loops) {
      expect_closed(l);
      area += signed_area(l);
      length += l.length();
      EXPECT_EQ(l.is_hole, signed_area(l) < 0);
      // The union lies on the left of every edge, not on its right.
      for (const auto& e : l.edges) {
        const double dx = (e.b.x > e.a.x) - (e.b.x < e.a.x), dy = (e.b.y > e.a.y) - (e.b.y < e.a.y);
        for (double t = 0.5; t < e.length(); t += 1.0) {
          const double mx = e.a.x + dx * t, my = e.a.y + dy * t;
          EXPECT_TRUE(inside(mx - 0.25 * dy, my + 0.25 * dx));
          EXPECT_FALSE(inside(mx + 0.25 * dy, my - 0.25 * dx));
        }
      }
      // Maximal segments: consecutive edges turn.
      for (std::size_t k = 0; k < l.edges.size(); ++k) {
        const auto& e = l.edges[k];
        const auto& f = l.edges[(k + 1) % l.edges.size()];
        EXPECT_FALSE((e.a.x == e.b.x) == (f.a.x == f.b.x));
      }
    }
    EXPECT_EQ(area, static_cast<double>(cells.size()));
    // One outer loop per 8-connected component, one hole loop per bounded
    // 4-connected component of the complement.
    std::size_t outer = 0, holes = 0;
    for (const auto& l : loops) (l.is_hole ? holes : outer)++;
    EXPECT_EQ(outer, connected_components(b).size());
    EXPECT_EQ(holes, bounded_gaps(cells, n));
    // Perimeter: count the cell sides with no neighbour.
    double perimeter = 0;
    for (auto [i, j] : cells) {
      perimeter += !cells.count({i + 1, j}) + !cells.count({i - 1, j}) + !cells.count({i, j + 1}) +
                   !cells.count({i, j - 1});
    }
    EXPECT_EQ(length, perimeter);
  }
}
