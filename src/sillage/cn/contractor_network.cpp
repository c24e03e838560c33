#include "sillage/cn/contractor_network.h"

#include <chrono>

#include "sillage/ctc/shrink.h"
#include "sillage/error.h"

namespace sillage {

std::shared_ptr<Interval> ContractorNetwork::create_dom(const Interval& x) {
  auto p = std::make_shared<Interval>(x);
  add_domain(std::make_shared<IntervalDomain>(p));
  return p;
}

std::shared_ptr<IntervalVector> ContractorNetwork::create_dom(const IntervalVector& x) {
  auto p = std::make_shared<IntervalVector>(x);
  add_domain(std::make_shared<BoxDomain>(p));
  return p;
}

std::size_t ContractorNetwork::add_domain(const std::shared_ptr<Domain>& domain) {
  if (!domain) throw Error("ContractorNetwork: null domain");
  const auto it = index_.find(domain->key());
  if (it != index_.end()) {
    domains_[it->second]->check_layout(label(it->second));
    return it->second;
  }
  const std::size_t d = domains_.size();
  domains_.push_back(domain);
  watchers_.emplace_back(domain->nb_atoms());
  index_.emplace(domain->key(), d);
  return d;
}

void ContractorNetwork::add(std::shared_ptr<const Ctc> ctc, const std::vector<DomainRef>& domains) {
  if (!ctc) throw Error("ContractorNetwork::add: null contractor");
  std::size_t total = 0;
  for (const auto& r : domains) total += r.count();
  if (total != ctc->nb_vars()) {
    throw DimensionError("ContractorNetwork::add: " + ctc->name() + " acts on " + std::to_string(ctc->nb_vars()) +
                         " variables but the " + std::to_string(domains.size()) + " domains given add up to " +
                         std::to_string(total));
  }
  // Validate everything before registering anything, so that a failed add
  // leaves the network unchanged.
  for (const auto& r : domains) {
    const auto it = index_.find(r.domain()->key());
    if (it != index_.end()) domains_[it->second]->check_layout(label(it->second));
  }
  std::vector<AtomRef> atoms;
  atoms.reserve(total);
  for (const auto& r : domains) {
    const std::size_t d = add_domain(r.domain());
    for (std::size_t k = 0; k < r.count(); ++k) atoms.push_back({d, r.first() + k});
  }
  add_node(std::make_shared<CtcNode>(std::move(ctc), std::move(atoms)));
}

void ContractorNetwork::add_node(std::shared_ptr<const CnNode> node) {
  if (!node) throw Error("ContractorNetwork::add_node: null node");
  for (const auto& a : node->atoms()) {
    if (a.domain >= domains_.size() || a.atom >= domains_[a.domain]->nb_atoms()) {
      throw DimensionError("ContractorNetwork::add_node: " + node->name() + " refers to an unknown domain atom");
    }
  }
  const std::size_t id = nodes_.size();
  for (const auto& a : node->atoms()) {
    auto& w = watchers_[a.domain][a.atom];
    if (w.empty() || w.back() != id) w.push_back(id);
  }
  nodes_.push_back(std::move(node));
}

void ContractorNetwork::set_ratio(double ratio) {
  check_ratio(ratio, "ContractorNetwork::set_ratio");
  ratio_ = ratio;
}

std::string ContractorNetwork::label(std::size_t d) const {
  return "domain " + std::to_string(d) + " (" + domains_[d]->kind() + ")";
}

ContractStats ContractorNetwork::contract() {
  const auto start = std::chrono::steady_clock::now();
  ContractStats stats;
  const auto finish = [&] {
    stats.time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
  };
  for (std::size_t d = 0; d < domains_.size(); ++d) {
    domains_[d]->check_layout(label(d));
    if (domains_[d]->is_empty() && !stats.empty) {
      stats.empty = true;
      stats.empty_domain = label(d);
    }
  }
  if (stats.empty) return finish();

  std::vector<std::size_t> round(nodes_.size()), next, changed;
  for (std::size_t i = 0; i < nodes_.size(); ++i) round[i] = i;
  std::vector<char> queued(nodes_.size(), 1);
  while (!round.empty()) {
    ++stats.iterations;
    for (const std::size_t i : round) {
      queued[i] = 0;
      changed.clear();
      const CnNode& node = *nodes_[i];
      ++stats.contractor_calls;
      if (!node.run(domains_, ratio_, changed)) {
        stats.empty = true;
        for (const auto& a : node.atoms()) {
          if (domains_[a.domain]->is_empty()) {
            stats.empty_domain = label(a.domain);
            break;
          }
        }
        return finish();
      }
      for (const std::size_t k : changed) {
        const AtomRef& a = node.atoms()[k];
        for (const std::size_t w : watchers_[a.domain][a.atom]) {
          if (w != i && !queued[w]) {
            queued[w] = 1;
            next.push_back(w);
          }
        }
      }
    }
    round.swap(next);
    next.clear();
  }
  return finish();
}

}  // namespace sillage
