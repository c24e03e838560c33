#include "sillage/cn/tube_node.h"

#include <algorithm>

#include "sillage/cn/empty_prefix.h"
#include "sillage/error.h"

namespace sillage {

namespace {

std::vector<AtomRange> ranges_of(const std::vector<BoundDomain>& args) {
  std::vector<AtomRange> r;
  r.reserve(args.size());
  for (const auto& a : args) r.push_back(a.range);
  return r;
}

}  // namespace

TubeNode::TubeNode(std::string name, const std::vector<BoundDomain>& args)
    : CnNode(ranges_of(args)), name_(std::move(name)) {
  tubes_.reserve(args.size());
  for (const auto& a : args) {
    tubes_.push_back(std::dynamic_pointer_cast<TubeDomain>(a.domain));
    if (tubes_.back() && first_tube_ == static_cast<std::size_t>(-1)) first_tube_ = tubes_.size() - 1;
  }
}

std::vector<std::shared_ptr<TubeDomain>> TubeNode::whole_tubes(std::size_t first, std::size_t n,
                                                               const char* what) const {
  const TubeDomain* ref = nullptr;
  for (const auto& t : tubes_)
    if (t && !ref) ref = t.get();
  std::vector<std::shared_ptr<TubeDomain>> out;
  for (std::size_t i = first; i < first + n; ++i) {
    const auto t = i < tubes_.size() ? tubes_[i] : nullptr;
    if (!t) throw DimensionError(where() + ": " + what + " must be tubes (argument " + std::to_string(i) + ")");
    if (ranges()[i].first != 0 || ranges()[i].count != t->nb_atoms()) {
      throw DimensionError(where() + ": " + what + " must be whole tubes (all their slices and gates, argument " +
                           std::to_string(i) + ")");
    }
    if (t->tube().tdomain() != ref->tube().tdomain()) {
      throw DimensionError(where() + ": the tubes are not on one TDomain (argument " + std::to_string(i) + ")");
    }
    out.push_back(t);
  }
  return out;
}

std::vector<std::size_t> TubeNode::dirty_time_atoms(const NodeRun& run, bool& constants) const {
  std::vector<std::size_t> atoms;
  constants = false;
  if (run.all) {
    atoms.resize(nb_time_atoms());
    for (std::size_t i = 0; i < nb_time_atoms(); ++i) atoms[i] = i;
    return atoms;
  }
  // Several tubes interleave their atoms: a short list is sorted, a long one
  // merged through flags.
  const bool long_list = 3 * run.dirty.size() > nb_time_atoms() / 16;
  std::vector<char> mark(long_list ? nb_time_atoms() : 0, 0);
  std::size_t g = 0;
  for (const std::size_t pos : run.dirty) {  // sorted: the range only moves forward
    while (g + 1 < tubes_.size() && offset(g + 1) <= pos) ++g;
    if (!tubes_[g]) {
      constants = true;
      continue;
    }
    const std::size_t i = pos - offset(g);
    const std::size_t lo = is_slice(i) ? i - 1 : i, hi = is_slice(i) ? i + 1 : i;
    for (std::size_t j = lo; j <= hi; ++j) {
      if (long_list) mark[j] = 1;
      else atoms.push_back(j);
    }
  }
  if (long_list) {
    for (std::size_t j = 0; j < nb_time_atoms(); ++j)
      if (mark[j]) atoms.push_back(j);
  } else {
    std::sort(atoms.begin(), atoms.end());
    atoms.erase(std::unique(atoms.begin(), atoms.end()), atoms.end());
  }
  return atoms;
}

bool TubeNode::dirty_slices(const NodeRun& run, std::size_t r, std::size_t& first, std::size_t& last) const {
  const std::size_t n = tubes_.at(r) ? ranges()[r].count / 2 : 0;
  if (n == 0) return false;
  if (run.all) {
    first = 0;
    last = n - 1;
    return true;
  }
  const std::size_t lo = offset(r), hi = lo + ranges()[r].count;
  const auto b = std::lower_bound(run.dirty.begin(), run.dirty.end(), lo);
  const auto e = std::lower_bound(b, run.dirty.end(), hi);
  if (b == e) return false;
  const std::size_t a0 = *b - lo, a1 = *(e - 1) - lo;
  first = is_slice(a0) || a0 == 0 ? a0 / 2 : a0 / 2 - 1;
  last = std::min(a1 / 2, n - 1);
  return true;
}

bool TubeNode::contract_tube(NodeRun& run, std::size_t r, const std::function<bool(Tube&)>& contract) const {
  thread_local TubeSnapshot before;  // scratch: per thread, never shared by two runs
  Tube& x = tubes_.at(r)->tube();
  before.take(x);
  const bool ok = contract(x);
  changes(run, r).diff(before, x);
  if (ok) return true;
  // x is now empty everywhere: find from its former value where it stopped being consistent.
  const std::size_t a = detail::first_empty_prefix(before.restore(x.tdomain()), contract);
  if (a < x.nb_slices() * 2 + 1) run.empty_at = offset(r) + a;
  return false;
}

bool TubeNode::empty_tubes(NodeRun& run, std::size_t first, std::size_t n) const {
  for (std::size_t j = first; j < first + n; ++j) {
    Tube& x = tubes_.at(j)->tube();
    const TubeChanges out = changes(run, j);
    for (std::size_t k = 0; k <= x.nb_slices(); ++k) out.gate(k, x.gate(k), Interval::empty());
    for (std::size_t k = 0; k < x.nb_slices(); ++k) out.slice(k, x.slice(k), Interval::empty());
    x.set(Interval::empty());
  }
  return false;
}

}  // namespace sillage
