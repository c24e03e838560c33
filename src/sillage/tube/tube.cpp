#include "sillage/tube/tube.h"
#include "sillage/tube/chunks.h"
#include "sillage/tube/synthesis_tree.h"
#include "sillage/tube/tdomain_eval.h"
#include "sillage/tube/time_search.h"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>

#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/interval/rounding.h"
#include "sillage/tube/trajectory.h"

namespace sillage {

// Up to this many slices a linear scan beats building the synthesis tree.
constexpr std::size_t kScanLimit = 256;

namespace {

const std::shared_ptr<TDomain>& checked(const std::shared_ptr<TDomain>& td, const char* where) {
  if (!td) throw Error(std::string(where) + ": null TDomain");
  return td;
}

// The cached synthesis tree if it is current, else null (no build).
std::shared_ptr<const SynthesisTree> current_tree(TubeData& d) {
  std::lock_guard<std::mutex> lock(d.tree_cache.mutex);
  if (d.tree_cache.tree && d.tree_cache.version == d.version) return d.tree_cache.tree;
  return nullptr;
}

// n copies of x, or a copy of a: large arrays by chunks on several threads
// (tube/chunks.h), each thread faulting in its own pages.
TubeArray filled(std::size_t n, const Interval& x) {
  TubeArray v = detail::unwritten_array<Interval>(n);
  detail::for_chunks(
      n, [&](std::size_t b, std::size_t e) { std::fill(v.data() + b, v.data() + e, x); }, detail::kParallelCopyFrom);
  return v;
}

TubeArray copied(const TubeArray& a) {
  TubeArray v = detail::unwritten_array<Interval>(a.size());
  detail::for_chunks(
      a.size(), [&](std::size_t b, std::size_t e) { std::copy(a.data() + b, a.data() + e, v.data() + b); },
      detail::kParallelCopyFrom);
  return v;
}

std::shared_ptr<TubeData> make_data(std::size_t n, const Interval& x) {
  auto d = std::make_shared<TubeData>();
  d->slices = filled(n, x);
  d->gates = filled(n + 1, x);
  return d;
}

// A copy of x's values and version (not of its cached tree).
std::shared_ptr<TubeData> copy_data(const TubeData& x) {
  auto d = std::make_shared<TubeData>();
  d->slices = copied(x.slices);
  d->gates = copied(x.gates);
  d->version = x.version;
  d->angle = x.angle;
  return d;
}

}  // namespace

Tube::Tube(std::shared_ptr<TDomain> td, const Interval& x)
    : td_(std::move(td)), data_(make_data(checked(td_, "Tube(td, x)")->nb_slices(), x)) {
  td_->attach(data_);
}

Tube::Tube(std::shared_ptr<TDomain> td, const std::vector<Interval>& slices) : td_(std::move(td)) {
  const std::size_t n = checked(td_, "Tube(td, slices)")->nb_slices();
  if (slices.size() != n) {
    throw DimensionError("Tube(td, slices): " + std::to_string(slices.size()) + " slices given, the TDomain has " +
                         std::to_string(n));
  }
  data_ = std::make_shared<TubeData>();
  data_->slices.assign(slices.begin(), slices.end());
  data_->gates.resize(n + 1);
  data_->gates[0] = slices[0];
  data_->gates[n] = slices[n - 1];
  for (std::size_t k = 1; k < n; ++k) data_->gates[k] = slices[k - 1] & slices[k];
  td_->attach(data_);
}

Tube::Tube(std::shared_ptr<TDomain> td, const std::vector<Interval>& slices, const std::vector<Interval>& gates)
    : td_(std::move(td)) {
  const std::size_t n = checked(td_, "Tube(td, slices, gates)")->nb_slices();
  if (slices.size() != n || gates.size() != n + 1) {
    throw DimensionError("Tube(td, slices, gates): " + std::to_string(slices.size()) + " slices and " +
                         std::to_string(gates.size()) + " gates given, the TDomain needs " + std::to_string(n) +
                         " and " + std::to_string(n + 1));
  }
  data_ = std::make_shared<TubeData>();
  data_->slices.assign(slices.begin(), slices.end());
  data_->gates.assign(gates.begin(), gates.end());
  td_->attach(data_);
}

Tube::Tube(std::shared_ptr<TDomain> td, const std::string& expr_of_t)
    : Tube(std::move(td), Function({"t"}, expr_of_t)) {}

namespace detail {

std::vector<Tube> tubes_of_function(const std::shared_ptr<TDomain>& td, const Function& f) {
  const std::size_t m = f.image_dim();
  std::vector<std::shared_ptr<TubeData>> data(m);
  std::vector<TubeData*> out(m);
  for (std::size_t i = 0; i < m; ++i) out[i] = (data[i] = std::make_shared<TubeData>()).get();
  eval_into_tubes(*td, f, out);
  std::vector<Tube> r;
  r.reserve(m);
  for (std::size_t i = 0; i < m; ++i) r.push_back(Tube(td, std::move(data[i])));
  return r;
}

}  // namespace detail

Tube::Tube(std::shared_ptr<TDomain> td, std::shared_ptr<TubeData> data) : td_(std::move(td)), data_(std::move(data)) {
  td_->attach(data_);
}

namespace {

// f checked to be a scalar function of t.
const Function& scalar_of_t(const Function& f) {
  if (f.nb_vars() != 1 || f.image_dim() != 1) {
    throw DimensionError("Tube(td, f): f must be a scalar function of one variable t, got " +
                         std::to_string(f.nb_vars()) + " variable(s) and " + std::to_string(f.image_dim()) +
                         " output(s)");
  }
  return f;
}

}  // namespace

Tube::Tube(std::shared_ptr<TDomain> td, const Function& f)
    : Tube(std::move(detail::tubes_of_function(checked(td, "Tube(td, f)"), scalar_of_t(f)).front())) {}

Tube::Tube(const Tube& x) : td_(x.td_), data_(copy_data(*x.data_)) {
  td_->attach(data_);
}

Tube& Tube::operator=(const Tube& x) {
  if (this == &x) return *this;
  if (data_ && td_ == x.td_) {  // same domain: keep our (attached) storage
    data_->slices = x.data_->slices;
    data_->gates = x.data_->gates;
    data_->angle = x.data_->angle;
    data_->touch();
    return *this;
  }
  td_ = x.td_;
  data_ = copy_data(*x.data_);
  td_->attach(data_);
  return *this;
}

const Interval& Tube::slice(std::size_t k) const {
  if (k >= nb_slices()) {
    throw OutOfRangeError("Tube::slice(k): slice " + std::to_string(k) + " out of range [0, " + std::to_string(nb_slices()) +
                ")");
  }
  return data_->slices[k];
}

const Interval& Tube::gate(std::size_t k) const {
  if (k > nb_slices()) {
    throw OutOfRangeError("Tube::gate(k): gate " + std::to_string(k) + " out of range [0, " + std::to_string(nb_slices()) +
                "]");
  }
  return data_->gates[k];
}

Interval Tube::operator()(double t) const {
  if (!td_->t0_tf().contains(t)) {  // also rejects NaN
    std::ostringstream os;
    os.precision(17);
    os << "Tube::operator()(t): t = " << t << " is " << (std::isnan(t) ? "NaN" : "outside the domain ")
       << (std::isnan(t) ? "" : td_->t0_tf().str());
    throw Error(os.str());
  }
  const std::ptrdiff_t g = td_->time_index(t);
  if (g >= 0) return data_->gates[static_cast<std::size_t>(g)];
  return data_->slices[td_->slice_index(t)];  // throws when t is NaN or outside
}

Interval Tube::operator()(const Interval& t) const {
  if (t.is_empty()) return Interval::empty();
  if (!t.is_subset(td_->t0_tf())) {
    throw Error("Tube::operator()([t]): [t] = " + t.str() + " is not inside the domain " + td_->t0_tf().str());
  }
  if (t.is_degenerate()) return (*this)(t.lb());
  if (nb_slices() > kScanLimit) {  // a current tree answers any range at once
    if (const auto tree = current_tree(*data_)) return tree->eval(t);
  }
  const auto ts = td_->times();
  const double a = t.lb(), b = t.ub();
  // Slices k with t_k < b and t_{k+1} > a meet the interior (a, b).
  const std::size_t k_lo = detail::first_time_after(ts, a) - 1, k_end = detail::first_time_from(ts, b);
  // Building the tree costs about 20 ns per slice of the whole tube, a scan
  // about 1 ns per slice of the range: build only when the range is a large
  // share of the tube (later queries then reuse the tree).
  if (k_end - k_lo > std::max(kScanLimit, nb_slices() / 8)) return synthesis_tree()->eval(t);
  Interval r = Interval::empty();
  for (std::size_t k = k_lo; k < k_end; ++k) r |= data_->slices[k];
  // Gates with a <= t_k <= b.
  const std::size_t g_lo = detail::first_time_from(ts, a), g_end = detail::first_time_after(ts, b);
  for (std::size_t k = g_lo; k < g_end; ++k) r |= data_->gates[k];
  return r;
}

std::shared_ptr<const SynthesisTree> Tube::synthesis_tree() const {
  TreeCache& c = data_->tree_cache;
  std::lock_guard<std::mutex> lock(c.mutex);
  if (!c.tree || c.version != data_->version) {
    c.tree.reset();  // the old tree's memory goes before the new one is built
    c.tree = std::make_shared<const SynthesisTree>(td_, data_);
    c.version = data_->version;
  }
  return c.tree;
}

std::size_t Tube::memory_bytes() const {
  std::size_t bytes = sizeof(TubeData) + detail::large_array_footprint(data_->slices.capacity() * sizeof(Interval)) +
                      detail::large_array_footprint(data_->gates.capacity() * sizeof(Interval));
  TreeCache& c = data_->tree_cache;
  std::lock_guard<std::mutex> lock(c.mutex);
  if (c.tree) bytes += c.tree->memory_bytes();
  return bytes;
}

void Tube::set(const Interval& y, std::size_t k) {
  const std::size_t n = nb_slices();
  if (k >= n) {
    throw OutOfRangeError("Tube::set(y, k): slice " + std::to_string(k) + " out of range [0, " + std::to_string(n) + ")");
  }
  data_->slices[k] = y;
  data_->gates[k] = k > 0 ? y & data_->slices[k - 1] : y;
  data_->gates[k + 1] = k + 1 < n ? y & data_->slices[k + 1] : y;
  data_->touch();
}

void Tube::set_gate(std::size_t k, const Interval& y) {
  if (k > nb_slices()) {
    throw OutOfRangeError("Tube::set_gate(k, y): gate " + std::to_string(k) + " out of range [0, " +
                std::to_string(nb_slices()) + "]");
  }
  data_->gates[k] = y;
  data_->touch();
}

void Tube::set(const Interval& y) {
  std::fill(data_->slices.begin(), data_->slices.end(), y);
  std::fill(data_->gates.begin(), data_->gates.end(), y);
  data_->touch();
}

bool Tube::is_empty() const {
  auto empty = [](const Interval& y) { return y.is_empty(); };
  return std::any_of(data_->slices.begin(), data_->slices.end(), empty) ||
         std::any_of(data_->gates.begin(), data_->gates.end(), empty);
}

Interval Tube::codomain() const {
  if (is_empty()) return Interval::empty();
  Interval r = Interval::empty();
  for (const auto& y : data_->slices) r |= y;
  for (const auto& y : data_->gates) r |= y;
  return r;
}

double Tube::volume() const {
  double v = 0.0;
  for (std::size_t k = 0; k < nb_slices(); ++k) {
    const Interval& y = data_->slices[k];
    if (y.is_empty()) continue;
    const double w = td_->slice_width(k).ub();
    v = rounding::add_up(v, rounding::mul_up(w, y.diam()));
  }
  return v;
}

double Tube::thickness(std::size_t k) const { return slice(k).volume(); }

double Tube::max_thickness() const {
  double m = 0.0;
  for (const auto& y : data_->slices) m = std::max(m, y.volume());
  return m;
}

void Tube::check_same_tdomain(const Tube& y, const char* where) const {
  if (td_ != y.td_) throw DimensionError(std::string(where) + ": the two tubes are not on the same TDomain");
}

bool Tube::is_subset(const Tube& y) const {
  check_same_tdomain(y, "Tube::is_subset");
  for (std::size_t k = 0; k < nb_slices(); ++k) {
    if (!data_->slices[k].is_subset(y.data_->slices[k])) return false;
  }
  for (std::size_t k = 0; k <= nb_slices(); ++k) {
    if (!data_->gates[k].is_subset(y.data_->gates[k])) return false;
  }
  return true;
}

bool Tube::contains(const Trajectory& x) const {
  if (!td_->t0_tf().is_subset(x.domain())) {
    throw Error("Tube::contains(x): the trajectory's domain " + x.domain().str() +
                " does not cover the tube's domain " + td_->t0_tf().str());
  }
  for (std::size_t k = 0; k <= nb_slices(); ++k) {
    if (!x(td_->times()[k]).is_subset(data_->gates[k])) return false;
  }
  for (std::size_t k = 0; k < nb_slices(); ++k) {
    if (!x(td_->slice_domain(k)).is_subset(data_->slices[k])) return false;
  }
  return true;
}

bool Tube::operator==(const Tube& y) const {
  return td_ == y.td_ && data_->slices == y.data_->slices && data_->gates == y.data_->gates;
}

Tube& Tube::operator&=(const Tube& y) {
  check_same_tdomain(y, "Tube::operator&=");
  for (std::size_t k = 0; k < nb_slices(); ++k) data_->slices[k] &= y.data_->slices[k];
  for (std::size_t k = 0; k <= nb_slices(); ++k) data_->gates[k] &= y.data_->gates[k];
  data_->touch();
  return *this;
}

Tube& Tube::operator|=(const Tube& y) {
  check_same_tdomain(y, "Tube::operator|=");
  for (std::size_t k = 0; k < nb_slices(); ++k) data_->slices[k] |= y.data_->slices[k];
  for (std::size_t k = 0; k <= nb_slices(); ++k) data_->gates[k] |= y.data_->gates[k];
  data_->touch();
  return *this;
}

Interval Tube::inverse(const Interval& y) const {
  std::vector<Interval> unused;
  return inverse(y, unused);
}

Interval Tube::inverse(const Interval& y, std::vector<Interval>& components) const {
  components.clear();
  const auto ts = td_->times();
  const std::size_t n = nb_slices();
  // Walk gate 0, slice 0, gate 1, ..., gate N; a run of elements meeting y is
  // one connected subset of {t : [x](t) ∩ y ≠ ∅} (its closure).
  bool in_run = false;
  double run_lo = 0.0, run_hi = 0.0;
  auto meet = [&](double lo, double hi) {
    if (!in_run) run_lo = lo;
    run_hi = hi;
    in_run = true;
  };
  auto close = [&]() {
    if (in_run) components.emplace_back(run_lo, run_hi);
    in_run = false;
  };
  for (std::size_t k = 0; k <= n; ++k) {
    if (data_->gates[k].intersects(y)) meet(ts[k], ts[k]); else close();
    if (k < n) {
      if (data_->slices[k].intersects(y)) meet(ts[k], ts[k + 1]); else close();
    }
  }
  close();
  if (components.empty()) return Interval::empty();
  return {components.front().lb(), components.back().ub()};
}

std::ostream& operator<<(std::ostream& os, const Tube& x) {
  return os << "Tube " << x.tdomain()->t0_tf() << " -> " << x.codomain() << ", " << x.nb_slices() << " slices";
}

}  // namespace sillage
