#pragma once
// Paving: the result of a set inversion (thesis 2.4.1). A binary tree whose
// root box is the initial box [x]0 and whose every node box is the union of
// its two children's boxes, so that the leaves are non-overlapping boxes that
// cover [x]0 (a paving, (2.37)). Each leaf carries a PavingTag:
//   Inner    proven inside the set X             (X- , green)
//   Boundary undetermined at the precision eps   (X+ \ X-, yellow)
//   Outside  proven outside X                    (blue)
// so that X- = inner() is in X and X is in X+ = outer() = inner ∪ boundary
// (2.38), within [x]0. Inner/Outside claims hold for the leaf boxes up to
// their faces shared with other leaves (a set of measure zero).
//
// Storage is array-backed in depth-first pre-order: the left child of an
// internal node i is i + 1, its right child i + right_offset. Boxes are packed
// contiguously (dim() intervals per node). Leaves listed by the queries come
// in this pre-order ("left before right"), which never depends on threads.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sillage/budget.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/paving/component.h"
#include "sillage/paving/paving_tag.h"

namespace sillage {

class Paving {
 public:
  // An empty paving (no node): the result for an empty initial box.
  Paving() = default;
  explicit Paving(std::size_t dim) : dim_(dim) {}

  // The dimension of the boxes.
  std::size_t dim() const { return dim_; }
  // True for the paving of an empty initial box (no node).
  bool is_empty() const { return nodes_.empty(); }
  // The initial box [x]0 (the root box); an empty box if the paving is empty.
  IntervalVector domain() const;

  // ---- leaves, by tag (pre-order) ----
  // The leaves of a tag, in pre-order ('left before right', independent of threads).
  std::vector<IntervalVector> boxes(PavingTag tag) const;
  // Boxes proven in X (the inner approximation).
  std::vector<IntervalVector> inner() const { return boxes(PavingTag::Inner); }
  // Undetermined boxes.
  std::vector<IntervalVector> boundary() const { return boxes(PavingTag::Boundary); }
  // Boxes proven outside X.
  std::vector<IntervalVector> outside() const { return boxes(PavingTag::Outside); }
  // The outer approximation X+ = inner ∪ boundary, leaves in pre-order.
  std::vector<IntervalVector> outer() const;

  // The number of nodes of the tree (leaves and internal nodes).
  std::size_t nb_nodes() const { return nodes_.size(); }
  // The number of leaves.
  std::size_t nb_leaves() const;
  // The number of leaves with this tag.
  std::size_t count(PavingTag tag) const;
  // Sum of the leaf volumes of a tag (a floating-point measure, not a set).
  double volume(PavingTag tag) const;
  // Volume of the outer approximation X+ = inner & boundary leaves.
  double outer_volume() const { return volume(PavingTag::Inner) + volume(PavingTag::Boundary); }
  // Hull of the outer approximation X+; an empty box if X+ is empty.
  IntervalVector hull() const;

  // Tag of the leaves that contain p; nullopt if p is not in [x]0. A point on
  // faces shared by leaves of different tags gets Boundary.
  std::optional<PavingTag> tag_at(const Vector& p) const;

  // Connected components of X+ (see component.h), in a deterministic order.
  // Cancelled once `cancel` is (checked every 1024 leaves: a large paving
  // takes tens of milliseconds).
  std::vector<Component> components(const CancelToken& cancel = {}) const;

  // ---- raw node access (pre-order indices) ----
  // The box of node i (pre-order index; the left child of i is i + 1).
  IntervalVector node_box(std::size_t i) const;
  // True when node i is a leaf.
  bool is_leaf(std::size_t i) const { return node(i).right == 0; }
  // Index of the left child of the internal node i.
  std::size_t left(std::size_t i) const;
  // Index of the right child of the internal node i.
  std::size_t right(std::size_t i) const;
  // Tag of a leaf; throws for an internal node.
  PavingTag tag(std::size_t i) const;
  // Pre-order indices of the leaves with the given tag.
  std::vector<std::size_t> leaf_indices(PavingTag tag) const;
  // Indices of the leaves whose closed box intersects x (tree descent).
  std::vector<std::size_t> leaves_intersecting(const IntervalVector& x) const;

  // Same tree, same boxes (bit for bit), same tags.
  bool operator==(const Paving& other) const;
  bool operator!=(const Paving& other) const { return !(*this == other); }
  std::string str() const;

  // ---- construction (used by the SIVIA builders; order is pre-order) ----
  struct Node {
    std::uint32_t right = 0;  // offset to the right child; 0 for a leaf
    std::uint8_t kind = 0;    // a PavingTag for a leaf, kInternal otherwise
  };
  static constexpr std::uint8_t kInternal = 3;
  std::vector<Node>& raw_nodes() { return nodes_; }
  std::vector<Interval>& raw_bounds() { return bounds_; }

 private:
  const Node& node(std::size_t i) const;
  const Interval* box_ptr(std::size_t i) const { return bounds_.data() + i * dim_; }

  std::size_t dim_ = 0;
  std::vector<Node> nodes_;
  std::vector<Interval> bounds_;  // dim_ intervals per node
};

}  // namespace sillage
