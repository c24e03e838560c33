#pragma once
// Connected components of a union of boxes (thesis 6.3: the sets Omega_i of
// the outer approximation T+ of a t-plane). Two closed boxes are connected as
// soon as they intersect, even at a single corner point: a component is a
// connected set in the topological sense, which is what the degree theory of
// chapter 6 needs. The contour of a 2-D component is one outer loop plus one
// loop per hole, loops that may touch themselves at such corners (contour.h).
#include <cstddef>
#include <vector>

#include "sillage/interval/interval_vector.h"
#include "sillage/paving/contour.h"
#include "sillage/paving/paving_tag.h"

namespace sillage {

struct Component {
  std::vector<IntervalVector> boxes;  // in the order of the input (paving pre-order)
  std::vector<PavingTag> tags;        // tags[k] is the tag of boxes[k]
  IntervalVector hull;                // hull of the boxes
  double volume = 0.0;                // sum of the box volumes

  // The number of leaves.
  std::size_t size() const { return boxes.size(); }
  // The number of leaves with this tag.
  std::size_t count(PavingTag tag) const;
  // Oriented boundary loops (2-D components only), see contour().
  std::vector<ContourLoop> contour() const { return sillage::contour(boxes); }
};

// Components of a list of boxes (empty boxes are skipped), ordered by their
// first box in the input order. `tags`, if given, must match `boxes` in size
// (else Boundary is assumed for every box).
std::vector<Component> connected_components(const std::vector<IntervalVector>& boxes,
                                            const std::vector<PavingTag>& tags = {});

namespace detail {
// Union-find over 0..n-1, path-halving and union by index (deterministic).
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n);
  std::size_t find(std::size_t i);
  void unite(std::size_t i, std::size_t j);

 private:
  std::vector<std::size_t> parent_;
};

// Builds components from the groups of a union-find, ordered by smallest member.
std::vector<Component> gather_components(DisjointSets& sets, const std::vector<IntervalVector>& boxes,
                                         const std::vector<PavingTag>& tags);
}  // namespace detail

}  // namespace sillage
