// What CtcIvp's network node remembers between runs (ivp_memory.h).
#include "sillage/dynamics/ivp_memory.h"

namespace sillage::detail {

namespace {

// The tubes of x then u, in one list.
std::vector<const Tube*> components(const TubeVector& x, const TubeVector* u) {
  std::vector<const Tube*> all;
  for (std::size_t i = 0; i < x.size(); ++i) all.push_back(&x[i]);
  if (u) {
    for (std::size_t i = 0; i < u->size(); ++i) all.push_back(&(*u)[i]);
  }
  return all;
}

}  // namespace

void IvpMemory::forget() {
  gates.clear();
  slices.clear();
  times.clear();
  arriving[0].clear();
  arriving[1].clear();
}

void IvpMemory::remember(const TubeVector& x, const TubeVector* u) {
  gates.clear();
  slices.clear();
  times.clear();
  for (std::size_t k = 0; k <= x.nb_slices(); ++k) times.push_back(x.tdomain()->t(k));
  for (const Tube* c : components(x, u)) {
    gates.emplace_back(c->data().gates.begin(), c->data().gates.end());
    slices.emplace_back(c->data().slices.begin(), c->data().slices.end());
  }
}

std::size_t IvpMemory::first_change(const TubeVector& x, const TubeVector* u, double sign) const {
  const std::vector<const Tube*> all = components(x, u);
  const std::size_t N = x.nb_slices();
  if (all.size() != gates.size() || times.size() != N + 1 || arriving[sign > 0 ? 0 : 1].size() != N + 1) return 0;
  for (std::size_t k = 0; k <= N; ++k) {
    if (x.tdomain()->t(k) != times[k]) return 0;
  }
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i]->data().gates.size() != N + 1 || gates[i].size() != N + 1) return 0;
  }
  for (std::size_t j = 0; j <= N; ++j) {
    const std::size_t k = sign > 0 ? j : N - j;
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (all[i]->data().gates[k] != gates[i][k]) return j;
      if (j < N) {
        const std::size_t s = sign > 0 ? k : k - 1;
        if (all[i]->data().slices[s] != slices[i][s]) return j;
      }
    }
  }
  return N + 1;
}

}  // namespace sillage::detail
