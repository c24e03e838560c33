// [[constraint]] kinds "deriv" (x' = v), "increment" (x(t_k+1) - x(t_k) in
// v(k)) and "second_deriv" (x'' in a): two tubes of one kind and dimension.
#include "sillage/problem/problem_loader.h"

namespace sillage::detail {

void ProblemLoader::read_deriv(const Fields& f, ConstraintSpec& c, const std::string& ks, const char* vkey) {
  c.kind = ks == "deriv" ? ConstraintKind::Deriv : ks == "increment" ? ConstraintKind::Increment : ConstraintKind::SecondDeriv;
  const VarSpec& x = tube_var(f, "x");
  const VarSpec& v = tube_var(f, vkey);
  if (x.dim != v.dim || x.kind != v.kind)
    throw ProblemError(doc_.pos(*f.find(vkey)),
                       "'" + v.name + "' (" + kind_name(v.kind) + ", dim " + std::to_string(v.dim) + ")",
                       "a variable of the kind and dimension of '" + x.name + "' (" + kind_name(x.kind) + ", dim " +
                           std::to_string(x.dim) + ")");
  c.x = x.name;
  c.v = v.name;
  c.label = f.where() + ": " + (ks == "deriv"          ? c.x + "' = " + c.v
                                : ks == "second_deriv" ? c.x + "'' in " + c.v
                                                       : c.x + "(t_k+1) - " + c.x + "(t_k) in " + c.v + "(k)");
}

}  // namespace sillage::detail
