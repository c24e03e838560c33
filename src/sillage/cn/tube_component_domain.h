#pragma once
// TubeComponentDomain: component i of a TubeVector as a network domain. The
// identity is the component (a heap object of its own, TubeComponents), so
// it is the same domain as the component given as a Tube. The vector is kept
// too, to report at contract() a vector resized behind the network's back
// (its components are no longer those the contractors were bound to).
#include <cstddef>
#include <memory>
#include <string>

#include "sillage/cn/tube_domain.h"
#include "sillage/tube/tube_vector.h"

namespace sillage::detail {

class TubeComponentDomain : public TubeDomain {
 public:
  // DimensionError if i >= x->size().
  TubeComponentDomain(std::shared_ptr<TubeVector> x, std::size_t i);
  std::string kind() const override;
  void check_layout(const std::string& label) const override;
  bool layout_changed() const override;
  std::shared_ptr<Domain> relaid() const override;

 private:
  std::shared_ptr<TubeVector> vector_;
  std::size_t index_, size_;
};

}  // namespace sillage::detail
