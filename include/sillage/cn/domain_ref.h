#pragma once
// DomainRef: what ContractorNetwork::add takes for each argument of a
// contractor: a whole user variable (a shared Interval, IntervalVector, Tube
// or TubeVector) or a part of one (a component or a range of components of a
// box, a component of a tube vector). Converts implicitly from the shared
// pointers, so cn.add(ctc, {x, rho}) reads naturally.
//
// A reference is a list of parts, each a range of atoms of one domain: one
// part for an Interval, a box or a tube; one part per component for a tube
// vector (each component is a domain of its own).
#include <cstddef>
#include <memory>
#include <vector>

#include "sillage/cn/domain.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

class DomainRef {
 public:
  struct Part {
    std::shared_ptr<Domain> domain;  // a fresh Domain; the network keeps the first one per key
    std::size_t first, count;        // its atoms [first, first + count)
  };

  DomainRef(std::shared_ptr<Interval> x);        // NOLINT: implicit on purpose
  DomainRef(std::shared_ptr<IntervalVector> x);  // NOLINT: the whole box
  DomainRef(std::shared_ptr<Tube> x);            // NOLINT: every slice and gate
  DomainRef(std::shared_ptr<TubeVector> x);      // NOLINT: one part per component
  // Component i of the box x (DimensionError if out of range).
  static DomainRef component(std::shared_ptr<IntervalVector> x, std::size_t i);
  // Components i..j (inclusive, as IntervalVector::subvector) of the box x.
  static DomainRef subvector(std::shared_ptr<IntervalVector> x, std::size_t i, std::size_t j);
  // Component i of the tube vector x, live (DimensionError if out of range).
  static DomainRef component(std::shared_ptr<TubeVector> x, std::size_t i);

  const std::vector<Part>& parts() const { return parts_; }
  // The first part: its domain and atom range (Python's DomainRef.first/count).
  const std::shared_ptr<Domain>& domain() const { return parts_.front().domain; }
  // Index of the first component referred to.
  std::size_t first() const { return parts_.front().first; }
  // Number of components referred to.
  std::size_t count() const { return parts_.front().count; }

  // Extension point: any Domain and a range of its atoms.
  DomainRef(std::shared_ptr<Domain> domain, std::size_t first, std::size_t count);

 private:
  DomainRef() = default;
  std::vector<Part> parts_;
};

}  // namespace sillage
