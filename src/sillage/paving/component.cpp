#include "sillage/paving/component.h"

#include <algorithm>
#include <numeric>

namespace sillage {

std::size_t Component::count(PavingTag tag) const {
  return static_cast<std::size_t>(std::count(tags.begin(), tags.end(), tag));
}

namespace detail {

DisjointSets::DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }

std::size_t DisjointSets::find(std::size_t i) {
  while (parent_[i] != i) {
    parent_[i] = parent_[parent_[i]];
    i = parent_[i];
  }
  return i;
}

void DisjointSets::unite(std::size_t i, std::size_t j) {
  i = find(i);
  j = find(j);
  if (i == j) return;
  if (j < i) std::swap(i, j);
  parent_[j] = i;  // the root stays the smallest member
}

std::vector<Component> gather_components(DisjointSets& sets, const std::vector<IntervalVector>& boxes,
                                         const std::vector<PavingTag>& tags) {
  std::vector<Component> comps;
  std::vector<std::size_t> slot(boxes.size(), boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const std::size_t r = sets.find(i);  // r <= i: the group's first member
    if (slot[r] == boxes.size()) {
      slot[r] = comps.size();
      comps.emplace_back();
      comps.back().hull = IntervalVector::empty(boxes[i].size());
    }
    Component& c = comps[slot[r]];
    c.boxes.push_back(boxes[i]);
    c.tags.push_back(tags[i]);
    c.hull |= boxes[i];
    c.volume += boxes[i].volume();
  }
  return comps;
}

}  // namespace detail

std::vector<Component> connected_components(const std::vector<IntervalVector>& boxes,
                                            const std::vector<PavingTag>& tags) {
  if (!tags.empty()) check_same_size(tags.size(), boxes.size(), "connected_components (tags vs boxes)");
  std::vector<IntervalVector> kept;
  std::vector<PavingTag> kept_tags;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (i > 0) check_same_size(boxes[i].size(), boxes[0].size(), "connected_components (box dimensions)");
    if (boxes[i].is_empty()) continue;
    kept.push_back(boxes[i]);
    kept_tags.push_back(tags.empty() ? PavingTag::Boundary : tags[i]);
  }
  if (!kept.empty() && kept[0].size() == 0) throw DimensionError("connected_components: zero-dimensional boxes");
  // Sweep along the first axis: sort by lower bound, keep the boxes still open.
  std::vector<std::size_t> order(kept.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return kept[i][0].lb() < kept[j][0].lb() || (kept[i][0].lb() == kept[j][0].lb() && i < j);
  });
  detail::DisjointSets sets(kept.size());
  std::vector<std::size_t> active;
  for (std::size_t i : order) {
    const double lo = kept[i][0].lb();
    std::erase_if(active, [&](std::size_t j) { return kept[j][0].ub() < lo; });
    for (std::size_t j : active) {
      if (kept[i].intersects(kept[j])) sets.unite(i, j);
    }
    active.push_back(i);
  }
  return detail::gather_components(sets, kept, kept_tags);
}

}  // namespace sillage
