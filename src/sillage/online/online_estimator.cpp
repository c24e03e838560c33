#include "sillage/online/online_estimator.h"

#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/cn/domain.h"
#include "sillage/error.h"

namespace sillage {

namespace {

enum class Kind { State, Input, Bounded };

struct TubeDecl {
  std::string name;
  Kind kind;
  IntervalVector value;  // State: x0; Bounded: the bound (x0 with a bound of t); Input: the whole space
  std::optional<Function> bound;  // Bounded by a function of t
  std::shared_ptr<TubeVector> tube;
  std::string deriv;  // v, when x' = v was declared
  bool in_network = false;
};

// An observation's contractors: nodes [first, first + count) of the network.
struct Observation {
  Interval t;
  std::size_t first, count;
};

// An observation whose [t] reaches past now, held until time passes its end.
struct Pending {
  Interval t;
  std::vector<std::string> states;
  std::shared_ptr<const Ctc> ctc;
  std::vector<DomainRef> extras;
};

std::string quoted(const std::string& s) { return "'" + s + "'"; }

double clock_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

struct OnlineEstimator::Impl {
  std::vector<TubeDecl> tubes;
  std::vector<std::function<void()>> constraints;  // added to the network at the first advance()
  std::shared_ptr<TDomain> td;
  ContractorNetwork cn;
  std::vector<Observation> observations;
  std::vector<Pending> pending;  // in arrival order
  std::size_t nb_observed = 0;
  OnlineStats stats;
  ContractStats last;

