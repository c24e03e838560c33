#pragma once
// Tube: a sliced enclosure [x](.) of scalar trajectories x : [t_0, t_N] -> IR
// (thesis 3.2-3.3). Over a TDomain of N slices it stores N slice codomains
// [x](k) ⊇ x([t_k, t_{k+1}]) and N+1 gates [x](t_k) ∋ x(t_k), each array
// contiguous (32 bytes per slice). A trajectory x belongs to the tube when
// x(t) ∈ [x](k) for every t in slice k and x(t_k) ∈ [x](t_k) for every k.
//
// Value semantics: copying a tube copies its data and attaches the copy to
// the same TDomain. Every result is guaranteed (outward rounding included).
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "sillage/interval/interval.h"
#include "sillage/tube/tdomain.h"

namespace sillage {

class Function;
class SynthesisTree;
class Trajectory;
class Tube;

namespace detail {
// The tubes of the outputs of f (one variable t): slice k = f([t_k, t_k+1]),
// gate k = f(t_k), by one batch evaluation written once into their storage,
// with unknown_where_undefined applied (the constructors from a function).
std::vector<Tube> tubes_of_function(const std::shared_ptr<TDomain>& td, const Function& f);
}  // namespace detail

class Tube {
 public:
  // Every slice and gate = x (the whole line by default).
  explicit Tube(std::shared_ptr<TDomain> td, const Interval& x = Interval());
  // Slice codomains given (size N, DimensionError otherwise); gate k is the
  // intersection of the two slices around t_k, the end gates the end slices.
  Tube(std::shared_ptr<TDomain> td, const std::vector<Interval>& slices);
  // Slices (size N) and gates (size N+1) given, DimensionError otherwise. A
  // gate disjoint from a neighbouring slice is taken as given: such a tube
  // holds no continuous trajectory, which CtcDeriv and a ContractorNetwork
  // report as no solution (is_empty() looks at each slice and gate alone).
  Tube(std::shared_ptr<TDomain> td, const std::vector<Interval>& slices,
       const std::vector<Interval>& gates);
  // From an expression of the single variable t, e.g.
  // "-9/20*cos(t/5) + [-0.001,0.001]": slice k = [f]([t_k, t_{k+1}]),
  // gate k = [f]([t_k, t_k]); one batch evaluation (one DAG walk). The
  // natural form encloses f over the part of its argument where f is
  // defined; where f is defined nowhere (sin(t)/t, log(t), 1/t at t = 0, or
  // a whole slice outside f's domain) nothing is known: the whole line, so
  // such an expression never makes the tube empty (docs/tubes.md).
  Tube(std::shared_ptr<TDomain> td, const std::string& expr_of_t);
  // Same from a scalar Function of one variable (DimensionError otherwise).
  Tube(std::shared_ptr<TDomain> td, const Function& f);

  Tube(const Tube& x);
  Tube(Tube&& x) noexcept = default;  // x is left unusable (no data)
  Tube& operator=(const Tube& x);  // becomes a copy of x, attached to x's TDomain
  Tube& operator=(Tube&& x) noexcept = default;
  ~Tube() = default;

  // The TDomain (shared, not a copy).
  const std::shared_ptr<TDomain>& tdomain() const { return td_; }
  // N, the number of slices.
  std::size_t nb_slices() const { return data_->slices.size(); }
  const Interval& slice(std::size_t k) const;  // [x](k), OutOfRangeError if k >= N
  const Interval& gate(std::size_t k) const;   // [x](t_k), OutOfRangeError if k > N
  std::span<const Interval> slices() const { return data_->slices; }
  std::span<const Interval> gates() const { return data_->gates; }
  // An angle tube holds values known modulo 2π (interval/angle.h): its gates
  // are not intersected with its slices as real intervals (a pointwise
  // contractor in a network), and CtcDerivAngle, CtcEvalAngle contract it. A
  // copy keeps the mark.
  void set_angle(bool on) { data_->angle = on; }
  bool is_angle() const { return data_->angle; }  // whether it is an angle tube (set_angle)
  // Increases at every modification of this tube (including TDomain::sample).
  std::uint64_t version() const { return data_->version; }
  // The synthesis tree of the current slices and gates (thesis Fig. 3.9),
  // built on the first query after a modification and cached; thread-safe.
  std::shared_ptr<const SynthesisTree> synthesis_tree() const;
  // Bytes held: slices, gates and the cached synthesis tree if built (not the shared TDomain).
  std::size_t memory_bytes() const;

  // [x](t): the gate when t is a time point, else the slice codomain.
  // Error if t is NaN or outside [t_0, t_N].
  Interval operator()(double t) const;
  // [x]([t]) (3.3): hull of the slices meeting the interior of [t] and of the
  // gates inside [t]; a degenerate [t] gives operator()(t); an empty [t]
  // gives the empty set. Error if [t] is not inside [t_0, t_N]. Long
  // ranges are answered by the synthesis tree, O(log N).
  Interval operator()(const Interval& t) const;

  // Slice k := y and its two gates := y ∩ the neighbouring slice (an end
  // gate := y). OutOfRangeError if k >= N (set_gate: gate k := y, if k > N).
  void set(const Interval& y, std::size_t k);
  void set_gate(std::size_t k, const Interval& y);
  void set(const Interval& y);  // every slice and gate := y

  Interval codomain() const;  // hull of all slices and gates
  // Sum over slices of width(t slice) * width(codomain), rounded up:
  // a rigorous upper bound of the area. Infinite if a slice is unbounded.
  double volume() const;
  double thickness(std::size_t k) const;  // diameter of slice k (0 if empty)
  // The largest slice diameter.
  double max_thickness() const;

