// The network between contractions (online estimation, docs/online.md):
// atoms narrowed from outside, tubes whose TDomain grew or forgot its past,
// contractors retired. Each rebuild costs one pass over the nodes; the
// propagation itself (update()) stays slice-granular.
#include <algorithm>
#include <optional>
#include <unordered_map>

#include "sillage/cn/network_impl.h"
#include "sillage/cn/tube_domain.h"
#include "sillage/error.h"

namespace sillage::detail {

void ContractorNetworkImpl::touched(const DomainRef& d, const Interval& t) {
  check_not_contracting("touched");
  if (t.is_empty()) throw Error("ContractorNetwork::touched: the time interval is empty");
  for (const auto& p : d.parts()) {
    const auto it = index_.find(p.domain->key());
    if (it == index_.end()) {
      throw Error("ContractorNetwork::touched: " + p.domain->noun() + " (" + p.domain->kind() +
                  ") is not in the network (add a contractor on it first)");
    }
    // A tube touched at some times is checked there at the next propagation; anything else anew.
    if (t.is_all_reals() || !dynamic_cast<const TubeDomain*>(domains_[it->second].get())) checked_[it->second] = 0;
  }
  touched_.push_back({d, t});
}

bool ContractorNetworkImpl::touched_atoms(std::size_t d, const Interval& t, std::size_t& first, std::size_t& end) const {
  first = 0, end = domains_[d]->nb_atoms();
  const auto* tube = dynamic_cast<const TubeDomain*>(domains_[d].get());
  if (!tube || t.is_all_reals()) return true;
  const TDomain& td = *tube->tube().tdomain();
  const Interval within = t & td.t0_tf();
  if (within.is_empty()) return false;  // forgotten since, or not yet there
  std::size_t k0 = 0, k1 = 0;
  slice_range(td, within, k0, k1, "ContractorNetwork::touched");
  first = 2 * k0;    // gate k0
  end = 2 * k1 + 3;  // up to gate k1 + 1
  return true;
}

void ContractorNetworkImpl::check_touched(ContractStats& s) const {
  for (const Touch& touch : touched_) {
    for (const auto& p : touch.ref.parts()) {
      const std::size_t d = index_.at(p.domain->key());
      std::size_t first = 0, end = 0;
      if (!checked_[d] || !touched_atoms(d, touch.t, first, end)) continue;  // checked whole, or nothing there
      explain_empty_on_input(s, d, domains_[d]->empty_on_input(first, end));
      if (s.empty) return;
    }
  }
}

void ContractorNetworkImpl::wake_touched(std::vector<std::size_t>& round, std::vector<char>& queued) {
  for (const Touch& touch : touched_) {
    for (const auto& p : touch.ref.parts()) {
      const std::size_t d = index_.at(p.domain->key());
      std::size_t first = 0, end = 0;
      if (!touched_atoms(d, touch.t, first, end)) continue;
      for (std::size_t a = first; a < end; ++a) {
        watchers_[d].for_each(a, [&](std::size_t node, std::size_t g) {
          if (dirty_.mark(node, g, a) && !queued[node]) {
            queued[node] = 1;
            round.push_back(node);
          }
        });
      }
    }
  }
}

void ContractorNetworkImpl::relayout() {
  check_not_contracting("relayout");
  changed_.clear(), relaid_.clear();
  for (std::size_t d = 0; d < domains_.size(); ++d) {
    if (!domains_[d]->layout_changed()) continue;
    auto now = domains_[d]->relaid();
    if (!now) domains_[d]->check_layout(label(d));
    changed_.push_back(d), relaid_.push_back(std::move(now));
  }
  const bool grown = grow_in_place();
  relaid_.clear();
  if (!grown && !relay_in_place({})) rebuild_nodes(false);
}

bool ContractorNetworkImpl::users_follow(std::size_t d) {
  Users& u = users_[d];
  if (u.follow < 0) {
    u.follow = std::all_of(u.nodes.begin(), u.nodes.end(),
                           [&](std::size_t i) { return records_[i].make && nodes_[i]->follows_appends(); });
  }
  return u.follow != 0;
}

bool ContractorNetworkImpl::grow_in_place() {
  for (std::size_t j = 0; j < changed_.size(); ++j) {
    const std::size_t d = changed_[j];
    if (!relaid_[j] || !domains_[d]->appended_only() || !users_follow(d)) return false;
  }
  const std::vector<std::size_t>& grown = changed_;
  grown_from_.resize(domains_.size(), kNoAtom);
  for (std::size_t j = 0; j < grown.size(); ++j) {
    const std::size_t d = grown[j];
    grown_from_[d] = domains_[d]->nb_atoms();
    domains_[d] = std::move(relaid_[j]);
    watchers_[d].grow(domains_[d]->nb_atoms());
  }
  // The nodes on them, each once (a node on several grown domains is marked by the first).
  grown_done_.resize(nodes_.size(), 0);
  for (const std::size_t d : grown) {
    for (const std::size_t i : users_[d].nodes) {
      if (grown_done_[i]) continue;
      grown_done_[i] = 1;
      // Made by this network for itself (records_[i].make): no one else holds it.
      auto& node = const_cast<CnNode&>(*nodes_[i]);
      if (node.follow_appends(grown_from_, domains_)) dirty_.relayout_node(i, node);
    }
  }
  for (const std::size_t d : grown) {
    grown_from_[d] = kNoAtom;
    for (const std::size_t i : users_[d].nodes) grown_done_[i] = 0;
  }
  note_time_layouts();
  return true;
}

void ContractorNetworkImpl::retire(std::vector<std::size_t> nodes) {
  check_not_contracting("retire");
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  if (!nodes.empty() && nodes.back() >= nodes_.size()) {
    throw Error("ContractorNetwork::retire: no contractor " + std::to_string(nodes.back()) + " (" +
                std::to_string(nodes_.size()) + " added)");
  }
  std::vector<char> gone(nodes_.size(), 0);
  for (const std::size_t i : nodes) gone[i] = 1;
  if (relay_in_place(gone)) return;
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (!gone[i] && !records_[i].make) {
      throw Error("ContractorNetwork::retire: contractor " + std::to_string(i) + " (" + describe_node(i) +
                  ") was given by add_node and cannot be laid out anew");
    }
  }
  std::size_t kept = 0;
  ctc_names_.resize(nodes_.size());
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (gone[i]) continue;
    if (kept == i) {  // no self-move (it would empty the record)
      ++kept;
      continue;
    }
    nodes_[kept] = std::move(nodes_[i]);
    records_[kept] = std::move(records_[i]);
    fresh_[kept] = fresh_[i];
    ctc_names_[kept] = std::move(ctc_names_[i]);
    ++kept;
  }
  nodes_.resize(kept);
  records_.resize(kept);
  fresh_.resize(kept);
  ctc_names_.resize(kept);
  rebuild_nodes(true);
}

