#pragma once
// TubeContractor: the one class a contractor on tubes derives from to enter a
// ContractorNetwork. Its author writes the contractor's own contract(...) on
// its argument types, and names that signature once, as a template argument:
//
//   class CtcIncrement : public TubeContractor<CtcIncrement, bool(Tube&, const Tube&)> {
//    public:
//     std::string name() const override { return "CtcIncrement"; }
//     bool contract(Tube& x, const Tube& i) const;  // false: x proven empty
//   };
//   cn.add(std::make_shared<CtcIncrement>(), {x, i});  // tubes, or tube vectors
//
// The base derives the rest: the network node, the arguments of add() checked
// and named in errors, the vector form (a signature on scalar tubes applies
// component by component to tube vectors of one size), the atoms of the
// tubes, what shrank reported to the network, and where an emptiness lies.
//
// Argument types, in any number and order:
//   Tube& / const Tube&                      a whole tube, contracted / read
//   TubeVector& / const TubeVector&          a tube vector (all its components)
//   Interval& / const Interval&              a constant over time: an Interval or a box component
//   IntervalVector& / const IntervalVector&  a box, or a part of one
// and, last, `const CancelToken&` for a contraction that runs long: it gets
// the network's token (the network's budget cancelled stops it within).
// The result is bool (false: no trajectory), void or anything else (not
// read); a contracted argument left empty is no trajectory either.
//
// Several signatures: the first that fits the arguments of add() is used
// (CtcBiasedIncrement: (x, b0, i) or (x, b0, i, j)). With one reference per
// argument, each reference is its argument; otherwise (components given one
// by one) the constants take one reference each and the tubes share the rest
// equally.
//
// What the node does per run: contract() on the whole arguments, the
// network's own tubes for Tube& (a snapshot before, to report what shrank),
// copies intersected back for the others. What woke the node is not passed,
// but a contractor on (Tube&, const Tube&) that also has
// `bool contract_local(Tube& x, const Tube& v, first, last, const TubeChanges&)`
// is called that way after its first run, with the slices that hold what
// woke it (CtcDeriv, CtcIncrement, CtcSecondDeriv). Another contractor that works only where its tubes
// changed (CtcEval around [t]) derives TubeNode (tube_node.h). A contractor whose
// `bool enforces_derivative() const` is true on a signature (Tube&, const
// Tube&, ...) tells the network that it enforces x' = v (CtcDeriv).
//
// A contractor that holds nothing per slice says so by `bool follows_appends()
// const` returning true: its node is then kept, grown, when its tubes gain
// slices at their end (TDomain::extend, online estimation) rather than built anew.
//
// contract() must be const and may only remove values that no trajectory
// takes; the node holds a copy of the contractor (make_node copies *this).
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "sillage/budget.h"
#include "sillage/cn/network_ctc.h"
#include "sillage/cn/tube_node.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

