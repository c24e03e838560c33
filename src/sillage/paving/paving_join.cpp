#include "sillage/paving/paving_join.h"

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

PavingArrays paving_arrays(const Paving& p) {
  Paving q(p);
  PavingArrays a;
  a.dim = p.dim();
  for (const Paving::Node& n : q.raw_nodes()) {
    a.right.push_back(n.right);
    a.kind.push_back(n.kind);
  }
  for (const Interval& x : q.raw_bounds()) {
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
