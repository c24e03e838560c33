#include "sillage/error.h"
#include "sillage/paving/paving_builder.h"

#include <tbb/parallel_invoke.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

namespace sillage::detail {

namespace {

// A piece of pre-order node array, with sub-chunks grown by other tasks
// spliced in at given local positions.
struct Chunk {
  struct Graft {
    std::size_t at;  // number of local nodes before the graft
    std::unique_ptr<Chunk> chunk;
  };
  std::vector<Paving::Node> nodes;
  std::vector<Interval> bounds;
  std::vector<Graft> grafts;
  std::size_t total = 0;  // nodes including the grafts
};

std::uint32_t offset(std::size_t from, std::size_t to, const char* where) {
  if (to - from > std::numeric_limits<std::uint32_t>::max()) {
    throw Error(std::string(where) + ": paving too large (a subtree exceeds 2^32 nodes)");
  }
  return static_cast<std::uint32_t>(to - from);
}

class Builder {
 public:
  Builder(const Separation& separate, double eps, std::size_t dim, bool parallel, BudgetMeter& meter,
          const char* where)
      : separate_(separate), eps_(eps), dim_(dim), parallel_(parallel), meter_(meter), where_(where) {}

  // Grows the subtree of `root` into c, in pre-order. Iterative below the
  // parallel levels (an explicit stack), so that deep trees (tiny eps) never
  // exhaust the call stack.
  void grow(Chunk& c, const IntervalVector& root, int root_depth) const {
    struct Item {
      IntervalVector x;
      int depth;
      std::size_t parent = 0, parent_pos = 0;  // for a right child: where to patch the offset
      bool is_right = false;
    };
    std::vector<Item> stack;
    stack.push_back({root, root_depth});
    while (!stack.empty()) {
      Item it = std::move(stack.back());
      stack.pop_back();
      if (it.is_right) c.nodes[it.parent].right = offset(it.parent_pos, c.total, where_);
      if (meter_.stopped()) {  // budget spent or cancelled: the box is left undetermined
        push(c, it.x, PavingTag::Boundary);
        continue;
      }
      IntervalVector r;
      if (!settle(c, it.x, r)) continue;
      const std::size_t k = widest(r);
      if (r[k].diam() < eps_ || r[k].is_degenerate() || meter_.stopped()) {
        push(c, r, PavingTag::Boundary);
        continue;
      }
      auto [lo, hi] = r.bisect(k, 0.5);
      if (lo == r || hi == r) {  // two consecutive floats: cannot split
        push(c, r, PavingTag::Boundary);
        continue;
      }
      const std::size_t pos = c.total;
      const std::size_t node = push(c, r, Paving::kInternal);
      if (parallel_ && it.depth < kParallelDepth) {
        auto left = std::make_unique<Chunk>(), right = std::make_unique<Chunk>();
        tbb::parallel_invoke([&] { grow(*left, lo, it.depth + 1); }, [&] { grow(*right, hi, it.depth + 1); });
        c.nodes[node].right = offset(pos, pos + 1 + left->total, where_);
        c.total += left->total + right->total;
        c.grafts.push_back({c.nodes.size(), std::move(left)});
        c.grafts.push_back({c.nodes.size(), std::move(right)});
      } else {
        stack.push_back({std::move(hi), it.depth + 1, node, pos, true});
        stack.push_back({std::move(lo), it.depth + 1});
      }
    }
  }

 private:
  // Appends a node; returns its local index. Counted against the budget, but
  // never refused: once the budget is spent, the boxes being processed end
  // as Boundary leaves (grow), so that the paving stays an enclosure.
  std::size_t push(Chunk& c, const IntervalVector& x, std::uint8_t kind) const {
    meter_.try_add();
    c.nodes.push_back({0, kind});
    c.bounds.insert(c.bounds.end(), x.begin(), x.end());
    ++c.total;
    return c.nodes.size() - 1;
  }
  std::size_t push(Chunk& c, const IntervalVector& x, PavingTag tag) const {
    return push(c, x, static_cast<std::uint8_t>(tag));
  }

  // Shrinks cur to target (a sub-box) by a chain of cuts; every removed slab
  // is a leaf tagged `tag`, stored as the first child of its chain node.
  void cut_to(Chunk& c, IntervalVector& cur, const IntervalVector& target, PavingTag tag) const {
    for (std::size_t d = 0; d < dim_; ++d) {
      for (int side = 0; side < 2; ++side) {
        const double a = cur[d].lb(), b = cur[d].ub();
        const double t = side == 0 ? target[d].lb() : target[d].ub();
        if (side == 0 ? !(t > a) : !(t < b)) continue;
        IntervalVector slab(cur);
        slab[d] = side == 0 ? Interval::from_bounds_unchecked(a, t) : Interval::from_bounds_unchecked(t, b);
        const std::size_t k = push(c, cur, Paving::kInternal);
        c.nodes[k].right = 2;
        push(c, slab, tag);
        cur[d] = side == 0 ? Interval::from_bounds_unchecked(t, b) : Interval::from_bounds_unchecked(a, t);
      }
    }
  }

  // Separates x: stores the proven parts (chains of slabs, or a whole leaf)
  // and returns true with the undetermined remainder in r, false if none.
  bool settle(Chunk& c, const IntervalVector& x, IntervalVector& r) const {
    IntervalVector x_in(x), x_out(x);
    separate_(x_in, x_out);
    if (x_in.size() != dim_ || x_out.size() != dim_) {
      throw DimensionError(std::string(where_) + ": the separation returned boxes of dimension " +
                           std::to_string(x_in.size()) + " and " + std::to_string(x_out.size()) + ", expected " +
                           std::to_string(dim_));
    }
    x_out &= x;  // a contractor only shrinks; enforce it
    if (x_out.is_empty()) {
      push(c, x, PavingTag::Outside);
      return false;
    }
    r = x;
    cut_to(c, r, x_out, PavingTag::Outside);
    x_in &= r;
    if (x_in.is_empty()) {
      push(c, r, PavingTag::Inner);
      return false;
    }
    cut_to(c, r, x_in, PavingTag::Inner);
    return true;
  }

