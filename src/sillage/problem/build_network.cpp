#include "sillage/problem/build_network.h"

#include <cmath>

#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/expr/function.h"
#include "sillage/problem/var_refs.h"

namespace sillage {

using detail::RewrittenExpr;
using detail::VarRef;
using detail::rewrite_refs;

namespace {

Interval constant(const BoundSpec& b) {
  if (b.expr.empty()) return Interval();
  return Function({"t"}, b.expr).eval(IntervalVector{Interval(0)});
}

Interval constant_text(const std::string& text, const SourcePos& pos) {
  const Interval x = constant(BoundSpec{text, pos});
  if (x.is_empty() || x.lb() < 0) throw ProblemError(pos, "the error " + text, "an error >= 0");
  return x;
}

Tube tube_of(const std::shared_ptr<TDomain>& td, const BoundSpec& b) {
  if (b.expr.empty()) return Tube(td);
  return Tube(td, Function({"t"}, b.expr));
}

}  // namespace

DomainRef VarDomain::component(std::size_t i) const {
  if (tubes) return spec->kind == VarKind::Tube ? DomainRef(tubes->shared_component(0)) : DomainRef::component(tubes, i);
  if (interval) return DomainRef(interval);
  return DomainRef::component(box, i);
}

std::size_t VarDomain::memory_bytes() const {
  if (tubes) {
    std::size_t s = 0;
    for (std::size_t i = 0; i < tubes->size(); ++i) s += (*tubes)[i].memory_bytes();
    return s;
  }
  return sizeof(Interval) * (box ? box->size() : 1);
}

const VarDomain& BuiltProblem::var(const std::string& name) const {
  for (const VarDomain& v : vars)
    if (v.spec->name == name) return v;
  throw Error("no variable '" + name + "'");
}

std::size_t BuiltProblem::constraint_of_node(std::size_t n) const {
  std::size_t c = 0;
  while (c + 1 < first_node.size() && first_node[c + 1] <= n) ++c;
  return c;
}

std::size_t BuiltProblem::memory_bytes() const {
  std::size_t s = 0;
  for (const VarDomain& v : vars) s += v.memory_bytes();
  return s;
}

std::size_t nb_slices_for(const Problem& p, double delta) {
  return static_cast<std::size_t>(std::ceil((p.time.tf - p.time.t0) / delta));
}

BuiltProblem build_network(const Problem& p, double delta) {
  BuiltProblem b;
  b.td = TDomain::create(p.time.t0, p.time.tf, delta);
  for (const VarSpec& v : p.vars)
    for (const GateSpec& g : v.at)
      if (g.t > p.time.t0 && g.t < p.time.tf) b.td->sample(g.t);
  b.cn = std::make_unique<ContractorNetwork>();
  ContractorNetwork& cn = *b.cn;
  for (const VarSpec& v : p.vars) {
    VarDomain d;
    d.spec = std::make_shared<const VarSpec>(v);
    if (v.is_tube()) {
      std::vector<Tube> comps;
      for (const BoundSpec& bs : v.value) comps.push_back(tube_of(b.td, bs));
      d.tubes = std::make_shared<TubeVector>(std::move(comps));
      for (const GateSpec& g : v.at) {
        const std::size_t k = static_cast<std::size_t>(b.td->time_index(g.t));
        for (std::size_t i = 0; i < v.dim; ++i) {
          Tube& x = (*d.tubes)[i];
          x.set_gate(k, x.gate(k) & constant(g.value[i]));
        }
      }
    } else if (v.kind == VarKind::Interval) {
      d.interval = std::make_shared<Interval>(constant(v.value[0]));
    } else {
      IntervalVector x(v.dim);
      for (std::size_t i = 0; i < v.dim; ++i) x[i] = constant(v.value[i]);
      d.box = std::make_shared<IntervalVector>(x);
    }
    b.vars.push_back(std::move(d));
  }

  auto dims = [&](const std::string& n) -> std::optional<std::size_t> {
    const VarSpec* v = p.var(n);
    return v ? std::optional<std::size_t>(v->dim) : std::nullopt;
  };
  auto vec = [&](const std::string& n) {
    const VarSpec* v = p.var(n);
    return v && (v->kind == VarKind::TubeVector || v->kind == VarKind::Box);
  };
  for (const ConstraintSpec& c : p.constraints) {
    b.first_node.push_back(cn.nb_ctc());
    switch (c.kind) {
      case ConstraintKind::Expr: {
        const RewrittenExpr r = rewrite_refs(c.expr, c.expr_pos, dims, vec, "");
        std::vector<DomainRef> args;
        for (const VarRef& ref : r.refs) args.push_back(b.var(ref.var).component(ref.component));
        cn.add(std::make_shared<CtcFunction>(Function(r.ids(), r.text)), args);
        break;
      }
      case ConstraintKind::Deriv:
      case ConstraintKind::Increment: {
        const VarDomain &x = b.var(c.x), &v = b.var(c.v);
        std::shared_ptr<const NetworkCtc> ctc;
        if (c.kind == ConstraintKind::Deriv) ctc = std::make_shared<CtcDeriv>();
        else ctc = std::make_shared<CtcIncrement>();
        if (x.spec->kind == VarKind::Tube) cn.add(ctc, {x.tubes->shared_component(0), v.tubes->shared_component(0)});
        else cn.add(ctc, {x.tubes, v.tubes});
        break;
      }
      case ConstraintKind::Eval: {
        const DataSpec& data = *p.table(c.data);
        const VarDomain& y = b.var(c.x);
        const bool scalar = y.spec->kind == VarKind::Tube;
        auto dims_eval = [&](const std::string& n) -> std::optional<std::size_t> {
          if (n == c.x) return y.spec->dim;
          if (data.table.has_column(n)) return 1;
          return dims(n);
        };
        auto vec_eval = [&](const std::string& n) { return n == c.x ? !scalar : !data.table.has_column(n) && vec(n); };
        const RewrittenExpr r = rewrite_refs(c.expr, c.expr_pos, dims_eval, vec_eval, "");
        const Function f(r.ids(), r.text);
        const auto eval = std::make_shared<CtcEval>();
        const auto obs = std::make_shared<CtcFunction>(f);
        const Interval terr = constant_text(c.time_error, c.pos);
        std::map<std::string, Interval> errs;
        for (const auto& [col, text] : c.errors) errs[col] = constant_text(text, c.pos);
        const std::size_t tcol = data.table.column(c.time_column);
        for (std::size_t row = 0; row < data.table.nb_rows(); ++row) {
          const std::vector<double>& values = data.table.row(row);
          auto t = std::make_shared<Interval>((Interval(values[tcol]) + Interval(-1, 1) * terr) & b.td->t0_tf());
          if (t->is_empty()) continue;  // a measurement outside the time domain says nothing about it
          std::vector<DomainRef> args;
          std::shared_ptr<Interval> z1;
          std::shared_ptr<IntervalVector> zn;
          if (scalar) z1 = std::make_shared<Interval>();
          else zn = std::make_shared<IntervalVector>(y.spec->dim);
          DomainRef y_ref = scalar ? DomainRef(y.tubes->shared_component(0)) : DomainRef(y.tubes);
          std::vector<DomainRef> eval_args{t, scalar ? DomainRef(z1) : DomainRef(zn), y_ref};
          if (!c.v.empty()) {
            const VarDomain& w = b.var(c.v);
            eval_args.push_back(scalar ? DomainRef(w.tubes->shared_component(0)) : DomainRef(w.tubes));
          }
          cn.add(std::static_pointer_cast<const NetworkCtc>(eval), eval_args);
          b.extra_domains += 2;
          for (const VarRef& ref : r.refs) {
            if (ref.var == c.x) {
              args.push_back(scalar ? DomainRef(z1) : DomainRef::component(zn, ref.component));
            } else if (data.table.has_column(ref.var)) {
              const auto it = errs.find(ref.var);
              const Interval e = it == errs.end() ? Interval(0) : it->second;
              args.push_back(std::make_shared<Interval>(Interval(values[data.table.column(ref.var)]) + Interval(-1, 1) * e));
              ++b.extra_domains;
            } else {
              args.push_back(b.var(ref.var).component(ref.component));
            }
          }
          cn.add(std::static_pointer_cast<const Ctc>(obs), args);
        }
        break;
      }
    }
  }
  for (const VarDomain& v : b.vars) {
    if (v.tubes && v.spec->kind == VarKind::Tube) cn.set_name(v.tubes->shared_component(0), v.spec->name);
    else if (v.tubes) cn.set_name(v.tubes, v.spec->name);
    else if (v.interval) cn.set_name(v.interval, v.spec->name);
    else cn.set_name(v.box, v.spec->name);
  }
  return b;
}

}  // namespace sillage
