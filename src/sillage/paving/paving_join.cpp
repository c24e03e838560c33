#include "sillage/paving/paving_join.h"

#include <limits>

#include "sillage/error.h"

namespace sillage {

Paving leaf_paving(const IntervalVector& box, PavingTag tag) {
  if (box.size() == 0 || box.is_empty()) throw Error("leaf_paving: expected a non-empty box, got " + box.str());
  Paving p(box.size());
  p.raw_nodes().push_back({0, static_cast<std::uint8_t>(tag)});
  for (std::size_t i = 0; i < box.size(); ++i) p.raw_bounds().push_back(box[i]);
  return p;
}

Paving join_pavings(const IntervalVector& box, const Paving& left, const Paving& right) {
  if (left.is_empty() || right.is_empty()) throw Error("join_pavings: a piece is an empty paving");
  if (left.dim() != box.size() || right.dim() != box.size())
    throw Error("join_pavings: the box has dimension " + std::to_string(box.size()) + ", the pieces " +
                std::to_string(left.dim()) + " and " + std::to_string(right.dim()));
  if (!left.domain().is_subset(box) || !right.domain().is_subset(box))
    throw Error("join_pavings: the pieces " + left.domain().str() + " and " + right.domain().str() +
                " are not inside the box " + box.str());
  Paving l(left), r(right);  // raw access is non-const
  Paving p(box.size());
  auto& nodes = p.raw_nodes();
  auto& bounds = p.raw_bounds();
  nodes.reserve(1 + l.nb_nodes() + r.nb_nodes());
  nodes.push_back({static_cast<std::uint32_t>(1 + l.nb_nodes()), Paving::kInternal});
  for (std::size_t i = 0; i < box.size(); ++i) bounds.push_back(box[i]);
  for (Paving* piece : {&l, &r}) {
    nodes.insert(nodes.end(), piece->raw_nodes().begin(), piece->raw_nodes().end());
    bounds.insert(bounds.end(), piece->raw_bounds().begin(), piece->raw_bounds().end());
  }
  return p;
}

namespace {

// Read access to a paving's arrays: Paving exposes them for building only (non-const); nothing here writes.
const std::vector<Paving::Node>& nodes_of(const Paving& p) { return const_cast<Paving&>(p).raw_nodes(); }
const std::vector<Interval>& bounds_of(const Paving& p) { return const_cast<Paving&>(p).raw_bounds(); }

// Appends the subtree of top's node i to out, pieces in place of the grafted leaves; returns its node count.
struct Grafter {
  const Paving& top;
  const std::vector<std::size_t>& leaves;
  const std::vector<const Paving*>& pieces;
  Paving& out;
  std::size_t next = 0;  // the next grafted leaf

  std::size_t emit(std::size_t i) {
    auto& nodes = out.raw_nodes();
    auto& bounds = out.raw_bounds();
    if (next < leaves.size() && leaves[next] == i) {
      const Paving& piece = *pieces[next++];
      nodes.insert(nodes.end(), nodes_of(piece).begin(), nodes_of(piece).end());
      bounds.insert(bounds.end(), bounds_of(piece).begin(), bounds_of(piece).end());
      return piece.nb_nodes();
    }
    const std::size_t at = nodes.size();
    nodes.push_back(nodes_of(top)[i]);
    const auto box = bounds_of(top).begin() + static_cast<std::ptrdiff_t>(i * top.dim());
    bounds.insert(bounds.end(), box, box + static_cast<std::ptrdiff_t>(top.dim()));
    if (top.is_leaf(i)) return 1;
    const std::size_t left = emit(top.left(i));
    nodes[at].right = static_cast<std::uint32_t>(1 + left);
    return 1 + left + emit(top.right(i));
  }
};

}  // namespace

Paving graft_pavings(const Paving& top, const std::vector<std::size_t>& leaves,
                     const std::vector<const Paving*>& pieces) {
  if (leaves.size() != pieces.size())
    throw Error("graft_pavings: " + std::to_string(leaves.size()) + " leaves and " + std::to_string(pieces.size()) +
                " pieces, expected one piece per leaf");
  for (std::size_t k = 0; k < leaves.size(); ++k) {
    if (!pieces[k]) throw Error("graft_pavings: piece " + std::to_string(k) + " is none, expected a paving");
    if (leaves[k] >= top.nb_nodes() || !top.is_leaf(leaves[k]) || (k > 0 && leaves[k] <= leaves[k - 1]))
      throw Error("graft_pavings: node " + std::to_string(leaves[k]) +
                  " is not a leaf of the paving after the previous one (leaves in increasing pre-order)");
    const Paving& piece = *pieces[k];
    if (piece.is_empty() || piece.dim() != top.dim() || piece.domain() != top.node_box(leaves[k]))
      throw Error("graft_pavings: piece " + std::to_string(k) + " paves " + piece.domain().str() +
                  ", expected the box of leaf " + std::to_string(leaves[k]) + ", " +
                  top.node_box(leaves[k]).str());
  }
  std::size_t total = top.nb_nodes();
  for (const Paving* p : pieces) total += p->nb_nodes() - 1;
  if (total > std::numeric_limits<std::uint32_t>::max())
    throw Error("graft_pavings: " + std::to_string(total) + " nodes, more than a paving's offsets hold");
  Paving out(top.dim());
  out.raw_nodes().reserve(total);
  out.raw_bounds().reserve(total * top.dim());
  if (!top.is_empty()) Grafter{top, leaves, pieces, out}.emit(0);
  return out;
}

PavingArrays paving_arrays(const Paving& p) {
  PavingArrays a;
  a.dim = p.dim();
  a.right.reserve(p.nb_nodes());
  a.kind.reserve(p.nb_nodes());
  a.bounds.reserve(2 * bounds_of(p).size());
  for (const Paving::Node& n : nodes_of(p)) {
    a.right.push_back(n.right);
    a.kind.push_back(n.kind);
  }
  for (const Interval& x : bounds_of(p)) {
    a.bounds.push_back(x.is_empty() ? rounding::kInf : x.lb());
    a.bounds.push_back(x.is_empty() ? -rounding::kInf : x.ub());
  }
  return a;
}

Paving paving_from_arrays(const PavingArrays& a) {
  const std::size_t n = a.right.size();
  if (a.kind.size() != n || a.bounds.size() != 2 * a.dim * n)
    throw Error("paving_from_arrays: " + std::to_string(n) + " offsets, " + std::to_string(a.kind.size()) +
                " kinds and " + std::to_string(a.bounds.size()) + " bounds for dimension " + std::to_string(a.dim) +
                ", expected one kind and 2 * dim bounds per offset");
  Paving p(a.dim);
  p.raw_nodes().reserve(n);
  p.raw_bounds().reserve(a.bounds.size() / 2);
  for (std::size_t i = 0; i < n; ++i) {
    const bool internal = a.kind[i] == Paving::kInternal;
    if (a.kind[i] > Paving::kInternal || internal != (a.right[i] != 0) || i + a.right[i] >= n)
      throw Error("paving_from_arrays: node " + std::to_string(i) + " (kind " + std::to_string(a.kind[i]) +
                  ", right offset " + std::to_string(a.right[i]) + ") is not a node of a paving of " +
                  std::to_string(n) + " nodes");
    p.raw_nodes().push_back({a.right[i], a.kind[i]});
  }
  for (std::size_t i = 0; i < a.bounds.size(); i += 2) {
    const double lb = a.bounds[i], ub = a.bounds[i + 1];
    p.raw_bounds().push_back(lb <= ub ? Interval(lb, ub) : Interval::empty());
  }
  return p;
}

}  // namespace sillage
