#include "sillage/cn/network_impl.h"

#include <algorithm>
#include <chrono>

#include "sillage/cn/round_order.h"
#include "sillage/cn/tube_ctc_node.h"
#include "sillage/cn/tube_domain.h"
#include "sillage/ctc/shrink.h"
#include "sillage/error.h"

namespace sillage::detail {

void ContractorNetworkImpl::set_name(const DomainRef& d, const std::string& name) {
  if (name.empty()) throw Error("ContractorNetwork::set_name: empty name");
  const auto& parts = d.parts();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    names_[add_domain(parts[i].domain)] = parts.size() == 1 ? name : name + "[" + std::to_string(i) + "]";
  }
}

void ContractorNetworkImpl::check_not_contracting(const char* where) const {
  if (contracting_) throw Error(std::string("ContractorNetwork::") + where + ": called during contract()");
}

std::size_t ContractorNetworkImpl::add_domain(const std::shared_ptr<Domain>& domain) {
  check_not_contracting("add_domain");
  if (!domain) throw Error("ContractorNetwork: null domain");
  const auto it = index_.find(domain->key());
  if (it != index_.end()) {
    check_layout(it->second);
    return it->second;
  }
  const std::size_t d = domains_.size();
  if (const auto* tube = dynamic_cast<const TubeDomain*>(domain.get())) {
    const auto& td = tube->tube().tdomain();
    if (std::none_of(time_layouts_.begin(), time_layouts_.end(), [&](const auto& l) { return l.td == td; }))
      time_layouts_.push_back({td, td->nb_slices(), td->nb_forgotten()});
  }
  domains_.push_back(domain);
  names_.emplace_back();
  checked_.push_back(0);
  watchers_.emplace_back(domain->nb_atoms());
  users_.emplace_back();
  index_.emplace(domain->key(), d);
  return d;
}

std::vector<BoundDomain> ContractorNetworkImpl::bind(const std::vector<DomainRef>& domains) {
  for (const auto& r : domains) {
    for (const auto& p : r.parts()) {
      const auto it = index_.find(p.domain->key());
      if (it != index_.end()) check_layout(it->second);
    }
  }
  std::vector<BoundDomain> bound;
  for (const auto& r : domains) {
    for (const auto& p : r.parts()) {
      // A whole tube referred to before its TDomain gained time points: the
      // whole tube as it is now.
      std::shared_ptr<Domain> dom = p.domain;
      std::size_t count = p.count;
      // Registered and laid out as it is now: that domain object (no new one per reference).
      if (const auto it = index_.find(dom->key()); it != index_.end() && dom->layout_changed() &&
                                                  !domains_[it->second]->layout_changed()) {
        if (p.first == 0 && p.count == dom->nb_atoms()) count = domains_[it->second]->nb_atoms();
        dom = domains_[it->second];
      } else if (dom->layout_changed() && p.first == 0 && p.count == dom->nb_atoms()) {
        if (auto now = dom->relaid()) {
          dom = now;
          count = dom->nb_atoms();
        }
      }
      const std::size_t d = add_domain(dom);
      bound.push_back({domains_[d], {d, p.first, count}});
    }
  }
  return bound;
}

void ContractorNetworkImpl::add(std::shared_ptr<const Ctc> ctc, const std::vector<DomainRef>& domains) {
  check_not_contracting("add");
  if (!ctc) throw Error("ContractorNetwork::add: null contractor");
  add_bound(domains, [ctc](const std::vector<BoundDomain>& bound) -> std::shared_ptr<const CnNode> {
    std::vector<AtomRange> ranges;
    bool any_tube = false;
    for (const auto& b : bound) {
      ranges.push_back(b.range);
      any_tube = any_tube || std::dynamic_pointer_cast<TubeDomain>(b.domain);
    }
    // The node constructors check the arguments (DimensionError naming ctc).
    if (any_tube) return std::make_shared<TubeCtcNode>(ctc, bound);
    return std::make_shared<CtcNode>(ctc, std::move(ranges));
  });
}

