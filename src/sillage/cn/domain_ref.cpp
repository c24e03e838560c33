#include "sillage/cn/domain_ref.h"

#include <string>

#include "sillage/cn/tube_component_domain.h"
#include "sillage/cn/tube_domain.h"
#include "sillage/error.h"

namespace sillage {

DomainRef::DomainRef(std::shared_ptr<Domain> domain, std::size_t first, std::size_t count) {
  if (!domain) throw Error("DomainRef: null domain");
  if (first > domain->nb_atoms() || count > domain->nb_atoms() - first) {
    throw DimensionError("DomainRef: components [" + std::to_string(first) + ", " + std::to_string(first + count) +
                         ") out of range for " + domain->kind());
  }
  parts_.push_back({std::move(domain), first, count});
}

DomainRef::DomainRef(std::shared_ptr<Interval> x) : DomainRef(std::make_shared<IntervalDomain>(std::move(x)), 0, 1) {}

DomainRef::DomainRef(std::shared_ptr<IntervalVector> x) {
  auto d = std::make_shared<BoxDomain>(std::move(x));
  const std::size_t n = d->nb_atoms();
  *this = DomainRef(std::move(d), 0, n);
}

DomainRef::DomainRef(std::shared_ptr<Tube> x) {
  auto d = std::make_shared<TubeDomain>(std::move(x));
  const std::size_t n = d->nb_atoms();
  *this = DomainRef(std::move(d), 0, n);
}

DomainRef::DomainRef(std::shared_ptr<TubeVector> x) {
  if (!x) throw Error("DomainRef: null TubeVector");
  parts_.reserve(x->size());
  for (std::size_t i = 0; i < x->size(); ++i) {
    const DomainRef c = component(x, i);
    parts_.push_back(c.parts_.front());
  }
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

DomainRef DomainRef::component(std::shared_ptr<TubeVector> x, std::size_t i) {
  auto d = std::make_shared<detail::TubeComponentDomain>(std::move(x), i);
  const std::size_t n = d->nb_atoms();
  return DomainRef(std::move(d), 0, n);
}

}  // namespace sillage