namespace detail {

// What an argument of contract() is.
enum class ArgKind { Tube, TubeVector, Interval, Box };
struct ArgSpec {
  ArgKind kind;
  bool contracted;  // a non-const reference
};

template <class A>
struct ArgOf;
template <>
struct ArgOf<Tube&> : std::integral_constant<ArgKind, ArgKind::Tube> {};
template <>
struct ArgOf<TubeVector&> : std::integral_constant<ArgKind, ArgKind::TubeVector> {};
template <>
struct ArgOf<Interval&> : std::integral_constant<ArgKind, ArgKind::Interval> {};
template <>
struct ArgOf<IntervalVector&> : std::integral_constant<ArgKind, ArgKind::Box> {};
template <class A>
struct ArgOf<const A&> : ArgOf<A&> {};

template <class A>
constexpr ArgSpec arg_spec() {
  static_assert(std::is_lvalue_reference_v<A>, "TubeContractor: arguments are references (Tube&, const Interval&, ...)");
  return {ArgOf<A>::value, !std::is_const_v<std::remove_reference_t<A>>};
}

// Which references of add() each argument of a signature takes.
struct ArgLayout {
  std::vector<std::size_t> first, count;  // per argument: its parts [first, first + count)
  std::size_t components = 1;             // each Tube argument has this many (vector form)
};

// The layout of `args` for `spec`: counts[k] parts for argument k when
// given, else one reference of `refs` (add()'s) per argument when they are
// as many, else the rule above; nullopt, with `why`, when they do not fit.
std::optional<ArgLayout> layout_arguments(const std::vector<ArgSpec>& spec, const std::vector<BoundDomain>& args,
                                          const std::vector<DomainRef>& refs, const std::vector<std::size_t>& counts,
                                          std::string& why);

// "(tube, interval, const tube)".
std::string signature_text(const std::vector<ArgSpec>& spec);

// The arguments of one call of contract(): the network's tubes (Tube&) or
// copies (the others), and what they were before, to report what shrank.
struct ArgValues {
  std::vector<Tube*> tube;                      // per argument, Tube: the network's tube
  std::vector<std::optional<TubeVector>> vector;  // per argument, TubeVector: a copy
  std::vector<Interval> scalar, scalar_before;  // per argument, Interval
  std::vector<IntervalVector> box, box_before;  // per argument, Box
  std::vector<TubeSnapshot> snapshot;           // per argument, contracted Tube
};

// The node's machinery that does not depend on the signature.
class TubeContractorNodeBase : public TubeNode {
 protected:
  TubeContractorNodeBase(std::string name, const std::vector<BoundDomain>& args, std::vector<ArgSpec> spec,
                         ArgLayout layout);
  std::size_t components() const { return layout_.components; }
  // Component c's arguments, read from the network.
  void load(const NodeRun& r, std::size_t c, ArgValues& v) const;
  // After the call (ok: its result): writes back, reports what shrank and,
  // on emptiness, where (call: contract() again on values like v).
  bool store(NodeRun& r, std::size_t c, ArgValues& v, bool ok,
             const std::function<bool(ArgValues&)>& call) const;
  // The pairs (x, v) of component c for derivative_pairs.
  void pair_of_first_two(std::vector<DerivativePair>& out) const;
  // A run that works where the first two tube arguments (x, v) changed: per
  // component c whose x or v has dirty atoms, local(x, v, first, last,
  // changes) with the slices first..last that hold them (a gate brings both
  // its slices). When local returns false, r.empty_at is where x's former
  // value stopped being consistent (found with `whole`, the contraction of
  // the whole tube; empty_prefix.h).
  using Local = std::function<bool(Tube&, const Tube&, std::size_t, std::size_t, const TubeChanges&)>;
  using Whole = std::function<bool(Tube&, const Tube&)>;
  bool run_local(NodeRun& r, const Local& local, const Whole& whole) const;

 private:
  // Sets r.empty_at: where along time the first contracted tube stopped being consistent.
  void locate_empty(NodeRun& r, std::size_t c, ArgValues& v, const std::function<bool(ArgValues&)>& call) const;
  std::vector<ArgSpec> spec_;
  ArgLayout layout_;
};

template <class R>
bool call_result(R&& r) {
  if constexpr (std::is_same_v<std::decay_t<R>, bool>) return r;
  return true;
}

template <class A>
decltype(auto) arg_value(ArgValues& v, std::size_t i) {
  constexpr ArgKind kind = ArgOf<A>::value;
  if constexpr (kind == ArgKind::Tube) return static_cast<A>(*v.tube[i]);
  else if constexpr (kind == ArgKind::TubeVector) return static_cast<A>(*v.vector[i]);
  else if constexpr (kind == ArgKind::Interval) return static_cast<A>(v.scalar[i]);
  else return static_cast<A>(v.box[i]);
}

template <class Derived, class Sig>
class TubeContractorNode;

template <class Derived, class R, class... A>
class TubeContractorNode<Derived, R(A...)> : public TubeContractorNodeBase {
 public:
  TubeContractorNode(const Derived& ctc, const std::vector<BoundDomain>& args, ArgLayout layout)
      : TubeContractorNodeBase(ctc.name(), args, {arg_spec<A>()...}, std::move(layout)), ctc_(ctc) {}
  std::string describe() const override { return ctc_.describe(); }

  bool run(NodeRun& r) const override {
    // A contractor that can start where its tubes changed (CtcDeriv::contract_local) does so
    // after its first run: the cost of a run is then the reach of the change, not the tube's.
    if constexpr (requires(const Derived& d, Tube& x, const Tube& w, const TubeChanges& ch) {
                    d.contract_local(x, w, std::size_t{0}, std::size_t{0}, ch);
                    d.contract(x, w);
                  }) {
      if (!r.all) {
        return run_local(
            r,
            [this](Tube& x, const Tube& w, std::size_t a, std::size_t b, const TubeChanges& ch) {
              return ctc_.contract_local(x, w, a, b, ch);
            },
            [this](Tube& x, const Tube& w) { return call_result(ctc_.contract(x, w)); });
      }
    }
    const CancelToken& cancel = r.cancel_token();
    const std::function<bool(ArgValues&)> call = [&](ArgValues& v) { return this->call(v, cancel); };
    thread_local ArgValues scratch;  // buffers reused; a nested run (a contractor running a network) gets its own
    thread_local bool busy = false;
    ArgValues local;
    ArgValues& v = busy ? local : scratch;
    const bool outer = !busy;
    busy = true;
    struct Release {
      bool outer;
      ~Release() {
        if (outer) busy = false;
      }
    } release{outer};
    for (std::size_t c = 0; c < components(); ++c) {
      load(r, c, v);
      if (!store(r, c, v, call(v), call)) return false;
    }
    return true;
  }