  // The component of largest diameter; the first one on ties.
  std::size_t widest(const IntervalVector& r) const {
    std::size_t k = 0;
    for (std::size_t d = 1; d < dim_; ++d) {
      if (r[d].diam() > r[k].diam()) k = d;
    }
    return k;
  }

  const Separation& separate_;
  double eps_;
  std::size_t dim_;
  bool parallel_;
  BudgetMeter& meter_;
  const char* where_;
};

void flatten(const Chunk& c, std::vector<Paving::Node>& nodes, std::vector<Interval>& bounds, std::size_t dim) {
  std::size_t g = 0;
  for (std::size_t i = 0; i <= c.nodes.size(); ++i) {
    for (; g < c.grafts.size() && c.grafts[g].at == i; ++g) flatten(*c.grafts[g].chunk, nodes, bounds, dim);
    if (i == c.nodes.size()) break;
    nodes.push_back(c.nodes[i]);
    bounds.insert(bounds.end(), c.bounds.begin() + static_cast<std::ptrdiff_t>(i * dim),
                  c.bounds.begin() + static_cast<std::ptrdiff_t>((i + 1) * dim));
  }
}

}  // namespace

void check_sivia_input(const IntervalVector& x0, double eps, const char* where) {
  if (!(eps > 0)) throw Error(std::string(where) + ": eps must be > 0, got " + number_text(eps));
  if (x0.size() == 0) throw DimensionError(std::string(where) + ": the initial box has dimension 0");
  if (x0.is_unbounded()) {
    throw Error(std::string(where) + ": the initial box " + x0.str() + " must be bounded");
  }
}

void image_test(const IntervalVector& fx, const IntervalVector& y, bool may_be_inner, IntervalVector& x_in,
                IntervalVector& x_out, const char* where) {
  if (fx.size() != y.size()) {
    throw DimensionError(std::string(where) + ": [f]([x]) has dimension " + std::to_string(fx.size()) +
                         " but Y has dimension " + std::to_string(y.size()));
  }
  if (fx.is_empty() || !fx.intersects(y)) {
    x_out.set_empty();  // case 1: [x] does not meet X
  } else if (may_be_inner && fx.is_subset(y)) {
    x_in.set_empty();  // case 2: [x] is in X
  }
}

void kernel_test(const IntervalVector& lo, const IntervalVector& hi, bool may_be_inner, IntervalVector& x_in,
                 IntervalVector& x_out, const char* where) {
  if (lo.size() != hi.size() || lo.size() == 0) {
    throw DimensionError(std::string(where) + ": [f-]([x]) and [f+]([x]) have dimensions " +
                         std::to_string(lo.size()) + " and " + std::to_string(hi.size()) +
                         " (equal and non-zero expected)");
  }
  if (lo.is_empty() || hi.is_empty()) {
    x_out.set_empty();
    return;
  }
  bool in_d = true, in_c = true;
  for (std::size_t i = 0; i < lo.size(); ++i) {
    in_d = in_d && lo[i].lb() <= 0 && 0 <= hi[i].ub();  // 0 in [f^d]([x]) (2.44)
    in_c = in_c && lo[i].ub() <= 0 && 0 <= hi[i].lb();  // 0 in [f^c]([x]) (2.43)
  }
  if (!in_d) {
    x_out.set_empty();
  } else if (in_c && may_be_inner) {
    x_in.set_empty();
  }
}

namespace {

// Emptiness of X ∩ x0 proven: no leaf of the paving is Inner or Boundary.
bool proven_empty(Paving& p) {
  for (const Paving::Node& n : p.raw_nodes()) {
    if (n.kind == static_cast<std::uint8_t>(PavingTag::Inner) ||
        n.kind == static_cast<std::uint8_t>(PavingTag::Boundary)) {
      return false;
    }
  }
  return true;
}

}  // namespace

SiviaResult run_paving(const IntervalVector& x0, double eps, const Separation& separate, bool parallel,
                       const Budget& budget, const char* where, const char* option) {
  check_sivia_input(x0, eps, where);
  // What a node costs: its tag and offset, and its box (kept once per node).
  const std::size_t bytes_per_box = sizeof(Paving::Node) + x0.size() * sizeof(Interval);
  BudgetMeter meter(budget, where, option, " or use a larger eps", bytes_per_box);
  SiviaResult result{Paving(x0.size()), {}};
  if (!x0.is_empty()) {
    Chunk root;
    Builder(separate, eps, x0.size(), parallel, meter, where).grow(root, x0, 0);
    result.paving.raw_nodes().reserve(root.total);
    result.paving.raw_bounds().reserve(root.total * x0.size());
    flatten(root, result.paving.raw_nodes(), result.paving.raw_bounds(), x0.size());
  }
  result.summary = meter.summary();
  if (result.summary.finished() && proven_empty(result.paving)) {
    result.summary.status = Status::NoSolution;
    result.summary.reason = std::string(where) + (x0.is_empty() ? ": the initial box is empty"
                                                                : ": every box of the initial box is proven "
                                                                  "outside X (X ∩ x0 is empty)");
  }
  return result;
}

Paving build_paving(const IntervalVector& x0, double eps, const Separation& separate, bool parallel,
                    const Budget& budget, const char* where, const char* option) {
  return run_paving(x0, eps, separate, parallel, budget, where, option).take();
}

}  // namespace sillage::detail
