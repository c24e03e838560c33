#include "sillage/cn/tube_domain.h"

#include <algorithm>
#include <span>

#include "sillage/error.h"

namespace sillage {

TubeDomain::TubeDomain(std::shared_ptr<Tube> x) : x_(std::move(x)) {
  if (!x_) throw Error("ContractorNetwork: null Tube domain");
  nb_slices_ = x_->nb_slices();
  td_ = x_->tdomain();
  forgotten_ = td_->nb_forgotten();
  tf_ = td_->tf();
}

// Slices only appended: nothing forgotten, and the time point that ended the
// domain is still number N (a sample() before it would have moved it).
bool TubeDomain::appended_only() const {
  return same_tdomain() && td_->nb_forgotten() == forgotten_ && x_->nb_slices() > nb_slices_ &&
         td_->t(nb_slices_) == tf_;
}

// Slices forgotten at the start, appended at the end, none sampled among
// those kept: the time point that ended the domain is still there, as many
// places earlier as slices were forgotten.
std::optional<std::size_t> TubeDomain::dropped_atoms() const {
  if (!same_tdomain()) return std::nullopt;
  const std::size_t forgotten = td_->nb_forgotten() - forgotten_;
  if (forgotten > nb_slices_) return std::nullopt;
  const std::size_t end = nb_slices_ - forgotten;  // where the last time point is now
  if (end > x_->nb_slices() || td_->t(end) != tf_) return std::nullopt;
  return 2 * forgotten;
}

Interval TubeDomain::atom(std::size_t i) const {
  return time_atom(x_->data(), i);
}

void TubeDomain::set_atom(std::size_t i, const Interval& x) {
  x_->write().atom(i) = x;  // the writer ends with the statement: one version step
}

namespace {

using Span = std::span<const Interval>;

// Slices [b, e) and their gates surely hold a trajectory: each gate meets
// its slices (an empty one, [+inf, -inf], meets nothing). Max/min without
// branches, which the compiler vectorizes: as fast as Tube::is_empty. false
// may be a false alarm (an empty gate e is judged with slice e).
bool surely_consistent(Span s, Span g, std::size_t b, std::size_t e) {
  bool bad = false;
  for (std::size_t k = b; k < e; ++k) {
    const double sl = s[k].lb(), su = s[k].ub();
    bad |= !(std::max(g[k].lb(), sl) <= std::min(g[k].ub(), su));
    bad |= !(std::max(g[k + 1].lb(), sl) <= std::min(g[k + 1].ub(), su));
  }
  return !bad;
}

// The first flaw of slices [b, e) in time order; gate k + 1 is checked
// against slice k before its own emptiness.
EmptyOnInput first_flaw(Span s, Span g, std::size_t b, std::size_t e) {
  using A = TubeAtoms;
  for (std::size_t k = b; k < e; ++k) {
    if (g[k].is_empty()) return {true, A::gate_atom(k)};
    if (s[k].is_empty()) return {true, A::slice_atom(k)};
    if (!g[k].intersects(s[k])) return {true, A::gate_atom(k), A::slice_atom(k)};
    if (!g[k + 1].is_empty() && !g[k + 1].intersects(s[k])) return {true, A::gate_atom(k + 1), A::slice_atom(k)};
  }
  return {};
}

}  // namespace

EmptyOnInput TubeDomain::empty_on_input() const { return empty_on_input(0, 2 * x_->nb_slices() + 1); }

// By blocks: a fast pass over each, the exact one only where it alarms.
EmptyOnInput TubeDomain::empty_on_input(std::size_t first, std::size_t end) const {
  constexpr std::size_t kBlock = 1024;
  const Span s = x_->slices(), g = x_->gates();
  end = std::min(end, g.size() + s.size());
  if (first >= end) return {};
  // Slices k0..k1-1: atom 2k (gate k) is in slices k-1 and k, atom 2k+1 in slice k.
  const std::size_t k0 = first >= 2 ? (first - 1) / 2 : 0, k1 = std::min(s.size(), (end - 1) / 2 + 1);
  for (std::size_t b = k0; b < k1; b += kBlock) {
    const std::size_t e = std::min(b + kBlock, k1);
    if (surely_consistent(s, g, b, e)) continue;
    if (const EmptyOnInput f = first_flaw(s, g, b, e); f.empty) return f;
  }
  if (k1 == s.size() && g.back().is_empty()) return {true, gate_atom(s.size())};
  return {};
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
  if (td_->nb_forgotten() != forgotten_) {
    throw DimensionError("ContractorNetwork: " + label + " forgot " + std::to_string(td_->nb_forgotten() - forgotten_) +
                         " slices since it was registered (relayout() after TDomain::forget_before)");
  }
}

std::shared_ptr<Domain> TubeDomain::relaid() const {
  return same_tdomain() ? std::make_shared<TubeDomain>(x_) : nullptr;
}

}  // namespace sillage
