// ContractorNetwork forwards to its implementation (network_impl.h): the
// public header stays free of the machinery, and contract() pays one call.
#include "sillage/cn/contractor_network.h"

#include "sillage/cn/network_impl.h"

namespace sillage {

ContractorNetwork::ContractorNetwork() : impl_(std::make_unique<detail::ContractorNetworkImpl>()) {}

ContractorNetwork::~ContractorNetwork() = default;

std::shared_ptr<Interval> ContractorNetwork::create_dom(const Interval& x, const std::string& name) {
  auto p = std::make_shared<Interval>(x);
  add_domain(std::make_shared<IntervalDomain>(p));
  if (!name.empty()) set_name(p, name);
  return p;
}

std::shared_ptr<IntervalVector> ContractorNetwork::create_dom(const IntervalVector& x, const std::string& name) {
  auto p = std::make_shared<IntervalVector>(x);
  add_domain(std::make_shared<BoxDomain>(p));
  if (!name.empty()) set_name(p, name);
  return p;
}

void ContractorNetwork::set_name(const DomainRef& d, const std::string& name) { impl_->set_name(d, name); }

const std::string& ContractorNetwork::domain_name(std::size_t d) const { return impl_->domain_name(d); }

void ContractorNetwork::set_ctc_name(std::size_t i, const std::string& name) { impl_->set_ctc_name(i, name); }

void ContractorNetwork::add(std::shared_ptr<const Ctc> ctc, const std::vector<DomainRef>& domains) {
  impl_->add(std::move(ctc), domains);
}

void ContractorNetwork::add(std::shared_ptr<const NetworkCtc> ctc, const std::vector<DomainRef>& domains) {
  impl_->add(std::move(ctc), domains);
}

void ContractorNetwork::add_node(std::shared_ptr<const CnNode> node) { impl_->add_node(std::move(node)); }

std::size_t ContractorNetwork::add_domain(const std::shared_ptr<Domain>& domain) { return impl_->add_domain(domain); }

ContractStats ContractorNetwork::contract() { return impl_->contract(); }

ContractStats ContractorNetwork::contract_run() { return impl_->contract_run(); }

ContractStats ContractorNetwork::update() { return impl_->update(); }

void ContractorNetwork::touched(const DomainRef& d, const Interval& t) { impl_->touched(d, t); }

void ContractorNetwork::relayout() { impl_->relayout(); }

void ContractorNetwork::retire(std::vector<std::size_t> nodes) { impl_->retire(std::move(nodes)); }

std::size_t ContractorNetwork::nb_ctc() const { return impl_->nb_ctc(); }

std::size_t ContractorNetwork::nb_dom() const { return impl_->nb_dom(); }

double ContractorNetwork::ratio() const { return impl_->ratio(); }

void ContractorNetwork::set_ratio(double ratio) { impl_->set_ratio(ratio); }

Scheduling ContractorNetwork::scheduling() const { return impl_->scheduling(); }

void ContractorNetwork::set_scheduling(Scheduling s) { impl_->set_scheduling(s); }

const Budget& ContractorNetwork::budget() const { return impl_->budget(); }

void ContractorNetwork::set_budget(const Budget& budget) { impl_->set_budget(budget); }

const ContractStats& ContractorNetwork::stopped_stats() const { return impl_->stopped_stats(); }

}  // namespace sillage
