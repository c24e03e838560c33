// Uses the core of an installed sillage (through sillage.h, or its own headers
// with SILLAGE_CONSUMER_CORE); exits 0 when the results are right.
#include <iostream>
#include <memory>

#ifdef SILLAGE_CONSUMER_CORE
#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/interval/elementary.h"
#include "sillage/paving/sivia_function.h"
#else
#include "sillage/sillage.h"
#endif

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
