// Uses every layer of an installed sillage; exits 0 when the results are right.
#include <iostream>
#include <memory>

#include "sillage/sillage.h"

using namespace sillage;

int main() {
  ContractorNetwork cn;
  auto x = cn.create_dom(IntervalVector(2));
  auto rho = cn.create_dom(Interval(3.63, 4.43));
  cn.add(std::make_shared<CtcFunction>(Function({"x1", "x2", "r"}, "sqrt((x1+0.5)^2 + (x2-4)^2) - r")), {x, rho});
  cn.contract();
  const Paving p = sivia(IntervalVector{{-5, 5}, {-5, 5}}, Function({"a", "b"}, "a^2 + b^2"), Interval(0, 4), 0.1);
  const bool ok = x->contains({0.0, 0.0}) && (*x)[0].ub() < 4 && p.count(PavingTag::Inner) > 0 &&
                  sin(Interval::pi()).contains(0.0);
  std::cout << *x << " " << p.nb_leaves() << " leaves: " << (ok ? "ok" : "WRONG") << std::endl;
  return ok ? 0 : 1;
}
