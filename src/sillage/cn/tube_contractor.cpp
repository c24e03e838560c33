#include "sillage/cn/tube_contractor.h"

#include "sillage/cn/empty_prefix.h"
#include "sillage/ctc/shrink.h"
#include "sillage/error.h"

namespace sillage::detail {

namespace {

bool is_tube_kind(ArgKind k) { return k == ArgKind::Tube || k == ArgKind::TubeVector; }

// "a tube", "an interval".
std::string with_article(const std::string& noun) {
  return (noun.find_first_of("aeiou") == 0 ? "an " : "a ") + noun;
}

bool is_tube(const BoundDomain& b) { return static_cast<bool>(std::dynamic_pointer_cast<TubeDomain>(b.domain)); }

const char* kind_word(ArgKind k) {
  switch (k) {
    case ArgKind::Tube: return "tube";
    case ArgKind::TubeVector: return "tube vector";
    case ArgKind::Interval: return "interval";
    case ArgKind::Box: return "box";
  }
  return "";
}

// Whether argument k (its parts [first, first + count) of args) has the kind
// the signature wants; why not otherwise.
bool fits(const ArgSpec& s, std::size_t k, std::size_t first, std::size_t count, const std::vector<BoundDomain>& args,
          std::string& why) {
  const std::string arg = "argument " + std::to_string(k + 1);
  if (count == 0) {
    why = arg + " is missing";
    return false;
  }
  for (std::size_t p = first; p < first + count; ++p) {
    if (is_tube_kind(s.kind) != is_tube(args[p])) {
      why = arg + " must be " + with_article(kind_word(s.kind)) + ", got " + with_article(args[p].domain->noun());
      return false;
    }
  }
  if (s.kind == ArgKind::Interval && (count != 1 || args[first].range.count != 1)) {
    why = arg + " must be one interval, got " + std::to_string(count == 1 ? args[first].range.count : count) +
          " components";
    return false;
  }
  return true;
}

}  // namespace

std::string signature_text(const std::vector<ArgSpec>& spec) {
  std::string s = "(";
  for (std::size_t k = 0; k < spec.size(); ++k) {
    if (k > 0) s += ", ";
    if (!spec[k].contracted) s += "const ";
    s += kind_word(spec[k].kind);
  }
  return s + ")";
}

std::optional<ArgLayout> layout_arguments(const std::vector<ArgSpec>& spec, const std::vector<BoundDomain>& args,
                                          const std::vector<DomainRef>& refs, const std::vector<std::size_t>& counts,
                                          std::string& why) {
  const std::size_t n = spec.size();
  ArgLayout l;
  l.first.resize(n);
  l.count.resize(n);
  if (counts.size() == n || refs.size() == n) {  // given, or one reference per argument
    std::size_t pos = 0;
    for (std::size_t k = 0; k < n; ++k) {
      l.first[k] = pos;
      l.count[k] = counts.size() == n ? counts[k] : refs[k].parts().size();
      pos += l.count[k];
    }
    if (pos != args.size()) {
      why = std::to_string(args.size()) + " arguments";
      return std::nullopt;
    }
  } else {  // components one by one: a constant takes one, the tubes share the rest
    std::size_t tubes = 0;
    for (const ArgSpec& s : spec) tubes += is_tube_kind(s.kind);
    const std::size_t constants = n - tubes;
    const std::size_t rest = args.size() >= constants ? args.size() - constants : 0;
    if (args.size() < constants || (tubes == 0 ? rest != 0 : rest == 0 || rest % tubes != 0)) {
      why = std::to_string(args.size()) + " arguments";
      return std::nullopt;
    }
    std::size_t pos = 0;
    for (std::size_t k = 0; k < n; ++k) {
      l.first[k] = pos;
      l.count[k] = is_tube_kind(spec[k].kind) ? rest / tubes : 1;
      pos += l.count[k];
    }
  }
  bool first_tube = true;
  for (std::size_t k = 0; k < n; ++k) {
    if (!fits(spec[k], k, l.first[k], l.count[k], args, why)) return std::nullopt;
    if (spec[k].kind != ArgKind::Tube) continue;
    if (first_tube) {
      l.components = l.count[k];
      first_tube = false;
    } else if (l.count[k] != l.components) {
      why = "argument " + std::to_string(k + 1) + " has " + std::to_string(l.count[k]) + " components, the first tube " +
            std::to_string(l.components);
      return std::nullopt;
    }
  }
  return l;
}

void throw_no_form(const std::string& name, const std::vector<std::string>& forms, const std::vector<std::string>& why,
                   const std::vector<BoundDomain>& args) {
  std::string got;
  for (const BoundDomain& b : args) got += (got.empty() ? "" : ", ") + b.domain->noun();
  std::string msg = "ContractorNetwork::add(" + name + "): expects ";
  for (std::size_t i = 0; i < forms.size(); ++i) {
    msg += (i == 0 ? "" : " or ") + forms[i] + " (" + why[i] + ")";
  }
  throw DimensionError(msg + "; a tube argument takes a tube or a tube vector, the tubes with as many components; got (" +
                       got + ")");
}

TubeContractorNodeBase::TubeContractorNodeBase(std::string name, const std::vector<BoundDomain>& args,
                                               std::vector<ArgSpec> spec, ArgLayout layout)
    : TubeNode(std::move(name), args), spec_(std::move(spec)), layout_(std::move(layout)) {
  for (std::size_t k = 0; k < spec_.size(); ++k) {
    if (is_tube_kind(spec_[k].kind)) whole_tubes(layout_.first[k], layout_.count[k], "the tube arguments");
  }
}

bool TubeContractorNodeBase::run_local(NodeRun& r, const Local& local, const Whole& whole) const {
  const std::size_t n = components(), x0 = layout_.first[0], v0 = layout_.first[1];
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  thread_local std::vector<std::size_t> lo, hi;
  lo.assign(n, kNone);
  hi.assign(n, 0);
  for (const std::size_t p : r.dirty) {
    const std::size_t g = range_of(p);
    const std::size_t c = g >= x0 && g < x0 + n ? g - x0 : g >= v0 && g < v0 + n ? g - v0 : kNone;
    if (c == kNone) continue;
    const std::size_t a = p - offset(g), slices = (ranges()[g].count - 1) / 2, k = time_index(a);
    const std::size_t from = is_slice(a) || k == 0 ? k : k - 1, to = is_slice(a) ? k : std::min(k, slices - 1);
    lo[c] = std::min(lo[c], from);
    hi[c] = std::max(hi[c], to);
  }
  for (std::size_t c = 0; c < n; ++c) {
    if (lo[c] == kNone) continue;
    Tube& x = tube(x0 + c)->tube();
    const Tube& v = tube(v0 + c)->tube();
    thread_local TubeSnapshot before;  // to tell where an emptiness lies (a copy: cheap beside the sweeps)
    before.take(x);
    if (!local(x, v, lo[c], hi[c], changes(r, x0 + c))) {
      const std::size_t a = first_empty_prefix(before.restore(x.tdomain()), [&](Tube& y) { return whole(y, v); });
      if (a < x.nb_slices() * 2 + 1) r.empty_at = offset(x0 + c) + a;
      return false;
    }
  }
  return true;
}

void TubeContractorNodeBase::load(const NodeRun& r, std::size_t c, ArgValues& v) const {
  const std::size_t n = spec_.size();
  v.tube.assign(n, nullptr);
  v.vector.resize(n);
  v.scalar.resize(n);
  v.scalar_before.resize(n);
  v.box.resize(n);
  v.box_before.resize(n);
  v.snapshot.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t first = layout_.first[k], count = layout_.count[k];
    switch (spec_[k].kind) {
      case ArgKind::Tube:
        v.tube[k] = &tube(first + c)->tube();
        if (spec_[k].contracted) v.snapshot[k].take(*v.tube[k]);
        break;
      case ArgKind::TubeVector: {
        std::vector<Tube> comps;
        comps.reserve(count);
        for (std::size_t i = 0; i < count; ++i) comps.push_back(tube(first + i)->tube());
        v.vector[k].emplace(std::move(comps));
        break;
      }
      case ArgKind::Interval: {
        const AtomRange& a = ranges()[first];
        v.scalar[k] = v.scalar_before[k] = r.domains[a.domain]->atom(a.first);
        break;
      }
      case ArgKind::Box: {
        std::size_t size = 0;
        for (std::size_t p = first; p < first + count; ++p) size += ranges()[p].count;
        IntervalVector& b = v.box[k];
        if (b.size() != size) b = IntervalVector(size);
        std::size_t j = 0;
        for (std::size_t p = first; p < first + count; ++p) {
          const AtomRange& a = ranges()[p];
          for (std::size_t i = 0; i < a.count; ++i) b[j++] = r.domains[a.domain]->atom(a.first + i);
        }
        v.box_before[k] = b;
        break;
      }
    }
  }
}