void ContractorNetworkImpl::add(std::shared_ptr<const NetworkCtc> ctc, const std::vector<DomainRef>& domains) {
  check_not_contracting("add");
  if (!ctc) throw Error("ContractorNetwork::add: null contractor");
  add_bound(domains,
            [ctc, domains](const std::vector<BoundDomain>& bound) { return ctc->make_node_for(domains, bound); });
  NetworkCtc::Gates g = ctc->gates_for(domains);
  if (g.tdomain && !g.times.empty()) pending_gates_.push_back(std::move(g));
}

void ContractorNetworkImpl::add_bound(const std::vector<DomainRef>& domains, const Make& make) {
  // The node validates its arguments: on an error, forget the domains this
  // call registered, so that a failed add leaves the network unchanged.
  const std::size_t nb_before = domains_.size();
  try {
    add_node(make(bind(domains)));
    records_.back() = {domains, make};
  } catch (...) {
    if (records_.size() > nodes_.size()) records_.pop_back();
    while (domains_.size() > nb_before) {
      index_.erase(domains_.back()->key());
      domains_.pop_back();
      names_.pop_back();
      checked_.pop_back();
      watchers_.pop_back();
      users_.pop_back();
    }
    throw;
  }
}

void ContractorNetworkImpl::add_node(std::shared_ptr<const CnNode> node) {
  check_not_contracting("add_node");
  if (!node) throw Error("ContractorNetwork::add_node: null node");
  for (const auto& a : node->ranges()) {
    if (a.domain >= domains_.size() || a.first > domains_[a.domain]->nb_atoms() ||
        a.count > domains_[a.domain]->nb_atoms() - a.first) {
      throw DimensionError("ContractorNetwork::add_node: " + node->name() + " refers to unknown domain atoms");
    }
  }
  watch(nodes_.size(), *node);
  nodes_.push_back(std::move(node));
  records_.emplace_back();
  fresh_.push_back(1);
}

void ContractorNetworkImpl::watch(std::size_t id, const CnNode& node) {
  dirty_.add_node(node);
  for (std::size_t g = 0; g < node.ranges().size(); ++g) {
    const AtomRange& a = node.ranges()[g];
    const AtomRange& w = node.watched()[g];
    if (w.count > 0) watchers_[a.domain].add({id, g, w.first, w.count});
    Users& u = users_[a.domain];
    if (u.nodes.empty() || u.nodes.back() != id) u.nodes.push_back(id), u.follow = -1;
  }
}

bool ContractorNetworkImpl::acts_on(const CnNode& node, const TDomain& td) const {
  for (const auto& a : node.ranges()) {
    const auto* t = dynamic_cast<const TubeDomain*>(domains_[a.domain].get());
    if (t && t->tube().tdomain().get() == &td) return true;
  }
  return false;
}

void ContractorNetworkImpl::add_pending_gates() {
  if (pending_gates_.empty()) return;
  const auto pending = std::move(pending_gates_);
  pending_gates_.clear();
  bool sampled = false;
  const bool laid_out = std::none_of(domains_.begin(), domains_.end(), [](const auto& d) { return d->layout_changed(); });
  for (const auto& g : pending) {
    const bool rebuildable = std::none_of(nodes_.begin(), nodes_.end(), [&](const auto& n) {
      return !records_[static_cast<std::size_t>(&n - nodes_.data())].make && acts_on(*n, *g.tdomain);
    });
    if (!rebuildable || !laid_out) continue;
    for (const double t : g.times) {
      if (t > g.tdomain->t0() && t < g.tdomain->tf() && !g.tdomain->is_time_point(t)) {
        g.tdomain->sample(t);
        sampled = true;
      }
    }
  }
  if (sampled) rebuild_nodes(false);
}

