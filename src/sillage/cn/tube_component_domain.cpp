#include "sillage/cn/tube_component_domain.h"

#include "sillage/error.h"

namespace sillage::detail {

namespace {

std::shared_ptr<Tube> component_of(const std::shared_ptr<TubeVector>& x, std::size_t i) {
  if (!x) throw Error("DomainRef::component: null TubeVector");
  if (i >= x->size()) {
    throw DimensionError("DomainRef::component: component " + std::to_string(i) + " out of range for a TubeVector of " +
                         std::to_string(x->size()) + " components");
  }
  return x->shared_component(i);
}

}  // namespace

TubeComponentDomain::TubeComponentDomain(std::shared_ptr<TubeVector> x, std::size_t i)
    : TubeDomain(component_of(x, i)), vector_(std::move(x)), index_(i), size_(vector_->size()) {}

std::string TubeComponentDomain::kind() const {
  return TubeDomain::kind() + ", component " + std::to_string(index_) + " of a TubeVector";
}

bool TubeComponentDomain::layout_changed() const {
  return vector_->size() != size_ || &(*vector_)[index_] != &tube() || TubeDomain::layout_changed();
}

void TubeComponentDomain::check_layout(const std::string& label) const {
  if (vector_->size() != size_) {
    throw DimensionError("ContractorNetwork: " + label + " was registered in a TubeVector of " + std::to_string(size_) +
                         " components, which now has " + std::to_string(vector_->size()));
  }
  if (&(*vector_)[index_] != &tube()) {
    throw DimensionError("ContractorNetwork: " + label +
                         " is no longer in its TubeVector (the vector was swapped or moved from)");
  }
  TubeDomain::check_layout(label);
}

std::shared_ptr<Domain> TubeComponentDomain::relaid() const {
  if (vector_->size() != size_ || &(*vector_)[index_] != &tube() || !same_tdomain()) return nullptr;
  return std::make_shared<TubeComponentDomain>(vector_, index_);
}

}  // namespace sillage::detail
