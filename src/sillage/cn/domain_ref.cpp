#include "sillage/cn/domain_ref.h"

#include <string>

#include "sillage/error.h"

namespace sillage {

DomainRef::DomainRef(std::shared_ptr<Domain> domain, std::size_t first, std::size_t count)
    : domain_(std::move(domain)), first_(first), count_(count) {
  if (!domain_) throw Error("DomainRef: null domain");
  if (first_ > domain_->nb_atoms() || count_ > domain_->nb_atoms() - first_) {
    throw DimensionError("DomainRef: components [" + std::to_string(first_) + ", " +
                         std::to_string(first_ + count_) + ") out of range for " + domain_->kind());
  }
}

DomainRef::DomainRef(std::shared_ptr<Interval> x) : DomainRef(std::make_shared<IntervalDomain>(std::move(x)), 0, 1) {}

DomainRef::DomainRef(std::shared_ptr<IntervalVector> x) {
  auto d = std::make_shared<BoxDomain>(std::move(x));
  const std::size_t n = d->nb_atoms();
  *this = DomainRef(std::move(d), 0, n);
}

DomainRef DomainRef::component(std::shared_ptr<IntervalVector> x, std::size_t i) {
  auto d = std::make_shared<BoxDomain>(std::move(x));
  if (i >= d->nb_atoms()) {
    throw DimensionError("DomainRef::component: component " + std::to_string(i) + " out of range for " + d->kind());
  }
  return DomainRef(std::move(d), i, 1);
}

DomainRef DomainRef::subvector(std::shared_ptr<IntervalVector> x, std::size_t i, std::size_t j) {
  auto d = std::make_shared<BoxDomain>(std::move(x));
  if (i > j || j >= d->nb_atoms()) {
    throw DimensionError("DomainRef::subvector: invalid range [" + std::to_string(i) + ", " + std::to_string(j) +
                         "] for " + d->kind());
  }
  return DomainRef(std::move(d), i, j - i + 1);
}

}  // namespace sillage
