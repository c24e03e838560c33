#include "sillage/cn/tube_domain.h"

#include "sillage/error.h"

namespace sillage {

TubeDomain::TubeDomain(std::shared_ptr<Tube> x) : x_(std::move(x)) {
  if (!x_) throw Error("ContractorNetwork: null Tube domain");
  nb_slices_ = x_->nb_slices();
  td_ = x_->tdomain();
}

Interval TubeDomain::atom(std::size_t i) const {
  return time_atom(x_->data(), i);
}

void TubeDomain::set_atom(std::size_t i, const Interval& x) {
  TubeData& d = x_->data();
  time_atom(d, i) = x;
  d.touch();
}

AtomPlace TubeDomain::place(std::size_t i) const {
  const auto t = x_->tdomain()->times();
  const std::size_t k = time_index(i);
  if (is_slice(i)) return {"slice", k, Interval(t[k], t[k + 1])};
  return {"gate", k, Interval(t[k])};
}

std::string TubeDomain::kind() const { return "Tube(" + std::to_string(nb_slices_) + " slices)"; }

void TubeDomain::check_layout(const std::string& label) const {
  if (x_->nb_slices() != nb_slices_) {
    throw DimensionError("ContractorNetwork: " + label + " was registered with " + std::to_string(nb_slices_) +
                         " slices but now has " + std::to_string(x_->nb_slices()) +
                         " (sample the TDomain before building the network)");
  }
  if (x_->tdomain() != td_) {
    throw DimensionError("ContractorNetwork: " + label +
                         " was registered on another TDomain (assign tubes of the same TDomain)");
  }
}

std::shared_ptr<Domain> TubeDomain::relaid() const {
  return same_tdomain() ? std::make_shared<TubeDomain>(x_) : nullptr;
}

}  // namespace sillage
