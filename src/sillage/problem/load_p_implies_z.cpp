// [[constraint]] kind = "p_implies_z": the temporal SLAM's inter-temporal
// implication (CtcPImpliesZ, thesis (7.9)): where the path p loops
// (p(t1) = p(t2), p' = w), the observations z agree (z(t1) = z(t2)).
#include "sillage/problem/problem_loader.h"

namespace sillage::detail {

void ProblemLoader::read_p_implies_z(const Fields& f, ConstraintSpec& c) {
  c.kind = ConstraintKind::PImpliesZ;
  const VarSpec& p = tube_var(f, "p");
  if (p.dim > 2)
    throw ProblemError(doc_.pos(*f.find("p")), "'" + p.name + "' (" + kind_name(p.kind) + ", dim " + std::to_string(p.dim) + ")",
                       "a position of dimension 1 or 2 (the t-plane is planar)");
  const VarSpec& w = tube_var(f, "w");
  if (w.dim != p.dim || w.kind != p.kind)
    throw ProblemError(doc_.pos(*f.find("w")), "'" + w.name + "' (" + kind_name(w.kind) + ", dim " + std::to_string(w.dim) + ")",
                       "the derivative of '" + p.name + "': a variable of its kind and dimension (" + kind_name(p.kind) +
                           ", dim " + std::to_string(p.dim) + ")");
  const VarSpec& z = tube_var(f, "z");
  const toml::node& en = f.require("eps", "the width of the t-boxes (time units, a number > 0)");
  c.eps = f.number(en, "the width of the t-boxes (time units, a number > 0)");
  if (!(c.eps > 0) || (p_.time.tf - p_.time.t0) / c.eps > 1e6)
    throw ProblemError(doc_.pos(en), "eps = " + doc_.raw(en), "a width of the t-boxes in (0, tf - t0], at least (tf - t0)/1e6");
  if (const toml::node* fn = f.find("fast")) {
    if (!fn->is_boolean()) throw ProblemError(doc_.pos(*fn), describe(*fn), "true (Alg. 14) or false (Alg. 13)");
    c.fast = fn->as_boolean()->get();
  }
  c.p = p.name;
  c.w = w.name;
  c.z = z.name;
  c.label = f.where() + ": " + c.p + "(t1) = " + c.p + "(t2) => " + c.z + "(t1) = " + c.z + "(t2), " + c.p + "' = " + c.w;
}

}  // namespace sillage::detail