  // A contractor whose `bool follows_appends() const` is true keeps its node
  // when its tubes gain slices (CnNode::follows_appends).
  bool follows_appends() const override {
    if constexpr (requires(const Derived& d) { d.follows_appends(); }) return ctc_.follows_appends();
    return false;
  }

  void derivative_pairs(std::vector<DerivativePair>& out) const override {
    if constexpr (requires(const Derived& d) { d.enforces_derivative(); } && sizeof...(A) >= 2) {
      using Args = std::tuple<A...>;
      if constexpr (std::is_same_v<std::tuple_element_t<0, Args>, Tube&> &&
                    std::is_same_v<std::tuple_element_t<1, Args>, const Tube&>) {
        if (ctc_.enforces_derivative()) pair_of_first_two(out);
      }
    }
  }

 private:
  bool call(ArgValues& v, const CancelToken& cancel) const {
    return call_with(v, cancel, std::index_sequence_for<A...>{});
  }
  template <std::size_t... I>
  bool call_with(ArgValues& v, const CancelToken& cancel, std::index_sequence<I...>) const {
    if constexpr (requires { ctc_.contract(arg_value<A>(v, I)..., cancel); }) {
      if constexpr (std::is_void_v<decltype(ctc_.contract(arg_value<A>(v, I)..., cancel))>) {
        ctc_.contract(arg_value<A>(v, I)..., cancel);
        return true;
      } else {
        return call_result(ctc_.contract(arg_value<A>(v, I)..., cancel));
      }
    } else if constexpr (std::is_void_v<decltype(ctc_.contract(arg_value<A>(v, I)...))>) {
      ctc_.contract(arg_value<A>(v, I)...);
      return true;
    } else {
      return call_result(ctc_.contract(arg_value<A>(v, I)...));
    }
  }

  Derived ctc_;
};

// The node of the first signature that fits; DimensionError naming the
// contractor and the forms it takes otherwise.

template <class Sig>
struct SpecOf;
template <class R, class... A>
struct SpecOf<R(A...)> {
  static std::vector<ArgSpec> get() { return {arg_spec<A>()...}; }
};

// DimensionError: none of `forms` fits (their reasons in `why`).
[[noreturn]] void throw_no_form(const std::string& name, const std::vector<std::string>& forms,
                                const std::vector<std::string>& why, const std::vector<BoundDomain>& args);

// The node of the first signature that fits; DimensionError naming the
// contractor and the forms it takes otherwise.
template <class Derived, class... Sigs>
std::shared_ptr<const CnNode> make_tube_contractor_node(const Derived& ctc, const std::vector<DomainRef>& refs,
                                                        const std::vector<BoundDomain>& args,
                                                        const std::vector<std::size_t>& counts) {
  std::shared_ptr<const CnNode> node;
  std::vector<std::string> forms, why;
  const auto try_form = [&]<class Sig>(std::type_identity<Sig>) {
    if (node) return;
    const std::vector<ArgSpec> spec = SpecOf<Sig>::get();
    std::string reason;
    if (auto layout = layout_arguments(spec, args, refs, counts, reason)) {
      node = std::make_shared<TubeContractorNode<Derived, Sig>>(ctc, args, std::move(*layout));
    } else {
      forms.push_back(signature_text(spec));
      why.push_back(reason);
    }
  };
  (try_form(std::type_identity<Sigs>{}), ...);
  if (!node) throw_no_form(ctc.name(), forms, why, args);
  return node;
}

}  // namespace detail

template <class Derived, class... Sigs>
class TubeContractor : public NetworkCtc {
  static_assert(sizeof...(Sigs) > 0, "TubeContractor: name at least one signature of contract()");

 public:
  std::shared_ptr<const CnNode> make_node(const std::vector<BoundDomain>& args) const override {
    return detail::make_tube_contractor_node<Derived, Sigs...>(self(), {}, args, {});
  }
  std::shared_ptr<const CnNode> make_node_for(const std::vector<DomainRef>& refs,
                                              const std::vector<BoundDomain>& args) const override {
    return detail::make_tube_contractor_node<Derived, Sigs...>(self(), refs, args, {});
  }
  // For reports: the name by default.
  virtual std::string describe() const { return name(); }

 protected:
  // The node with counts[k] of the arguments of add() for argument k: for a
  // contractor whose components given one by one split by a rule of its own.
  std::shared_ptr<const CnNode> make_node_split(const std::vector<BoundDomain>& args,
                                                const std::vector<std::size_t>& counts) const {
    return detail::make_tube_contractor_node<Derived, Sigs...>(self(), {}, args, counts);
  }

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace sillage