bool TubeContractorNodeBase::store(NodeRun& r, std::size_t c, ArgValues& v, bool ok,
                                   const std::function<bool(ArgValues&)>& call) const {
  std::size_t constant_empty = kNoAtom;  // the first constant atom left empty
  // Writes a constant atom back (intersected: a contractor cannot enlarge).
  const auto put = [&](std::size_t p, std::size_t i, const Interval& value) {
    const AtomRange& a = ranges()[p];
    Domain& d = *r.domains[a.domain];
    const Interval was = d.atom(a.first + i), now = was & value;
    if (now != was) d.set_atom(a.first + i, now);
    if (shrank(was, now, r.ratio)) r.changed.push_back(offset(p) + i);
    if (now.is_empty() && constant_empty == kNoAtom) constant_empty = offset(p) + i;
  };
  bool empty = !ok;
  for (std::size_t k = 0; k < spec_.size(); ++k) {
    if (!spec_[k].contracted) continue;
    const std::size_t first = layout_.first[k], count = layout_.count[k];
    switch (spec_[k].kind) {
      case ArgKind::Tube:
        changes(r, first + c).diff(v.snapshot[k], *v.tube[k]);
        empty = empty || v.tube[k]->is_empty();
        break;
      case ArgKind::TubeVector:
        for (std::size_t i = 0; i < count; ++i) {
          const Tube& now = (*v.vector[k])[i];
          if (!contract_tube(r, first + i, [&](Tube& x) {
                x &= now;
                return !x.is_empty();
              })) {
            return false;  // contract_tube located it
          }
        }
        break;
      case ArgKind::Interval:
        put(first, 0, v.scalar[k]);
        break;
      case ArgKind::Box: {
        std::size_t j = 0;
        for (std::size_t p = first; p < first + count; ++p) {
          for (std::size_t i = 0; i < ranges()[p].count; ++i) put(p, i, v.box[k][j++]);
        }
        break;
      }
    }
  }
  if (constant_empty != kNoAtom) {  // a constant with no value left says the most
    r.empty_at = constant_empty;
    return false;
  }
  if (!empty) return true;
  locate_empty(r, c, v, call);
  return false;
}

