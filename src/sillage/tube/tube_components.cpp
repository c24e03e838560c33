#include "sillage/tube/tube_components.h"

#include <algorithm>
#include <utility>

namespace sillage {

TubeComponents::TubeComponents(std::vector<Tube> tubes) {
  p_.reserve(tubes.size());
  for (auto& x : tubes) p_.push_back(std::make_shared<Tube>(std::move(x)));
}

TubeComponents::TubeComponents(const TubeComponents& x) {
  p_.reserve(x.size());
  for (const auto& c : x.p_) p_.push_back(std::make_shared<Tube>(*c));
}

TubeComponents& TubeComponents::operator=(const TubeComponents& x) {
  if (this == &x) return *this;
  const std::size_t n = std::min(size(), x.size());
  for (std::size_t i = 0; i < n; ++i) *p_[i] = *x.p_[i];
  p_.resize(n);
  for (std::size_t i = n; i < x.size(); ++i) p_.push_back(std::make_shared<Tube>(*x.p_[i]));
  return *this;
}

TubeComponents& TubeComponents::operator=(TubeComponents&& x) {
  if (this == &x) return *this;
  // Swapping the tubes rather than moving them leaves x's components valid
  // tubes (this vector's former values): a network may still hold them.
  const std::size_t n = std::min(size(), x.size());
  for (std::size_t i = 0; i < n; ++i) std::swap(*p_[i], *x.p_[i]);
  p_.resize(n);
  for (std::size_t i = n; i < x.size(); ++i) p_.push_back(std::move(x.p_[i]));
  x.p_.resize(n);
  return *this;
}

bool TubeComponents::operator==(const TubeComponents& y) const {
  return std::equal(begin(), end(), y.begin(), y.end());
}

}  // namespace sillage
