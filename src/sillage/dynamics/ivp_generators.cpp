// Generators of CtcIvp's zonotopes: splitting, boxing, reduction (ivp_generators.h).
#include "sillage/dynamics/ivp_generators.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sillage::detail {

Interval symmetric(const Interval& x) { return Interval(-x.mag(), x.mag()); }

Vector split_generator(const IntervalVector& g, IntervalVector& extra) {
  Vector mid = g.mid();
  for (std::size_t i = 0; i < g.size(); ++i) extra[i] += symmetric(g[i] - Interval(mid[i]));
  return mid;
}

void box_to_generators(const IntervalVector& box, std::vector<Vector>& G) {
  for (std::size_t i = 0; i < box.size(); ++i) {
    const double m = box[i].mag();
    if (m == 0.0) continue;
    Vector g(box.size(), 0.0);
    g[i] = m;
    G.push_back(std::move(g));
  }
}

namespace {

// The active state with the largest |g_i|, n if g has no active part.
std::size_t leading_active(const Vector& g, const std::vector<bool>& passive) {
  std::size_t best = g.size();
  double top = 0.0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (!passive[i] && std::abs(g[i]) > top) top = std::abs(g[i]), best = i;
  }
  return best;
}

// An estimate of what merging a and b (both positive on `axis`) adds to the
// box: |a_i d_b - b_i d_a| / (d_a + d_b) per state, twice; an active
// residual costs far more (it would be sheared later).
double merge_cost(const Vector& a, const Vector& b, std::size_t axis, const std::vector<bool>& passive) {
  const double da = a[axis], db = b[axis];
  double cost = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double r = 2.0 * std::abs(a[i] * db - b[i] * da) / (da + db);
    cost += passive[i] ? r : 1e6 * r;
  }
  return cost;
}

// a w_a + b w_b ⊆ m w + residual box (rigorous: ḡ and the residuals in
// interval arithmetic); a and b positive on `axis`.
Vector merge_pair(const Vector& a, const Vector& b, std::size_t axis, IntervalVector& extra) {
  const std::size_t n = a.size();
  IntervalVector sum(n);
  for (std::size_t i = 0; i < n; ++i) sum[i] = Interval(a[i]) + Interval(b[i]);
  const Vector m = sum.mid();
  const Interval D = Interval(a[axis]) + Interval(b[axis]);
  for (std::size_t i = 0; i < n; ++i) {
    const Interval gbar = Interval(m[i]) / D;
    extra[i] += symmetric(Interval(a[i]) - Interval(a[axis]) * gbar);
    extra[i] += symmetric(Interval(b[i]) - Interval(b[axis]) * gbar);
  }
  return m;
}

// The merging stage; G keeps its order (birth order) otherwise.
void merge_along_active(std::vector<Vector>& G, IntervalVector& extra, const std::vector<bool>& passive,
                        std::size_t target) {
  const std::size_t n = extra.size();
  const bool some_passive = std::find(passive.begin(), passive.end(), true) != passive.end();
  const bool some_active = std::find(passive.begin(), passive.end(), false) != passive.end();
  if (!some_passive || !some_active) return;
  std::vector<std::vector<std::size_t>> by_axis(n);
  std::vector<bool> gone(G.size(), false);
  std::size_t count = 0;
  for (std::size_t j = 0; j < G.size(); ++j) {
    Vector& g = G[j];
    const std::size_t axis = leading_active(g, passive);
    if (axis == n) {  // passive only: boxing it loses nothing later
      for (std::size_t i = 0; i < n; ++i) extra[i] += symmetric(Interval(g[i]));
      gone[j] = true;
      continue;
    }
    if (g[axis] < 0.0) {
      for (double& x : g) x = -x;  // w ↦ -w
    }
    by_axis[axis].push_back(j);
    ++count;
  }
  struct Pair {
    double cost;
    std::size_t first, second, axis;
  };
  std::vector<Pair> pairs;
  for (std::size_t axis = 0; axis < n; ++axis) {
    const std::vector<std::size_t>& js = by_axis[axis];
    for (std::size_t k = 0; k + 1 < js.size(); ++k) {
      pairs.push_back({merge_cost(G[js[k]], G[js[k + 1]], axis, passive), js[k], js[k + 1], axis});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.cost < b.cost; });
  std::vector<bool> used(G.size(), false);
  for (const Pair& p : pairs) {
    if (count <= target) break;
    if (used[p.first] || used[p.second]) continue;
    used[p.first] = used[p.second] = true;
    G[p.first] = merge_pair(G[p.first], G[p.second], p.axis, extra);
    gone[p.second] = true;
    --count;
  }
  std::vector<Vector> kept;
  kept.reserve(count);
  for (std::size_t j = 0; j < G.size(); ++j) {
    if (!gone[j]) kept.push_back(std::move(G[j]));
  }
  G = std::move(kept);
}

// Girard's criterion: the cheapest to box (‖g‖₁ − ‖g‖∞, zero along an
// axis) become a box: their correlation with the rest is lost, not their bound.
void box_cheapest(std::vector<Vector>& G, IntervalVector& extra, std::size_t target) {
  if (G.size() <= target) return;
  std::vector<std::pair<double, std::size_t>> cost;
  for (std::size_t j = 0; j < G.size(); ++j) {
    double l1 = 0.0, linf = 0.0;
    for (double x : G[j]) l1 += std::abs(x), linf = std::max(linf, std::abs(x));
    cost.emplace_back(l1 - linf, j);
  }
  std::sort(cost.begin(), cost.end());
  std::vector<bool> gone(G.size(), false);
  for (std::size_t k = 0; k < G.size() - target; ++k) {
    const Vector& g = G[cost[k].second];
    for (std::size_t i = 0; i < g.size(); ++i) extra[i] += symmetric(Interval(g[i]));
    gone[cost[k].second] = true;
  }
  std::vector<Vector> kept;
  for (std::size_t j = 0; j < G.size(); ++j) {
    if (!gone[j]) kept.push_back(std::move(G[j]));
  }
  G = std::move(kept);
}

}  // namespace

void reduce_generators(std::vector<Vector>& G, IntervalVector& extra, const std::vector<bool>& passive,
                       std::size_t max_generators) {
  if (G.size() <= max_generators) return;
  const std::size_t target = max_generators - max_generators / 4;
  // Each round merges disjoint neighbours (at most halves each class).
  for (std::size_t before = 0; G.size() > target && G.size() != before;) {
    before = G.size();
    merge_along_active(G, extra, passive, target);
  }
  box_cheapest(G, extra, target);
}

}  // namespace sillage::detail
