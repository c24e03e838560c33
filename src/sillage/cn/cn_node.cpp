#include "sillage/cn/cn_node.h"

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

#include "sillage/ctc/shrink.h"
#include "sillage/error.h"

namespace sillage {

CnNode::CnNode(std::vector<AtomRange> ranges) : ranges_(std::move(ranges)), watched_(ranges_) {
  offsets_.reserve(ranges_.size());
  for (const auto& r : ranges_) {
    offsets_.push_back(nb_atoms_);
    nb_atoms_ += r.count;
  }
}

namespace {
bool same(const AtomRange& a, const AtomRange& b) {
  return a.domain == b.domain && a.first == b.first && a.count == b.count;
}
}  // namespace

bool NodeRun::has_derivative(const AtomRange& x, const AtomRange& v) const {
  for (const DerivativePair& p : derivatives) {
    if (same(p.x, x) && same(p.v, v)) return true;
  }
  return false;
}

const CancelToken& NodeRun::cancel_token() const {
  static const CancelToken never;  // no one holds it to cancel it
  return cancel ? *cancel : never;
}

std::size_t CnNode::range_of(std::size_t pos) const {
  std::size_t g = ranges_.size() - 1;
  while (offsets_[g] > pos) --g;
  return g;
}

bool CnNode::follow_appends(const std::vector<std::size_t>& from,
                            const std::vector<std::shared_ptr<Domain>>& domains) {
  bool watched = false;
  for (std::size_t g = 0; g < ranges_.size(); ++g) {
    const std::size_t d = ranges_[g].domain;
    if (from[d] == kNoAtom || ranges_[g].first != 0 || ranges_[g].count != from[d]) continue;
    const std::size_t to = domains[d]->nb_atoms();
    ranges_[g].count = to;
    if (watched_[g].first == 0 && watched_[g].count == from[d]) watched_[g].count = to, watched = true;
  }
  count_atoms();
  return watched;
}

namespace {

// Range r of a domain that had `from` atoms, now `to` after dropping `dropped` at its start.
void shift(AtomRange& r, std::size_t from, std::size_t dropped, std::size_t to) {
  if (r.first == 0 && r.count == from) {
    r.count = to;
    return;
  }
  const std::size_t first = std::max(r.first, dropped) - dropped;
  const std::size_t end = std::max(r.first + r.count, dropped) - dropped;
  r.first = first, r.count = end - first;
}

}  // namespace

void CnNode::follow_shift(const std::vector<std::size_t>& from, const std::vector<std::size_t>& dropped,
                          const std::vector<std::shared_ptr<Domain>>& domains) {
  for (std::size_t g = 0; g < ranges_.size(); ++g) {
    const std::size_t d = ranges_[g].domain;
    if (from[d] == kNoAtom) continue;
    const std::size_t to = domains[d]->nb_atoms();
    shift(ranges_[g], from[d], dropped[d], to);
    shift(watched_[g], from[d], dropped[d], to);
  }
  count_atoms();
}

void CnNode::renumber_domains(const std::vector<std::size_t>& index) {
  for (auto& r : ranges_) r.domain = index[r.domain];
  for (auto& w : watched_) w.domain = index[w.domain];
}

void CnNode::count_atoms() {
  nb_atoms_ = 0;
  for (std::size_t g = 0; g < ranges_.size(); ++g) {
    offsets_[g] = nb_atoms_;
    nb_atoms_ += ranges_[g].count;
  }
}

void CnNode::watch_only(std::size_t r, std::size_t first, std::size_t count) {
  const AtomRange& a = ranges_.at(r);
  if (first < a.first || count > a.count || first - a.first > a.count - count) {
    throw DimensionError("CnNode::watch_only: atoms outside range " + std::to_string(r));
  }
  watched_[r] = {a.domain, first, count};
}

CtcNode::CtcNode(std::shared_ptr<const Ctc> ctc, std::vector<AtomRange> ranges)
    : CnNode(std::move(ranges)), ctc_(std::move(ctc)) {
  if (!ctc_) throw Error("ContractorNetwork::add: null contractor");
  if (ctc_->nb_vars() != nb_atoms()) {
    throw DimensionError("ContractorNetwork::add: " + ctc_->name() + " acts on " + std::to_string(ctc_->nb_vars()) +
                         " variables but the domains given add up to " + std::to_string(nb_atoms()));
  }
}

namespace {

// The boxes of CtcNode::run, reused on this thread (a network runs thousands
// of such nodes), one pair per nesting level: a contractor (a Python one may)
// can contract another network inside its contract().
struct BoxScratch {
  std::vector<std::unique_ptr<std::pair<IntervalVector, IntervalVector>>> levels;
  std::size_t depth = 0;
};
thread_local BoxScratch box_scratch;

// The pair of boxes of the current level, for as long as it lives.
class ScratchLevel {
 public:
  ScratchLevel() {
    if (box_scratch.levels.size() == box_scratch.depth) {
      box_scratch.levels.push_back(std::make_unique<std::pair<IntervalVector, IntervalVector>>(IntervalVector(1), IntervalVector(1)));
    }
    boxes_ = box_scratch.levels[box_scratch.depth++].get();
  }
  ~ScratchLevel() { --box_scratch.depth; }
  ScratchLevel(const ScratchLevel&) = delete;
  ScratchLevel& operator=(const ScratchLevel&) = delete;
  std::pair<IntervalVector, IntervalVector>& boxes() { return *boxes_; }

 private:
  std::pair<IntervalVector, IntervalVector>* boxes_;
};

}  // namespace

bool CtcNode::run(NodeRun& r) const {
  ScratchLevel level;
  IntervalVector& box = level.boxes().first;
  if (box.size() != nb_atoms()) box = IntervalVector(nb_atoms());
  std::size_t k = 0;
  for (const auto& g : ranges()) {
    for (std::size_t a = 0; a < g.count; ++a) box[k++] = r.domains[g.domain]->atom(g.first + a);
  }
  IntervalVector& before = level.boxes().second;
  before = box;
  ctc_->contract(box);
  if (box.size() != before.size()) {
    throw DimensionError("ContractorNetwork: " + ctc_->name() + " changed the size of its box");
  }
  k = 0;
  for (const auto& g : ranges()) {
    Domain& d = *r.domains[g.domain];
    for (std::size_t a = 0; a < g.count; ++a, ++k) {
      // Read again: the same atom may appear twice in one node.
      const Interval cur = d.atom(g.first + a);
      const Interval now = cur & box[k];
      if (now != cur) d.set_atom(g.first + a, now);
      if (now.is_empty()) {
        r.empty_at = k;
        return false;
      }
      if (shrank(before[k], now, r.ratio)) r.changed.push_back(k);
    }
  }
  return true;
}

}  // namespace sillage
