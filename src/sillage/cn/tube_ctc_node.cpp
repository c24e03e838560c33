#include "sillage/cn/tube_ctc_node.h"

#include <algorithm>

#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/shrink.h"
#include "sillage/error.h"

namespace sillage {

namespace {

// At most this many passes over all time elements for constants to settle
// (each pass is a valid contraction: stopping early loses no solution).
constexpr int kMaxParamPasses = 64;

Interval& time_atom(TubeData& d, std::size_t i) { return (i & 1) ? d.slices[i / 2] : d.gates[i / 2]; }

}  // namespace

TubeCtcNode::TubeCtcNode(std::shared_ptr<const Ctc> ctc, std::vector<AtomRange> ranges,
                         std::vector<std::shared_ptr<TubeDomain>> tubes)
    : CnNode(std::move(ranges)), ctc_(std::move(ctc)), tubes_(std::move(tubes)) {
  if (!ctc_) throw Error("ContractorNetwork::add: null contractor");
  const std::string where = "ContractorNetwork::add(" + ctc_->name() + ")";
  if (tubes_.size() != this->ranges().size()) throw Error(where + ": one entry per range expected");
  std::size_t nb_vars = 0;
  const TDomain* td = nullptr;
  for (std::size_t g = 0; g < tubes_.size(); ++g) {
    const AtomRange& a = this->ranges()[g];
    if (!tubes_[g]) {
      nb_vars += a.count;
      nb_params_ += a.count;
      continue;
    }
    ++nb_vars;
    const Tube& x = tubes_[g]->tube();
    if (a.first != 0 || a.count != tubes_[g]->nb_atoms()) {
      throw DimensionError(where + ": argument " + std::to_string(g) +
                           " must be a whole tube (all its slices and gates)");
    }
    if (td && x.tdomain().get() != td) {
      throw DimensionError(where + ": the tubes are not on one TDomain (argument " + std::to_string(g) + ")");
    }
    td = x.tdomain().get();
    nb_time_atoms_ = tubes_[g]->nb_atoms();
  }
  if (nb_vars != ctc_->nb_vars()) {
    throw DimensionError(where + ": the contractor acts on " + std::to_string(ctc_->nb_vars()) +
                         " variables but the domains given make " + std::to_string(nb_vars) +
                         " (a tube counts as one variable)");
  }
  if (const auto* cf = dynamic_cast<const CtcFunction*>(ctc_.get())) {
    f_ = &cf->function();
    image_ = &cf->image();
  }
}

bool TubeCtcNode::contract_box(IntervalVector& box) const {
  if (f_) return f_->hc4_revise(box, *image_);
  ctc_->contract(box);
  return !box.is_empty();
}

bool TubeCtcNode::contract_atoms(NodeRun& r, const std::vector<std::size_t>& atoms, IntervalVector& params) const {
  const std::size_t n = ctc_->nb_vars();
  IntervalVector box(n), before(n);
  const std::size_t last = nb_time_atoms_ - 1;
  std::vector<char> touched(tubes_.size(), 0);
  // Slices first, then gates (which are intersected with their slices).
  for (const int parity : {1, 0}) {
    for (const std::size_t i : atoms) {
      if (static_cast<int>(i & 1) != parity) continue;
      std::size_t v = 0, p = 0;
      for (std::size_t g = 0; g < tubes_.size(); ++g) {
        if (!tubes_[g]) {
          for (std::size_t c = 0; c < ranges()[g].count; ++c) box[v++] = params[p++];
          continue;
        }
        TubeData& d = tubes_[g]->tube().data();
        Interval& x = time_atom(d, i);
        if (parity == 0) {  // x(t_k) lies in both neighbouring slices
          Interval h = x;
          if (i > 0) h &= d.slices[i / 2 - 1];
          if (i < last) h &= d.slices[i / 2];
          if (h != x) {
            if (shrank(x, h, r.ratio)) r.changed.push_back(offset(g) + i);
            x = h;
            touched[g] = 1;
          }
        }
        box[v++] = x;
      }
      before = box;
      const bool ok = contract_box(box);
      v = p = 0;
      for (std::size_t g = 0; g < tubes_.size(); ++g) {
        if (!tubes_[g]) {
          for (std::size_t c = 0; c < ranges()[g].count; ++c, ++v) params[p++] &= ok ? box[v] : Interval::empty();
          continue;
        }
        TubeData& d = tubes_[g]->tube().data();
        Interval& x = time_atom(d, i);
        const Interval now = ok ? (x & box[v]) : Interval::empty();
        if (now != x) {
          if (shrank(before[v], now, r.ratio)) r.changed.push_back(offset(g) + i);
          x = now;
          touched[g] = 1;
        }
        ++v;
      }
      if (!ok) {
        for (std::size_t g = 0; g < tubes_.size(); ++g)
          if (touched[g]) tubes_[g]->tube().touch();
        return false;
      }
    }
  }
  for (std::size_t g = 0; g < tubes_.size(); ++g)
    if (touched[g]) tubes_[g]->tube().touch();
  return true;
}

bool TubeCtcNode::run(NodeRun& r) const {
  // The time atoms to contract.
  std::vector<std::size_t> atoms;
  bool all = r.all;
  if (!all) {
    // r.dirty is sorted, so within one tube the atoms (with the gates of
    // the changed slices) come out sorted; several tubes need a sort.
    bool sorted = true;
    const auto push = [&](std::size_t i) {
      if (!atoms.empty() && i <= atoms.back()) {
        if (i == atoms.back()) return;
        sorted = false;
      }
      atoms.push_back(i);
    };
    for (const std::size_t pos : r.dirty) {
      const std::size_t g = static_cast<std::size_t>(
          std::upper_bound(ranges().begin(), ranges().end(), pos,
                           [&](std::size_t p, const AtomRange& a) { return p < offset(&a - ranges().data()); }) -
          ranges().begin() - 1);
      if (!tubes_[g]) {  // a constant changed: every time element may shrink
        all = true;
        break;
      }
      const std::size_t i = pos - offset(g);
      if (i & 1) {  // a slice: with its two gates
        push(i - 1);
        push(i);
        push(i + 1);
      } else {
        push(i);
      }
    }
    if (!sorted) {
      std::sort(atoms.begin(), atoms.end());
      atoms.erase(std::unique(atoms.begin(), atoms.end()), atoms.end());
    }
  }
  if (all) {
    atoms.resize(nb_time_atoms_);
    for (std::size_t i = 0; i < nb_time_atoms_; ++i) atoms[i] = i;
  }

  // Constants: read, intersect with every contracted time element, write back.
  IntervalVector params(std::max<std::size_t>(nb_params_, 1));
  const auto read_params = [&] {
    std::size_t p = 0;
    for (std::size_t g = 0; g < tubes_.size(); ++g) {
      if (tubes_[g]) continue;
      for (std::size_t c = 0; c < ranges()[g].count; ++c) params[p++] = r.domains[ranges()[g].domain]->atom(ranges()[g].first + c);
    }
  };
  // Writes the constants back; true if one shrank by more than the ratio.
  const auto write_params = [&] {
    bool moved = false;
    std::size_t p = 0;
    for (std::size_t g = 0; g < tubes_.size(); ++g) {
      if (tubes_[g]) continue;
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
    if (atoms.size() != nb_time_atoms_) {
      atoms.resize(nb_time_atoms_);
      for (std::size_t i = 0; i < nb_time_atoms_; ++i) atoms[i] = i;
    }
    read_params();
    if (!contract_atoms(r, atoms, params)) {
      write_params();
      return false;
    }
  }
  return !params.is_empty() || nb_params_ == 0;
}

}  // namespace sillage
