#include "sillage/cn/tube_ctc_node.h"

#include <algorithm>

#include "sillage/ctc/shrink.h"
#include "sillage/error.h"
#include "sillage/tube/time_box_ctc.h"

namespace sillage {

namespace {

// At most this many passes over all time elements for constants to settle
// (each pass is a valid contraction: stopping early loses no solution).
constexpr int kMaxParamPasses = 64;

std::string name_of(const std::shared_ptr<const Ctc>& ctc) {
  if (!ctc) throw Error("ContractorNetwork::add: null contractor");
  return ctc->name();
}

}  // namespace

TubeCtcNode::TubeCtcNode(std::shared_ptr<const Ctc> ctc, const std::vector<BoundDomain>& args)
    : TubeNode(name_of(ctc), args), ctc_(std::move(ctc)) {
  std::size_t nb_vars = 0;
  for (std::size_t g = 0; g < nb_args(); ++g) {
    if (tube(g)) whole_tubes(g, 1, "tube arguments");
    const std::size_t count = tube(g) ? 1 : ranges()[g].count;
    var_range_.insert(var_range_.end(), count, g);
    nb_vars += count;
    if (!tube(g)) nb_params_ += count;
  }
  if (nb_vars != ctc_->nb_vars()) {
    throw DimensionError(where() + ": the contractor acts on " + std::to_string(ctc_->nb_vars()) +
                         " variables but the domains given make " + std::to_string(nb_vars) +
                         " (a tube counts as one variable)");
  }
}

bool TubeCtcNode::contract_atoms(NodeRun& r, const std::vector<std::size_t>& atoms, IntervalVector& params) const {
  std::vector<detail::TimeVar> vars(var_range_.size());
  std::vector<TubeChanges> out(var_range_.size());
  std::size_t p = 0;
  for (std::size_t v = 0; v < vars.size(); ++v) {
    const auto& t = tube(var_range_[v]);
    vars[v] = t ? detail::TimeVar{&t->tube(), 0} : detail::TimeVar{nullptr, p++};
    out[v] = changes(r, var_range_[v]);
  }
  const std::size_t empty = detail::contract_time_elements(
      *ctc_, vars, atoms, params,
      [&out](std::size_t v, std::size_t i, const Interval& before, const Interval& after) {
        out[v].atom(i, before, after);
      });
  if (empty == detail::kNoTimeAtom) return true;
  for (std::size_t g = 0; g < nb_args() && r.empty_at == kNoAtom; ++g) {
    if (tube(g)) r.empty_at = offset(g) + empty;
  }
  return false;
}

bool TubeCtcNode::run(NodeRun& r) const {
  // The time atoms to contract: all when a constant changed.
  bool constants = false;
  std::vector<std::size_t> atoms = dirty_time_atoms(r, constants);
  const auto all_atoms = [&] {
    atoms.resize(nb_time_atoms());
    for (std::size_t i = 0; i < nb_time_atoms(); ++i) atoms[i] = i;
  };
  if (constants) all_atoms();

  // Constants: read, intersect with every contracted time element, write back.
  IntervalVector params(std::max<std::size_t>(nb_params_, 1));
  const auto read_params = [&] {
    std::size_t p = 0;
    for (std::size_t g = 0; g < nb_args(); ++g) {
      if (tube(g)) continue;
      for (std::size_t c = 0; c < ranges()[g].count; ++c) params[p++] = r.domains[ranges()[g].domain]->atom(ranges()[g].first + c);
    }
  };
  // Writes the constants back; true if one shrank by more than the ratio.
  const auto write_params = [&] {
    bool moved = false;
    std::size_t p = 0;
    for (std::size_t g = 0; g < nb_args(); ++g) {
      if (tube(g)) continue;
      Domain& d = *r.domains[ranges()[g].domain];
      for (std::size_t c = 0; c < ranges()[g].count; ++c, ++p) {
        const Interval cur = d.atom(ranges()[g].first + c);
        const Interval now = cur & params[p];
        if (now != cur) d.set_atom(ranges()[g].first + c, now);
        if (shrank(cur, now, r.ratio)) {
          r.changed.push_back(offset(g) + c);
          moved = true;
        }
      }
    }
    return moved;
  };

  read_params();
  if (!contract_atoms(r, atoms, params)) {
    write_params();
    return false;
  }
  for (int pass = 0; write_params() && pass < kMaxParamPasses; ++pass) {
    if (params.is_empty()) return false;
    if (atoms.size() != nb_time_atoms()) all_atoms();
    read_params();
    if (!contract_atoms(r, atoms, params)) {
      write_params();
      return false;
    }
  }
  return !params.is_empty() || nb_params_ == 0;
}

}  // namespace sillage
