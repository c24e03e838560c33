// Connected components: the tree-based search of Paving::components and the
// sweep of connected_components against an all-pairs brute force.
#include <gtest/gtest.h>

#include <random>

#include "sillage/paving/sivia.h"

using namespace sillage;

namespace {

// Component index of each box by the O(n^2) definition.
std::vector<std::size_t> brute_force_labels(const std::vector<IntervalVector>& b) {
  std::vector<std::size_t> label(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) label[i] = i;
  bool changed = true;
  while (changed) {
    changed = false;
    for (std::size_t i = 0; i < b.size(); ++i) {
      for (std::size_t j = 0; j < b.size(); ++j) {
        if (b[i].intersects(b[j]) && label[j] < label[i]) {
          label[i] = label[j];
          changed = true;
        }
      }
    }
  }
  return label;
}

// The components as lists of boxes, in the order of the brute force.
std::vector<std::vector<IntervalVector>> brute_force(const std::vector<IntervalVector>& b) {
  const auto label = brute_force_labels(b);
  std::vector<std::vector<IntervalVector>> r;
  std::vector<std::size_t> slot(b.size(), b.size());
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (slot[label[i]] == b.size()) {
      slot[label[i]] = r.size();
      r.emplace_back();
    }
    r[slot[label[i]]].push_back(b[i]);
  }
  return r;
}

}  // namespace

TEST(Components, PavingMatchesBruteForce) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 12; ++trial) {
    // A union of three random disks of random radii: 1 to 3 components.
    const double cx[3] = {u(rng), u(rng), u(rng)}, cy[3] = {u(rng), u(rng), u(rng)};
    const double r[3] = {0.1 + 0.3 * std::abs(u(rng)), 0.1 + 0.3 * std::abs(u(rng)), 0.1 + 0.3 * std::abs(u(rng))};
    auto sep = [&](IntervalVector& x_in, IntervalVector& x_out) {
      bool all_out = true, one_in = false;
      for (int k = 0; k < 3; ++k) {
        const Interval d = sqr(x_in[0] - Interval(cx[k])) + sqr(x_in[1] - Interval(cy[k]));
        all_out = all_out && d.lb() > r[k] * r[k];
        one_in = one_in || d.ub() < r[k] * r[k];
      }
      if (all_out) x_out.set_empty();
      if (one_in) x_in.set_empty();
    };
    auto p = sivia_separator(IntervalVector{Interval(-1.5, 1.5), Interval(-1.5, 1.5)}, sep, 0.05);
    const auto outer = p.outer();
    const auto comps = p.components();
    const auto ref = brute_force(outer);
    ASSERT_EQ(comps.size(), ref.size());
    EXPECT_GE(comps.size(), 1u);
    EXPECT_LE(comps.size(), 3u);
    std::size_t total = 0;
    for (std::size_t k = 0; k < comps.size(); ++k) {
      EXPECT_EQ(comps[k].boxes, ref[k]);
      total += comps[k].size();
      IntervalVector h = IntervalVector::empty(2);
      for (const auto& b : ref[k]) h |= b;
      EXPECT_EQ(comps[k].hull, h);
      // Each 2-D component has exactly one outer loop.
      std::size_t outer_loops = 0;
      for (const auto& l : comps[k].contour()) outer_loops += !l.is_hole;
      EXPECT_EQ(outer_loops, 1u);
    }
    EXPECT_EQ(total, outer.size());
    // The generic sweep agrees with the tree search.
    const auto sweep = connected_components(outer);
    ASSERT_EQ(sweep.size(), comps.size());
    for (std::size_t k = 0; k < comps.size(); ++k) EXPECT_EQ(sweep[k].boxes, comps[k].boxes);
  }
}

TEST(Components, RandomBoxesIn3D) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0, 10), w(0, 1.5);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<IntervalVector> boxes;
    for (int k = 0; k < 40; ++k) {
      IntervalVector b(3);
      for (std::size_t d = 0; d < 3; ++d) {
        const double a = std::floor(u(rng) * 4) / 4;  // on a grid, so that boxes touch
        b[d] = Interval(a, a + std::floor(w(rng) * 4 + 1) / 4);
      }
      boxes.push_back(b);
    }
    const auto comps = connected_components(boxes);
    const auto ref = brute_force(boxes);
    ASSERT_EQ(comps.size(), ref.size());
    for (std::size_t k = 0; k < comps.size(); ++k) EXPECT_EQ(comps[k].boxes, ref[k]);
  }
}

TEST(Components, InvalidInput) {
  EXPECT_THROW(connected_components({IntervalVector(2), IntervalVector(3)}), DimensionError);
  EXPECT_THROW(connected_components({IntervalVector(2)}, {PavingTag::Inner, PavingTag::Inner}), DimensionError);
  EXPECT_TRUE(connected_components({}).empty());
  EXPECT_TRUE(connected_components({IntervalVector::empty(2)}).empty());
}