  // True if some slice or gate is empty (no trajectory belongs to the tube).
  bool is_empty() const;
  // Slice- and gate-wise inclusion; DimensionError if TDomains differ.
  bool is_subset(const Tube& y) const;
  // Rigorous: the trajectory's enclosure over each slice and at each gate
  // lies inside; Error if the trajectory's domain does not cover [t_0, t_N].
  bool contains(const Trajectory& x) const;
  bool operator==(const Tube& y) const;  // same TDomain, same slices and gates
  bool operator!=(const Tube& y) const { return !(*this == y); }

  // Slice- and gate-wise intersection / hull; DimensionError if TDomains differ.
  Tube& operator&=(const Tube& y);
  Tube& operator|=(const Tube& y);

  // In-place arithmetic, slice- and gate-wise, rigorous (3.5)-(3.6);
  // defined in tube_arithmetic.cpp. DimensionError if TDomains differ.
  Tube& operator+=(const Tube& y);
  Tube& operator-=(const Tube& y);
  Tube& operator*=(const Tube& y);
  Tube& operator/=(const Tube& y);
  Tube& operator+=(const Interval& y);
  Tube& operator-=(const Interval& y);
  Tube& operator*=(const Interval& y);
  Tube& operator/=(const Interval& y);

  // Inversion (3.4): hull of the times t where [x](t) meets y (slices
  // contribute their whole domain, gates their time point). Empty if none.
  Interval inverse(const Interval& y) const;
  // Same; `components` receives the connected subsets: the maximal runs of
  // consecutive slices/gates meeting y, in increasing time order.
  Interval inverse(const Interval& y, std::vector<Interval>& components) const;

  // With a derivative tube v (x' ∈ v; tube/tube_eval_deriv.cpp): inside
  // slice k, x(t) ∈ ([x](t_k) + (t-t_k)[v](k)) ∩ ([x](t_{k+1}) - (t_{k+1}-t)[v](k))
  // ∩ [x](k), a polygon tighter than the slice box. eval: the hull of it over
  // t ∈ [t] (Error if [t] is not inside the domain; empty -> empty).
  // inverse: hull of the times where the polygon meets y, a subset of
  // inverse(y). Rigorous; DimensionError if v is not on this TDomain.
  Interval eval(const Interval& t, const Tube& v) const;
  Interval inverse(const Interval& y, const Tube& v) const;
  // The same restricted to t ∈ [t] (the slices meeting [t]): ⊆ [t].
  Interval inverse(const Interval& y, const Tube& v, const Interval& t) const;

  // Writing the slices and gates in place (contractors, extensions): see
  // Tube::Writer below. The version increases once when the writer ends.
  class Writer;
  Writer write();
  // The storage, read only (algorithms of this layer).
  const TubeData& data() const { return *data_; }

 private:
  friend std::vector<Tube> detail::tubes_of_function(const std::shared_ptr<TDomain>& td, const Function& f);
  Tube(std::shared_ptr<TDomain> td, std::shared_ptr<TubeData> data);  // attaches data, of the right sizes

  void check_same_tdomain(const Tube& y, const char* where) const;

  std::shared_ptr<TDomain> td_;
  std::shared_ptr<TubeData> data_;
};

// Write access to a tube's slices and gates in place (Tube::write()). It
// holds the storage's invariant: the spans cannot change the number of
// slices or gates, and the tube's version increases once when the writer
// ends (its scope, or commit()), which tells the caches (synthesis tree) and
// the networks (TubeChanges) that the tube changed.
//
//   {
//     Tube::Writer w = x.write();
//     const auto s = w.slices();
//     for (std::size_t k = 0; k < s.size(); ++k) s[k] &= y.slice(k);
//   }  // x.version() increased once
//
// Until the writer ends, x's cached synthesis tree is the one of before: read
// what is being written through the spans.
class Tube::Writer {
 public:
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;
  Writer(Writer&& w) noexcept : d_(std::exchange(w.d_, nullptr)) {}
  Writer& operator=(Writer&& w) noexcept {
    if (this != &w) {
      commit();
      d_ = std::exchange(w.d_, nullptr);
    }
    return *this;
  }
  ~Writer() { commit(); }

  // The N slice codomains and the N+1 gates, in place.
  std::span<Interval> slices() const { return d_->slices; }
  std::span<Interval> gates() const { return d_->gates; }
  // Time element a (tube_atoms.h): gate a/2 if a is even, slice a/2 if odd.
  Interval& atom(std::size_t a) const { return (a & 1) != 0 ? d_->slices[a / 2] : d_->gates[a / 2]; }

  // Ends the write: the version increases once if `changed`; commit(false)
  // when the caller saw every value stay as it was (the caches stay valid).
  // The spans are not to be used after. The destructor calls commit().
  void commit(bool changed = true) {
    if (d_ && changed) d_->touch();
    d_ = nullptr;
  }

 private:
  friend class Tube;
  explicit Writer(TubeData& d) : d_(&d) {}
  TubeData* d_;
};

inline Tube::Writer Tube::write() { return Writer(*data_); }

std::ostream& operator<<(std::ostream& os, const Tube& x);

namespace detail {
// The enclosure of a function where it is defined nowhere: the whole line
// (nothing is known there), not the empty set.
inline Interval unknown_where_undefined(const Interval& y) { return y.is_empty() ? Interval() : y; }
}  // namespace detail

}  // namespace sillage