bool ContractorNetworkImpl::relay_in_place(const std::vector<char>& gone) {
  const std::size_t nd = domains_.size();
  // The domains that changed, each only shifted: from[d] its former atom count, dropped[d] at its start.
  std::vector<std::size_t> from(nd, kNoAtom), dropped(nd, 0);
  std::vector<std::shared_ptr<Domain>> now(nd);
  for (std::size_t d = 0; d < nd; ++d) {
    if (!domains_[d]->layout_changed()) continue;
    const std::optional<std::size_t> shift = domains_[d]->dropped_atoms();
    if (!shift || !(now[d] = domains_[d]->relaid())) return false;
    from[d] = domains_[d]->nb_atoms(), dropped[d] = *shift;
  }
  // Every node kept is this network's own (it renumbers them), and follows the shifts.
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (!gone.empty() && gone[i]) continue;
    if (!records_[i].make) return false;
    for (const auto& a : nodes_[i]->ranges()) {
      if (from[a.domain] != kNoAtom && !nodes_[i]->follows_appends()) return false;
    }
  }
  // Nothing fails below.
  for (std::size_t d = 0; d < nd; ++d) {
    if (now[d]) domains_[d] = std::move(now[d]);
  }
  // The nodes kept, in order, following their domains; the domains only the retired ones used, dropped.
  std::vector<char> used(nd, 0), orphaned(nd, 0);
  std::size_t kept = 0;
  ctc_names_.resize(nodes_.size());
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    const bool retired = !gone.empty() && gone[i];
    for (const auto& a : nodes_[i]->ranges()) (retired ? orphaned : used)[a.domain] = 1;
    if (retired) continue;
    // Made by this network for itself (records_[i].make): no one else holds it.
    const_cast<CnNode&>(*nodes_[i]).follow_shift(from, dropped, domains_);
    if (kept != i) {  // no self-move (it would empty a record or a name)
      nodes_[kept] = std::move(nodes_[i]);
      records_[kept] = std::move(records_[i]);
      fresh_[kept] = fresh_[i];
      ctc_names_[kept] = std::move(ctc_names_[i]);
    }
    ++kept;
  }
  nodes_.resize(kept), records_.resize(kept), fresh_.resize(kept), ctc_names_.resize(kept);
  std::vector<std::size_t> index(nd, kNoAtom);
  std::size_t nb = 0;
  for (std::size_t d = 0; d < nd; ++d) {
    if (orphaned[d] && !used[d]) {
      index_.erase(domains_[d]->key());
      continue;
    }
    index[d] = nb;
    if (nb != d) {
      domains_[nb] = std::move(domains_[d]);
      names_[nb] = std::move(names_[d]);
      checked_[nb] = checked_[d];
      index_[domains_[nb]->key()] = nb;
    }
    ++nb;
  }
  domains_.resize(nb), names_.resize(nb), checked_.resize(nb);
  // Who watches what, from the nodes as they are now.
  watchers_.clear(), users_.assign(nb, {});
  for (std::size_t d = 0; d < nb; ++d) watchers_.emplace_back(domains_[d]->nb_atoms());
  dirty_.clear_nodes();
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (nb < nd) const_cast<CnNode&>(*nodes_[i]).renumber_domains(index);
    watch(i, *nodes_[i]);
  }
  grown_from_.clear(), grown_done_.clear();
  forget_dropped_touches();
  note_time_layouts();
  return true;
}