  TubeDecl* find(const std::string& name) {
    for (auto& d : tubes) {
      if (d.name == name) return &d;
    }
    return nullptr;
  }
  TubeDecl& at(const std::string& name, const std::string& where) {
    if (TubeDecl* d = find(name)) return *d;
    std::string known;
    for (const auto& d : tubes) known += (known.empty() ? "" : ", ") + d.name;
    throw Error("OnlineEstimator::" + where + ": no tube " + quoted(name) + " (declared: " +
                (known.empty() ? "none" : known) + ")");
  }
  void declare(const std::string& name, Kind kind, const IntervalVector& value, const char* where) {
    if (td) throw Error(std::string("OnlineEstimator::") + where + ": the model is declared before the first advance()");
    if (name.empty()) throw Error(std::string("OnlineEstimator::") + where + ": empty name");
    if (find(name)) throw Error(std::string("OnlineEstimator::") + where + ": " + quoted(name) + " is already declared");
    if (value.size() == 0) throw Error(std::string("OnlineEstimator::") + where + ": " + quoted(name) + " has dimension 0");
    if (value.is_empty()) throw Error(std::string("OnlineEstimator::") + where + ": the value of " + quoted(name) + " is empty");
    tubes.push_back({name, kind, value, std::nullopt, nullptr, "", false});
  }
  // Slice k and its gates of a bounded tube within the bound.
  static void bound_slice(TubeDecl& d, const TDomain& td, std::size_t k) {
    IntervalVector slice = d.value, end = d.value, start = d.value;
    if (d.bound) {
      slice = d.bound->eval_vector(IntervalVector{td.slice_domain(k)});
      end = d.bound->eval_vector(IntervalVector{Interval(td.t(k + 1))});
      if (k == 0) start = d.bound->eval_vector(IntervalVector{Interval(td.t(0))}) & d.value;
    }
    for (std::size_t i = 0; i < d.value.size(); ++i) {
      Tube::Writer w = (*d.tube)[i].write();
      w.slices()[k] &= detail::unknown_where_undefined(slice[i]);
      w.gates()[k + 1] &= detail::unknown_where_undefined(end[i]);
      if (k == 0) w.gates()[0] &= start[i];
    }
  }
  // A tube, or "name[i]" its component i.
  std::pair<TubeDecl*, std::ptrdiff_t> named(const std::string& name, const char* where) {
    const std::size_t open = name.find('[');
    if (open == std::string::npos || name.back() != ']') return {&at(name, where), -1};
    TubeDecl& d = at(name.substr(0, open), where);
    const std::string index = name.substr(open + 1, name.size() - open - 2);
    std::size_t i = 0, used = 0;
    try {
      i = std::stoul(index, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != index.size() || index.empty() || i >= d.value.size()) {
      throw Error(std::string("OnlineEstimator::") + where + ": " + quoted(name) + " is not a component of " +
                  quoted(d.name) + " (dimension " + std::to_string(d.value.size()) + ")");
    }
    return {&d, static_cast<std::ptrdiff_t>(i)};
  }
  DomainRef ref(const std::string& name) {
    const auto [d, i] = named(name, "add");
    if (i < 0) return DomainRef(d->tube);
    return DomainRef::component(d->tube, static_cast<std::size_t>(i));
  }
  // The constraint, added to the network at the first advance(), on the named tubes.
  template <class C>
  void constrain(std::shared_ptr<const C> ctc, const std::vector<std::string>& names, const char* where) {
    if (td) throw Error(std::string("OnlineEstimator::") + where + ": the model is declared before the first advance()");
    if (!ctc) throw Error(std::string("OnlineEstimator::") + where + ": null contractor");
    for (const auto& n : names) named(n, where).first->in_network = true;
    constraints.push_back([this, ctc, names] {
      std::vector<DomainRef> refs;
      for (const auto& n : names) refs.push_back(ref(n));
      cn.add(ctc, refs);
    });
  }
  void start(double t0, double t1) {
    td = TDomain::create({t0, t1});
    for (auto& d : tubes) {
      d.tube = std::make_shared<TubeVector>(td, d.value.size());
      if (d.kind == Kind::Bounded) bound_slice(d, *td, 0);
      if (d.kind == Kind::State) d.tube->set_gate(0, d.value);
    }
    for (const auto& add : constraints) add();
  }
  // The slices before now - W dropped, with the observations they held.
  // True if it forgot (and so laid the network out anew).
  bool forget(double now, const OnlineOptions& o) {
    const double cut = now - o.window;
    if (!(cut - td->t0() >= o.forget_every)) return false;
    stats.forgotten += td->forget_before(cut);
    const double start = td->t0();
    std::vector<std::size_t> gone;
    std::vector<Observation> kept;
    for (const Observation& obs : observations) {
      if (obs.t.lb() < start) {
        for (std::size_t i = 0; i < obs.count; ++i) gone.push_back(obs.first + i);
      } else {
        kept.push_back({obs.t, obs.first - gone.size(), obs.count});
      }
    }
    stats.retired += observations.size() - kept.size();
    observations = std::move(kept);
    const std::size_t held = pending.size();  // held too long for a window this short: dropped
    std::erase_if(pending, [&](const Pending& p) { return p.t.lb() < start; });
    stats.retired += held - pending.size();
    cn.retire(gone);  // lays the network out anew as well
    return true;
  }
  // The observation's nodes: per state a CtcEval x(t) = q_j at the one t,
  // then ctc on (q_1, ..., extras).
  void apply(const Interval& t, const std::vector<std::string>& states, std::shared_ptr<const Ctc> ctc,
             const std::vector<DomainRef>& extras) {
    const auto tt = std::make_shared<Interval>(t);
    const std::size_t first = cn.nb_ctc();
    std::vector<DomainRef> args;
    std::vector<std::pair<TubeDecl*, std::shared_ptr<IntervalVector>>> evals;
    for (const std::string& state : states) {
      TubeDecl& x = at(state, "observe");
      evals.emplace_back(&x, std::make_shared<IntervalVector>(x.value.size()));
      args.push_back(evals.back().second);
    }
    args.insert(args.end(), extras.begin(), extras.end());
    cn.add(std::move(ctc), args);  // checks the sizes: nothing added on an error
    try {
      for (auto& [x, q] : evals) {
        cn.add(std::make_shared<CtcEval>(), {tt, q, x->tube, find(x->deriv)->tube});
        x->in_network = true;
      }
    } catch (...) {
      std::vector<std::size_t> added;
      for (std::size_t i = first; i < cn.nb_ctc(); ++i) added.push_back(i);
      cn.retire(added);
      throw;
    }
    observations.push_back({t, first, 1 + states.size()});
  }
  // The held observations whose time is now past, in arrival order.
  void apply_due(double now) {
    std::vector<Pending> still;
    for (Pending& p : pending) {
      if (p.t.ub() <= now) apply(p.t, p.states, std::move(p.ctc), p.extras);
      else still.push_back(std::move(p));
    }
    pending = std::move(still);
  }
  void contract(double started) {
    last = cn.update();
    stats.updates += 1;
    stats.contractor_runs += last.contractor_calls;
    stats.last_seconds = clock_seconds() - started;
    stats.total_seconds += stats.last_seconds;
  }
};

OnlineEstimator::OnlineEstimator(double t0, OnlineOptions options)
    : impl_(std::make_unique<Impl>()), options_(options), now_(t0) {
  if (!std::isfinite(t0)) throw Error("OnlineEstimator: t0 = " + number_text(t0) + " is not finite");
  if (!(options.window > 0)) {
    throw Error("OnlineEstimator: the window must be positive, got " + number_text(options.window));
  }
  if (!(options.forget_every >= 0) || std::isinf(options.forget_every)) {
    throw Error("OnlineEstimator: forget_every must be finite and >= 0, got " + number_text(options.forget_every));
  }
  if (options_.forget_every == 0 && std::isfinite(options_.window)) options_.forget_every = options_.window / 8;
  impl_->cn.set_ratio(options.ratio);
}

OnlineEstimator::~OnlineEstimator() = default;

void OnlineEstimator::add_state(const std::string& name, std::size_t dim, const IntervalVector& x0) {
  if (x0.size() != 0 && x0.size() != dim) {
    throw DimensionError("OnlineEstimator::add_state: x0 of " + quoted(name) + " has " + std::to_string(x0.size()) +
                         " components, not " + std::to_string(dim));
  }
  impl_->declare(name, Kind::State, x0.size() != 0 ? x0 : IntervalVector(dim), "add_state");
}

void OnlineEstimator::add_input(const std::string& name, std::size_t dim) {
  impl_->declare(name, Kind::Input, IntervalVector(dim), "add_input");
}

void OnlineEstimator::add_bounded(const std::string& name, const IntervalVector& value) {
  impl_->declare(name, Kind::Bounded, value, "add_bounded");
}

void OnlineEstimator::add_bounded(const std::string& name, const Function& bound, const IntervalVector& x0) {
  if (bound.nb_vars() != 1) {
    throw DimensionError("OnlineEstimator::add_bounded: the bound of " + quoted(name) +
                         " is a function of t alone, not of " + std::to_string(bound.nb_vars()) + " variables");
  }
  if (x0.size() != 0 && x0.size() != bound.image_dim()) {
    throw DimensionError("OnlineEstimator::add_bounded: x0 of " + quoted(name) + " has " + std::to_string(x0.size()) +
                         " components, the bound " + std::to_string(bound.image_dim()));
  }
  impl_->declare(name, Kind::Bounded, x0.size() != 0 ? x0 : IntervalVector(bound.image_dim()), "add_bounded");
  impl_->tubes.back().bound = bound;
}

void OnlineEstimator::add_deriv(const std::string& x, const std::string& v) {
  TubeDecl& dx = impl_->at(x, "add_deriv");
  const TubeDecl& dv = impl_->at(v, "add_deriv");
  if (dx.value.size() != dv.value.size()) {
    throw DimensionError("OnlineEstimator::add_deriv: " + quoted(x) + " has dimension " +
                         std::to_string(dx.value.size()) + " but " + quoted(v) + " " + std::to_string(dv.value.size()));
  }
  impl_->constrain<NetworkCtc>(std::make_shared<CtcDeriv>(), {x, v}, "add_deriv");
  dx.deriv = v;
}

void OnlineEstimator::add(std::shared_ptr<const Ctc> ctc, const std::vector<std::string>& tubes) {
  impl_->constrain(std::move(ctc), tubes, "add");
}

void OnlineEstimator::add(std::shared_ptr<const NetworkCtc> ctc, const std::vector<std::string>& tubes) {
  impl_->constrain(std::move(ctc), tubes, "add");
}

void OnlineEstimator::advance(double t, const std::vector<std::pair<std::string, IntervalVector>>& inputs) {
  const double started = clock_seconds();
  if (!std::isfinite(t)) throw Error("OnlineEstimator::advance: t = " + number_text(t) + " is not finite");
  if (!(t > now_)) {
    throw Error("OnlineEstimator::advance: t = " + number_text(t) + " is not after now = " + number_text(now_));
  }
  std::vector<std::pair<TubeDecl*, const IntervalVector*>> given;
  for (const auto& [name, value] : inputs) {
    TubeDecl& d = impl_->at(name, "advance");
    const std::string what = "OnlineEstimator::advance(t = " + number_text(t) + "): input " + quoted(name);
    if (d.kind != Kind::Input) throw Error(what + " was not declared by add_input");
    if (value.size() != d.value.size()) {
      throw DimensionError(what + " has " + std::to_string(value.size()) + " components, not " +
                           std::to_string(d.value.size()));
    }
    if (value.is_empty()) throw Error(what + " is empty: " + value.str());
    given.emplace_back(&d, &value);
  }
  Impl& m = *impl_;
  const double before = now_;
  if (!m.td) {
    m.start(now_, t);
  } else {
    m.td->extend(t);
    for (auto& d : m.tubes)
      if (d.kind == Kind::Bounded) Impl::bound_slice(d, *m.td, m.td->nb_slices() - 1);
    const double laying = clock_seconds();
    const bool forgot = std::isfinite(options_.window) && m.forget(t, options_);
    if (!forgot) m.cn.relayout();
    ++m.stats.relayouts;
    m.stats.layout_seconds += clock_seconds() - laying;
  }
  const std::size_t k = m.td->nb_slices() - 1;
  for (const auto& [d, value] : given) {
    for (std::size_t i = 0; i < value->size(); ++i) {
      Tube::Writer w = (*d->tube)[i].write();
      w.slices()[k] &= (*value)[i];
    }
  }
  now_ = t;
  for (const auto& d : m.tubes) {
    if (d.in_network) m.cn.touched(d.tube, Interval(before, t));
  }
  m.apply_due(now_);
  m.contract(started);
}

std::size_t OnlineEstimator::observe(const Interval& t, const std::string& state, std::shared_ptr<const Ctc> ctc,
                                     const std::vector<DomainRef>& extras) {
  return observe(t, std::vector<std::string>{state}, std::move(ctc), extras);
}

std::size_t OnlineEstimator::observe(const Interval& t, const std::vector<std::string>& states,
                                     std::shared_ptr<const Ctc> ctc, const std::vector<DomainRef>& extras) {
  const double started = clock_seconds();
  Impl& m = *impl_;
  const std::string what = "OnlineEstimator::observe([t] = " + t.str() + ")";
  if (!ctc) throw Error(what + ": null contractor");
  if (t.is_empty()) throw Error(what + ": the time interval is empty");
  if (!m.td) throw Error(what + ": no time yet (advance() first; now = " + number_text(now_) + ")");
  if (t.lb() > now_) {
    throw Error(what + ": begins in the future of now = " + number_text(now_) +
                " (advance to the time the measurement arrived first)");
  }
  if (t.lb() < m.td->t0()) {
    throw Error(what + ": begins before the window [" + number_text(m.td->t0()) + ", " + number_text(now_) +
                "] (older than the window: its past is forgotten)");
  }
  if (states.empty()) throw Error(what + ": no state named");
  std::size_t dims = 0;
  for (const std::string& state : states) {
    const TubeDecl& x = m.at(state, "observe");
    if (x.deriv.empty()) throw Error(what + ": the state " + quoted(state) + " has no derivative (add_deriv)");
    dims += x.value.size();
  }
  for (std::size_t i = 0; i < extras.size(); ++i) {
    for (const auto& part : extras[i].parts()) {
      if (!dynamic_cast<const IntervalDomain*>(part.domain.get()) && !dynamic_cast<const BoxDomain*>(part.domain.get()))
        throw Error(what + ": extra " + std::to_string(i) + " is a " + part.domain->kind() + ", not an interval or a box");
      dims += part.count;
    }
  }
  if (dims != ctc->nb_vars()) {
    throw DimensionError(what + ": " + ctc->describe() + " acts on " + std::to_string(ctc->nb_vars()) +
                         " components, the states and extras have " + std::to_string(dims));
  }
  if (t.ub() > now_) {  // held: its time may lie ahead of the last advance
    m.pending.push_back({t, states, std::move(ctc), extras});
    return m.nb_observed++;
  }
  m.apply(t, states, std::move(ctc), extras);
  m.contract(started);
  return m.nb_observed++;
}

std::size_t OnlineEstimator::pending() const { return impl_->pending.size(); }

double OnlineEstimator::window_start() const { return impl_->td ? impl_->td->t0() : now_; }

IntervalVector OnlineEstimator::now(const std::string& name) const {
  const TubeDecl& d = impl_->at(name, "now");
  if (!d.tube) return d.value;
  return d.tube->gate(d.tube->nb_slices());
}

std::shared_ptr<TubeVector> OnlineEstimator::tube(const std::string& name) const {
  const TubeDecl& d = impl_->at(name, "tube");
  if (!d.tube) throw Error("OnlineEstimator::tube: no time yet (advance() first; now = " + number_text(now_) + ")");
  return d.tube;
}

OnlineStats OnlineEstimator::stats() const {
  OnlineStats s = impl_->stats;
  s.slices = impl_->td ? impl_->td->nb_slices() : 0;
  s.observations = impl_->observations.size();
  s.pending = impl_->pending.size();
  s.contractors = impl_->cn.nb_ctc();
  return s;
}

const ContractStats& OnlineEstimator::last_update() const { return impl_->last; }

ContractorNetwork& OnlineEstimator::network() { return impl_->cn; }

}  // namespace sillage
