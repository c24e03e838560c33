#include "sillage/paving/paving.h"

#include <sstream>

namespace sillage {

const Paving::Node& Paving::node(std::size_t i) const {
  if (i >= nodes_.size()) {
    throw DimensionError("Paving: node index " + std::to_string(i) + " out of range (" +
                         std::to_string(nodes_.size()) + " nodes)");
  }
  return nodes_[i];
}

IntervalVector Paving::node_box(std::size_t i) const {
  node(i);  // range check
  const Interval* p = box_ptr(i);
  return IntervalVector(std::vector<Interval>(p, p + dim_));
}

IntervalVector Paving::domain() const { return is_empty() ? IntervalVector::empty(dim_) : node_box(0); }

std::size_t Paving::left(std::size_t i) const {
  if (is_leaf(i)) throw Error("Paving::left: node " + std::to_string(i) + " is a leaf");
  return i + 1;
}

std::size_t Paving::right(std::size_t i) const {
  if (is_leaf(i)) throw Error("Paving::right: node " + std::to_string(i) + " is a leaf");
  return i + node(i).right;
}

PavingTag Paving::tag(std::size_t i) const {
  if (!is_leaf(i)) throw Error("Paving::tag: node " + std::to_string(i) + " is not a leaf");
  return static_cast<PavingTag>(node(i).kind);
}

std::vector<std::size_t> Paving::leaf_indices(PavingTag tag) const {
  std::vector<std::size_t> r;
  const auto k = static_cast<std::uint8_t>(tag);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (nodes_[i].kind == k) r.push_back(i);
  }
  return r;
}

std::vector<IntervalVector> Paving::boxes(PavingTag tag) const {
  std::vector<IntervalVector> r;
  for (std::size_t i : leaf_indices(tag)) r.push_back(node_box(i));
  return r;
}

std::vector<IntervalVector> Paving::outer() const {
  std::vector<IntervalVector> r;
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const auto k = nodes_[i].kind;
    if (k == static_cast<std::uint8_t>(PavingTag::Inner) || k == static_cast<std::uint8_t>(PavingTag::Boundary)) {
      r.push_back(node_box(i));
    }
  }
  return r;
}

std::size_t Paving::nb_leaves() const {
  std::size_t n = 0;
  for (const auto& nd : nodes_) n += nd.kind != kInternal;
  return n;
}

std::size_t Paving::count(PavingTag tag) const {
  std::size_t n = 0;
  for (const auto& nd : nodes_) n += nd.kind == static_cast<std::uint8_t>(tag);
  return n;
}

double Paving::volume(PavingTag tag) const {
  double v = 0.0;
  const auto k = static_cast<std::uint8_t>(tag);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (nodes_[i].kind != k) continue;
    double b = 1.0;
    for (std::size_t d = 0; d < dim_; ++d) b *= box_ptr(i)[d].diam();
    v += b;
  }
  return v;
}

IntervalVector Paving::hull() const {
  IntervalVector h = IntervalVector::empty(dim_);
  for (const auto& b : outer()) h |= b;
  return h;
}

std::optional<PavingTag> Paving::tag_at(const Vector& p) const {
  check_same_size(p.size(), dim_, "Paving::tag_at (point vs paving)");
  if (is_empty() || !domain().contains(p)) return std::nullopt;
  const IntervalVector pt = IntervalVector::from_point(p);
  std::optional<PavingTag> t;
  for (std::size_t i : leaves_intersecting(pt)) {
    const PavingTag ti = tag(i);
    t = (!t || *t == ti) ? ti : PavingTag::Boundary;
  }
  return t;
}

std::vector<std::size_t> Paving::leaves_intersecting(const IntervalVector& x) const {
  check_same_size(x.size(), dim_, "Paving::leaves_intersecting");
  std::vector<std::size_t> r;
  if (is_empty() || x.is_empty()) return r;
  std::vector<std::size_t> stack{0};
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    const Interval* b = box_ptr(i);
    bool meets = true;
    for (std::size_t d = 0; d < dim_ && meets; ++d) meets = b[d].intersects(x[d]);
    if (!meets) continue;
    if (nodes_[i].right == 0) {
      r.push_back(i);
    } else {
      stack.push_back(i + nodes_[i].right);  // popped after the left subtree
      stack.push_back(i + 1);
    }
  }
  return r;
}

std::vector<Component> Paving::components(const CancelToken& cancel) const {
  // Union-find over the outer leaves; neighbours found by tree descent.
  std::vector<std::size_t> leaves;
  std::vector<std::size_t> slot(nodes_.size(), nodes_.size());
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const auto k = nodes_[i].kind;
    if (k == static_cast<std::uint8_t>(PavingTag::Inner) || k == static_cast<std::uint8_t>(PavingTag::Boundary)) {
      slot[i] = leaves.size();
      leaves.push_back(i);
    }
  }
  std::vector<IntervalVector> boxes;
  std::vector<PavingTag> tags;
  boxes.reserve(leaves.size());
  for (std::size_t i : leaves) {
    boxes.push_back(node_box(i));
    tags.push_back(tag(i));
  }
  detail::DisjointSets sets(leaves.size());
  for (std::size_t k = 0; k < leaves.size(); ++k) {
    if (k % 1024 == 0) check_cancel(cancel, "Paving::components");
    for (std::size_t j : leaves_intersecting(boxes[k])) {
      if (slot[j] != nodes_.size() && slot[j] > k) sets.unite(k, slot[j]);
    }
  }
  return detail::gather_components(sets, boxes, tags);
}

bool Paving::operator==(const Paving& other) const {
  if (dim_ != other.dim_ || nodes_.size() != other.nodes_.size()) return false;
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (nodes_[i].right != other.nodes_[i].right || nodes_[i].kind != other.nodes_[i].kind) return false;
  }
  for (std::size_t k = 0; k < bounds_.size(); ++k) {
    const Interval &a = bounds_[k], &b = other.bounds_[k];
    // Bit-for-bit: same bounds (an empty interval only equals an empty one).
    if (!(a.lb() == b.lb() && a.ub() == b.ub()) && !(a.is_empty() && b.is_empty())) return false;
  }
  return true;
}

std::string Paving::str() const {
  std::ostringstream os;
  os << "Paving(dim " << dim_ << ", " << nb_nodes() << " nodes, " << count(PavingTag::Inner) << " inner, "
     << count(PavingTag::Boundary) << " boundary, " << count(PavingTag::Outside) << " outside)";
  return os.str();
}

}  // namespace sillage
