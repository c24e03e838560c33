#pragma once
// DomainRef: what ContractorNetwork::add takes for each argument of a
// contractor: a whole user variable (a shared Interval or IntervalVector) or a
// part of a box (one component, or a range of components). Converts implicitly
// from the shared pointers, so cn.add(ctc, {x, rho}) reads naturally.
#include <cstddef>
#include <memory>

#include "sillage/cn/domain.h"

namespace sillage {

class DomainRef {
 public:
  DomainRef(std::shared_ptr<Interval> x);        // NOLINT: implicit on purpose
  DomainRef(std::shared_ptr<IntervalVector> x);  // NOLINT: the whole box
  // Component i of the box x (DimensionError if out of range).
  static DomainRef component(std::shared_ptr<IntervalVector> x, std::size_t i);
  // Components i..j (inclusive, as IntervalVector::subvector) of the box x.
  static DomainRef subvector(std::shared_ptr<IntervalVector> x, std::size_t i, std::size_t j);

  // A fresh Domain wrapping the object (the network keeps the first one per key).
  const std::shared_ptr<Domain>& domain() const { return domain_; }
  // The atoms of the domain this reference covers: [first, first + count).
  std::size_t first() const { return first_; }
  std::size_t count() const { return count_; }

  // Extension point (tubes, ...): any Domain and a range of its atoms.
  DomainRef(std::shared_ptr<Domain> domain, std::size_t first, std::size_t count);

 private:
  std::shared_ptr<Domain> domain_;
  std::size_t first_ = 0, count_ = 0;
};

}  // namespace sillage