void TubeContractorNodeBase::locate_empty(NodeRun& r, std::size_t c, ArgValues& v,
                                          const std::function<bool(ArgValues&)>& call) const {
  std::size_t j = spec_.size();  // the first contracted tube: where along time it stopped being consistent
  for (std::size_t k = 0; k < spec_.size() && j == spec_.size(); ++k) {
    if (spec_[k].kind == ArgKind::Tube && spec_[k].contracted) j = k;
  }
  if (j == spec_.size()) return;  // the network names the first empty atom
  const std::shared_ptr<TDomain>& td = v.tube[j]->tdomain();
  const Tube before = v.snapshot[j].restore(td);
  const std::size_t a = first_empty_prefix(before, [&](Tube& y) {
    // The other arguments as they were before the call, fresh for each try.
    ArgValues w;
    load(r, c, w);
    std::vector<Tube> copies;
    copies.reserve(spec_.size());
    for (std::size_t k = 0; k < spec_.size(); ++k) {
      if (spec_[k].kind != ArgKind::Tube || !spec_[k].contracted) continue;
      if (k == j) {
        w.tube[k] = &y;
      } else {
        copies.push_back(v.snapshot[k].restore(td));
        w.tube[k] = &copies.back();
      }
    }
    w.scalar = v.scalar_before;
    w.box = v.box_before;
    if (!call(w)) return false;
    for (std::size_t k = 0; k < spec_.size(); ++k) {
      if (w.tube[k] && w.tube[k]->is_empty()) return false;
    }
    return true;
  });
  if (a < before.nb_slices() * 2 + 1) r.empty_at = offset(layout_.first[j] + c) + a;
}

void TubeContractorNodeBase::pair_of_first_two(std::vector<DerivativePair>& out) const {
  for (std::size_t c = 0; c < layout_.components; ++c) {
    out.push_back({ranges()[layout_.first[0] + c], ranges()[layout_.first[1] + c]});
  }
}

}  // namespace sillage::detail