void ContractorNetworkImpl::forget_dropped_touches() {
  std::erase_if(touched_, [&](const Touch& t) {
    const auto& parts = t.ref.parts();
    return std::any_of(parts.begin(), parts.end(), [&](const auto& p) { return !index_.contains(p.domain->key()); });
  });
}

void ContractorNetworkImpl::rebuild_nodes(bool rebind) {
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (records_[i].make) continue;
    for (const auto& a : nodes_[i]->ranges()) {
      if (domains_[a.domain]->layout_changed()) {
        throw Error("ContractorNetwork: contractor " + std::to_string(i) + " (" + describe_node(i) +
                    ") was given by add_node and cannot be laid out anew on " + label(a.domain));
      }
    }
  }
  auto old = std::move(nodes_);
  auto records = std::move(records_);
  auto fresh = std::move(fresh_);
  nodes_.clear();
  records_.clear();
  fresh_.clear();
  // What a domain carries besides its object, found again by key after a rebind.
  struct Kept {
    std::string name;
    char checked;
  };
  std::unordered_map<const void*, Kept> kept;
  if (rebind) {  // from an empty network: the domains come back as the records bind them
    for (std::size_t d = 0; d < domains_.size(); ++d) kept.emplace(domains_[d]->key(), Kept{names_[d], checked_[d]});
    domains_.clear();
    names_.clear();
    index_.clear();
    watchers_.clear();
    users_.clear();
    checked_.clear();
  }
  // relayout: which domains changed, and the atoms of those that only grew at the end.
  std::vector<char> changed(domains_.size(), 0);
  std::vector<std::size_t> grown_from(domains_.size(), kNoAtom);
  if (!rebind) {
    for (std::size_t d = 0; d < domains_.size(); ++d) {
      if (!domains_[d]->layout_changed()) continue;
      changed[d] = 1;
      if (domains_[d]->appended_only()) grown_from[d] = domains_[d]->nb_atoms();
      if (auto now = domains_[d]->relaid()) domains_[d] = std::move(now);
    }
    for (std::size_t d = 0; d < domains_.size(); ++d) {
      watchers_[d] = Watchers(domains_[d]->nb_atoms());
      users_[d] = {};
    }
  }
  dirty_.clear_nodes();
  // Every node again, in the same order (the watchers name nodes by index): as
  // it was if its domains did not change, grown in place if they only grew
  // and it follows appends (the observations, many), else built anew.
  for (std::size_t i = 0; i < old.size(); ++i) {
    bool touches = false, grows = true;
    for (const auto& a : old[i]->ranges()) {
      if (rebind || !changed[a.domain]) continue;
      touches = true;
      grows = grows && grown_from[a.domain] != kNoAtom;
    }
    std::shared_ptr<const CnNode> node = old[i];
    if (rebind || (touches && records[i].make && !(grows && old[i]->follows_appends()))) {
      node = records[i].make(bind(records[i].refs));
    } else if (touches) {  // made by this network for itself: no one else holds it
      (void)const_cast<CnNode&>(*old[i]).follow_appends(grown_from, domains_);
    }
    add_node(std::move(node));
    records_.back() = std::move(records[i]);
    fresh_.back() = fresh[i];
  }
  for (std::size_t d = 0; d < domains_.size(); ++d) {
    const auto it = kept.find(domains_[d]->key());
    if (it == kept.end()) continue;
    names_[d] = it->second.name;
    checked_[d] = it->second.checked;
  }
  if (rebind) forget_dropped_touches();
  note_time_layouts();
}

}  // namespace sillage::detail