void ContractorNetworkImpl::set_ratio(double ratio) {
  check_ratio(ratio, "ContractorNetwork::set_ratio");
  ratio_ = ratio;
}

// The label is built only for the error: bind() checks every domain it meets
// (on plaza1.toml the labels of the 3529 rows' domains were 23 % of the build).
void ContractorNetworkImpl::check_layout(std::size_t d) const {
  if (domains_[d]->layout_changed()) domains_[d]->check_layout(label(d));
}

std::string ContractorNetworkImpl::label(std::size_t d) const {
  return "domain " + std::to_string(d) + " (" + domains_[d]->kind() + ")";
}
void ContractorNetworkImpl::check_layouts_after(const CnNode& node) const {
  for (const auto& a : node.ranges()) {
    const Domain& d = *domains_[a.domain];
    if (d.layout_changed()) d.check_layout(label(a.domain) + ", changed during contract() (" + node.describe() + "),");
  }
}

void ContractorNetworkImpl::check_layouts_before(const CnNode& node) const {
  for (const auto& a : node.ranges()) check_layout(a.domain);
}

void ContractorNetworkImpl::note_time_layouts() {
  for (TimeLayout& l : time_layouts_) l.slices = l.td->nb_slices(), l.forgotten = l.td->nb_forgotten();
}

bool ContractorNetworkImpl::time_layouts_unchanged() const {
  return std::all_of(time_layouts_.begin(), time_layouts_.end(), [](const TimeLayout& l) {
    return l.td->nb_slices() == l.slices && l.td->nb_forgotten() == l.forgotten;
  });
}

void ContractorNetworkImpl::set_ctc_name(std::size_t i, const std::string& name) {
  if (i >= nodes_.size())
    throw Error("ContractorNetwork::set_ctc_name: no contractor " + std::to_string(i) + " (" +
                std::to_string(nodes_.size()) + " added)");
  if (name.empty()) throw Error("ContractorNetwork::set_ctc_name: empty name");
  if (ctc_names_.size() <= i) ctc_names_.resize(i + 1);
  ctc_names_[i] = name;
}

void ContractorNetworkImpl::set_budget(const Budget& budget) {
  check_budget(budget, "ContractorNetwork::set_budget");
  budget_ = budget;
}

ContractStats ContractorNetworkImpl::contract() {
  ContractStats stats = contract_run();
  if (!stats.summary.finished()) {
    stopped_stats_ = stats;  // the runs done: the summary of a stopped solve
    throw_unfinished(stats.summary);
  }
  return stats;
}

ContractStats ContractorNetworkImpl::contract_run() { return propagate(true); }

ContractStats ContractorNetworkImpl::update() { return propagate(false); }

