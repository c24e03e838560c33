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

// Boxes contracted together (one HC4 batch); their rows stay in cache.
constexpr std::size_t kChunk = 256;

}  // namespace

namespace {

std::string name_of(const std::shared_ptr<const Ctc>& ctc) {
  if (!ctc) throw Error("ContractorNetwork::add: null contractor");
  return ctc->name();
}

}  // namespace

TubeCtcNode::TubeCtcNode(std::shared_ptr<const Ctc> ctc, const std::vector<BoundDomain>& args)
    : TubeNode(name_of(ctc), args), ctc_(std::move(ctc)) {
  std::size_t nb_vars = 0;
  for (std::size_t g = 0; g < nb_args(); ++g) {
    tubes_.push_back(tube(g) ? whole_tubes(g, 1, "tube arguments").front() : nullptr);
    nb_vars += tube(g) ? 1 : ranges()[g].count;
    if (!tube(g)) nb_params_ += ranges()[g].count;
  }
  if (nb_vars != ctc_->nb_vars()) {
    throw DimensionError(where() + ": the contractor acts on " + std::to_string(ctc_->nb_vars()) +
                         " variables but the domains given make " + std::to_string(nb_vars) +
                         " (a tube counts as one variable)");
  }
  if (const auto* cf = dynamic_cast<const CtcFunction*>(ctc_.get())) {
    f_ = &cf->function();
    image_ = &cf->image();
  }
}

void TubeCtcNode::contract_boxes(std::vector<Interval>& box, std::size_t count) const {
  const std::size_t n = ctc_->nb_vars();
  if (f_) {
    std::vector<Interval*> cols(n);
    for (std::size_t v = 0; v < n; ++v) cols[v] = box.data() + v * count;
    f_->hc4_revise_batch(cols, count, *image_);
    return;
  }
  IntervalVector b(n);
  for (std::size_t j = 0; j < count; ++j) {
    for (std::size_t v = 0; v < n; ++v) b[v] = box[v * count + j];
    ctc_->contract(b);
    for (std::size_t v = 0; v < n; ++v) box[v * count + j] = b[v];
  }
}

bool TubeCtcNode::contract_atoms(NodeRun& r, const std::vector<std::size_t>& atoms, IntervalVector& params) const {
  const std::size_t n = ctc_->nb_vars();
  // With constants, a chunk is one box: each box sees them as narrowed by the previous ones.
  const std::size_t chunk = nb_params_ > 0 ? 1 : kChunk;
  std::vector<Interval> before(n * chunk), box;
  std::vector<std::size_t> ids;  // the time atoms of the chunk
  const std::size_t last = nb_time_atoms() - 1;
  std::vector<char> touched(tubes_.size(), 0);
  const auto touch = [&] {
    for (std::size_t g = 0; g < tubes_.size(); ++g)
      if (touched[g]) tubes_[g]->tube().touch();
  };
  // Slices first, then gates (which are intersected with their slices).
  for (const int parity : {1, 0}) {
    for (auto next = atoms.begin(); next != atoms.end();) {
      ids.clear();
      for (; next != atoms.end() && ids.size() < chunk; ++next)
        if (static_cast<int>(*next & 1) == parity) ids.push_back(*next);
      if (ids.empty()) break;
      const std::size_t c = ids.size();
      // Gather: box j in column layout, variable v at v * c + j.
      for (std::size_t j = 0; j < c; ++j) {
        const std::size_t i = ids[j];
        std::size_t v = 0, p = 0;
        for (std::size_t g = 0; g < tubes_.size(); ++g) {
          if (!tubes_[g]) {
            for (std::size_t k = 0; k < ranges()[g].count; ++k) before[v++ * c + j] = params[p++];
            continue;
          }
          TubeData& d = tubes_[g]->tube().data();
          Interval& x = time_atom(d, i);
          if (parity == 0) {  // x(t_k) lies in both neighbouring slices
            Interval h = x;
            if (i > 0) h &= d.slices[i / 2 - 1];
            if (i < last) h &= d.slices[i / 2];
            if (h != x) {
              changes(r, g).atom(i, x, h);
              x = h;
              touched[g] = 1;
            }
          }
          before[v++ * c + j] = x;
        }
      }
      box.assign(before.begin(), before.begin() + static_cast<std::ptrdiff_t>(n * c));
      contract_boxes(box, c);
      // Scatter, in order: a box proven empty stops the run there.
      for (std::size_t j = 0; j < c; ++j) {
        const std::size_t i = ids[j];
        bool ok = true;
        for (std::size_t v = 0; v < n; ++v) ok = ok && !box[v * c + j].is_empty();
        std::size_t v = 0, p = 0;
        for (std::size_t g = 0; g < tubes_.size(); ++g) {
          if (!tubes_[g]) {
            for (std::size_t k = 0; k < ranges()[g].count; ++k, ++v)
              params[p++] &= ok ? box[v * c + j] : Interval::empty();
            continue;
          }
          Interval& x = time_atom(tubes_[g]->tube().data(), i);
          const Interval now = ok ? (x & box[v * c + j]) : Interval::empty();
          if (now != x) {
            changes(r, g).atom(i, before[v * c + j], now);
            x = now;
            touched[g] = 1;
          }
          ++v;
        }
        if (!ok) {
          touch();
          for (std::size_t g = 0; g < tubes_.size() && r.empty_at == kNoAtom; ++g) {
            if (tubes_[g]) r.empty_at = offset(g) + i;
          }
          return false;
        }
      }
    }
  }
  touch();
  return true;
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