ContractStats ContractorNetworkImpl::propagate(bool all) {
  check_not_contracting(all ? "contract" : "update");
  add_pending_gates();
  const auto start = std::chrono::steady_clock::now();
  struct Running {
    bool& flag;
    explicit Running(bool& f) : flag(f) { flag = true; }
    ~Running() { flag = false; }
  } running(contracting_);
  ContractStats stats;
  const auto finish = [&] {
    stats.time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Summary& s = stats.summary;
    if (s.status == Status::Converged && stats.empty) {
      s.status = Status::NoSolution;
      s.reason = stats.emptiness;
    }
    s.rounds = stats.iterations;
    s.work = stats.contractor_calls;
    s.seconds = stats.time;
    return stats;
  };
  // One pass over each domain: an empty one, or a tube with a gate off its
  // slices, is no solution before any contractor runs.
  // update(): the domains registered since, and the atoms of the others touched since (check_touched);
  // while no TDomain moved, the layouts of the nodes that run only (before each run).
  const bool quick = !all && time_layouts_unchanged();
  for (std::size_t d = 0; d < domains_.size(); ++d) {
    if (!all && checked_[d]) {
      if (!quick) check_layout(d);
      continue;
    }
    check_layout(d);
    if (stats.empty) continue;
    explain_empty_on_input(stats, d);
    checked_[d] = !stats.empty;
  }
  if (!quick) note_time_layouts();
  // The touched domains are read below (their atoms wake the nodes): their layouts first.
  for (const Touch& touch : touched_) {
    for (const auto& part : touch.ref.parts()) check_layout(index_.at(part.domain->key()));
  }
  if (!all && !stats.empty) check_touched(stats);
  if (stats.empty) return finish();

  // The hook is called once per round (below), not per unit of work.
  Budget metered = budget_;
  metered.progress = nullptr;
  BudgetMeter meter(metered, "ContractorNetwork::contract", "the network's budget (set_budget)", "", 0,
                    "contractor calls");
  dirty_.reset();
  std::vector<DerivativePair> derivatives;
  for (const auto& node : nodes_) node->derivative_pairs(derivatives);
  // Buffers reused by every run: the round, the next one, what a node shrank, what woke it.
  std::vector<std::size_t> round, next, changed, dirty;
  std::vector<char> queued(nodes_.size(), 0);
  if (all) std::fill(fresh_.begin(), fresh_.end(), 1);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (fresh_[i]) {
      round.push_back(i);
      queued[i] = 1;
    }
  }
  if (!all) wake_touched(round, queued);
  touched_.clear();
  detail::RoundOrder order(scheduling_, nodes_.size());
  while (!round.empty()) {
    ++stats.iterations;
    order.order(round, dirty_);
    for (const std::size_t i : round) {
      queued[i] = 0;
      changed.clear();
      const CnNode& node = *nodes_[i];
      dirty_.take(i, node, dirty);
      if (quick) check_layouts_before(node);
      NodeRun run{domains_, ratio_, fresh_[i] != 0, dirty, changed};
      run.derivatives = derivatives;
      run.cancel = &budget_.cancel;
      if (!meter.try_add()) {  // a budget spent or cancelled: the domains so far are still enclosures
        const Summary m = meter.summary();
        stats.summary.status = m.status;
        stats.summary.reason = m.reason;
        return finish();
      }
      fresh_[i] = 0;
      ++stats.contractor_calls;
      bool ok = true;
      try {
        ok = node.run(run);
      } catch (const Cancelled& e) {  // within a long node (CtcIvp, CtcPImpliesZ): its writes are contractions
        if (!budget_.cancel.cancelled()) throw;  // not the network's token: not a cancellation of this run
        stats.summary.status = Status::Cancelled;
        stats.summary.reason = e.what();
        return finish();
      }
      order.ran(i, changed.size(), node.nb_atoms());
      check_layouts_after(node);
      if (!ok) {
        explain_node_empty(stats, i, run);
        stats.empty_node = i;
        return finish();
      }
      for (const std::size_t k : changed) {
        // The range holding position k, then the atom it is.
        const std::size_t g = node.range_of(k);
        const AtomRange& a = node.ranges()[g];
        const std::size_t atom = a.first + k - node.offset(g);
        watchers_[a.domain].for_each(atom, [&](std::size_t w, std::size_t wg) {
          // A node never wakes itself; one already recorded for this atom is queued.
          if (w != i && dirty_.mark(w, wg, atom) && !queued[w]) {
            queued[w] = 1;
            next.push_back(w);
          }
        });
      }
      if (run.again && !queued[i]) {
        queued[i] = 1;
        next.push_back(i);
      }
    }
    round.swap(next);
    next.clear();
    if (budget_.progress) {
      budget_.progress(Progress{"ContractorNetwork::contract", stats.iterations, stats.contractor_calls,
                                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
    }
  }
  // Changed by a node that does not act on it (each node's own are checked after its run): found here,
  // or by update() before a node reads it.
  for (std::size_t d = 0; d < domains_.size() && !quick; ++d) {
    if (domains_[d]->layout_changed()) domains_[d]->check_layout(label(d) + ", changed during contract(),");
  }
  return finish();
}

}  // namespace sillage::detail
