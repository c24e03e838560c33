// TubeContractor: a contractor written on its own argument types enters a
// network with nothing else written: arguments checked, vector form,
// constants and boxes written back, what shrank reported, emptiness located,
// the network's cancel token passed on.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "sillage/budget.h"
#include "sillage/cn/contractor_network.h"
#include "sillage/cn/tube_contractor.h"
#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/tube/tube_vector.h"

using namespace sillage;

namespace {

// x(t) = y(t) + b for a constant b: x ∩= y + b, b ∩= x - y at every slice and gate.
class CtcOffset : public TubeContractor<CtcOffset, bool(Tube&, const Tube&, Interval&)> {
 public:
  std::string name() const override { return "CtcOffset"; }
  bool contract(Tube& x, const Tube& y, Interval& b) const {
    for (std::size_t k = 0; k <= x.nb_slices(); ++k) b &= x.gate(k) - y.gate(k);
    for (std::size_t k = 0; k < x.nb_slices(); ++k) b &= x.slice(k) - y.slice(k);
    if (b.is_empty()) return false;
    for (std::size_t k = 0; k <= x.nb_slices(); ++k) x.set_gate(k, x.gate(k) & (y.gate(k) + b));
    for (std::size_t k = 0; k < x.nb_slices(); ++k) x.set(x.slice(k) & (y.slice(k) + b), k);
    return !x.is_empty();
  }
};

// Every component of p inside the box c: p[i] ∩= c[i]; and c ∩= the hull of p.
class CtcInBox : public TubeContractor<CtcInBox, void(TubeVector&, IntervalVector&)> {
 public:
  std::string name() const override { return "CtcInBox"; }
  void contract(TubeVector& p, IntervalVector& c) const {
    for (std::size_t i = 0; i < p.size(); ++i) {
      p[i] &= Tube(p.tdomain(), c[i]);
      c[i] &= p[i].codomain();
    }
  }
};

// lo <= x(t_k) <= hi on every gate, with or without lo: two forms.
class CtcBelow
    : public TubeContractor<CtcBelow, bool(Tube&, const Interval&), bool(Tube&, const Interval&, const Interval&)> {
 public:
  std::string name() const override { return "CtcBelow"; }
  bool contract(Tube& x, const Interval& hi) const { return contract(x, Interval(), hi); }
  bool contract(Tube& x, const Interval& lo, const Interval& hi) const {
    for (std::size_t k = 0; k <= x.nb_slices(); ++k) x.set_gate(k, x.gate(k) & Interval(lo.lb(), hi.ub()));
    return !x.is_empty();
  }
};

// Cancels the token it is given: only the network's own stops the network.
class CtcCancelling : public TubeContractor<CtcCancelling, bool(Tube&)> {
 public:
  std::string name() const override { return "CtcCancelling"; }
  bool contract(Tube&, const CancelToken& cancel) const {
    cancel.cancel();
    return true;
  }
};

std::shared_ptr<TDomain> ten_slices() { return TDomain::create(0.0, 1.0, 0.1); }

}  // namespace

TEST(TubeContractor, ContractsTubesAndConstantsAndKeepsTheTruth) {
  auto td = ten_slices();
  auto y = std::make_shared<Tube>(td, "sin(t)");
  auto x = std::make_shared<Tube>(td, Interval(-10, 10));
  x->set_gate(0, Interval(1.9, 2.1));  // x = sin(t) + 2
  auto b = std::make_shared<Interval>(1.0, 5.0);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcOffset>(), {x, y, b});
  const ContractStats s = cn.contract();
  EXPECT_FALSE(s.empty);
  EXPECT_TRUE(b->is_subset(Interval(1.9, 2.1)));  // learnt from gate 0
  EXPECT_TRUE(b->contains(2.0));
  for (int i = 0; i <= 100; ++i) {
    const double t = i / 100.0;
    EXPECT_TRUE((*x)(t).contains(std::sin(t) + 2.0)) << t;  // the truth stays inside
  }
  EXPECT_LT(x->max_thickness(), 0.3);
}

TEST(TubeContractor, AppliesAScalarSignatureComponentByComponent) {
  auto td = ten_slices();
  auto y = std::make_shared<TubeVector>(td, "(sin(t), cos(t))");
  auto x = std::make_shared<TubeVector>(td, 2, Interval(-10, 10));
  x->set_gate(0, IntervalVector{Interval(0.9, 1.1), Interval(1.9, 2.1)});  // x[i] = y[i] + 1, b shared
  auto b = std::make_shared<Interval>(0.0, 5.0);
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcOffset>(), {x, y, b});
  EXPECT_FALSE(cn.contract().empty);
  EXPECT_TRUE(b->is_subset(Interval(0.9, 1.1)));  // both components share it: [0.9, 1.1] ∩ [0.9, 1.1]
  EXPECT_TRUE((*x)[1](0.5).contains(std::cos(0.5) + 1.0));
  EXPECT_TRUE((*x)[1].codomain().is_subset(Interval(0.4, 2.2)));
}

TEST(TubeContractor, TubeVectorsAndBoxesAreWrittenBackIntersected) {
  auto td = ten_slices();
  auto p = std::make_shared<TubeVector>(td, "(t, 2*t)");
  (*p)[0].set(Interval(-3, 3));
  auto c = std::make_shared<IntervalVector>(IntervalVector{Interval(-1, 1.5), Interval(-5, 5)});
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcInBox>(), {p, c});
  EXPECT_FALSE(cn.contract().empty);
  EXPECT_EQ((*p)[0].codomain(), Interval(-1, 1.5));
  EXPECT_EQ((*c)[0], Interval(-1, 1.5));
  EXPECT_EQ((*c)[1], Interval(0, 2));
}

TEST(TubeContractor, TheFirstSignatureThatFitsIsUsed) {
  auto td = ten_slices();
  auto x = std::make_shared<Tube>(td, Interval(-10, 10));
  ContractorNetwork cn;
  cn.add(std::make_shared<CtcBelow>(), {x, std::make_shared<Interval>(3.0)});
  cn.add(std::make_shared<CtcBelow>(), {x, std::make_shared<Interval>(-2.0), std::make_shared<Interval>(8.0)});
  cn.contract();
  EXPECT_EQ(x->gate(4), Interval(-2, 3));
}

TEST(TubeContractor, ArgumentsThatFitNoSignatureAreRefusedNamingTheForms) {
  auto td = ten_slices();
  ContractorNetwork cn;
  try {
    cn.add(std::make_shared<CtcOffset>(), {std::make_shared<Tube>(td), std::make_shared<Interval>(),
                                            std::make_shared<Interval>()});
    FAIL();
  } catch (const DimensionError& e) {
    EXPECT_EQ(std::string(e.what()),
              "ContractorNetwork::add(CtcOffset): expects (tube, const tube, interval) (argument 2 must be a tube, got "
              "an interval); a tube argument takes a tube or a tube vector, the tubes with as many components; got "
              "(tube, interval, interval)");
  }
  // Vector form: the tubes with as many components.
  EXPECT_THROW(cn.add(std::make_shared<CtcOffset>(), {std::make_shared<TubeVector>(td, 2),
                                                      std::make_shared<TubeVector>(td, 3), std::make_shared<Interval>()}),
               DimensionError);
  // Tubes on one TDomain.
  EXPECT_THROW(cn.add(std::make_shared<CtcOffset>(),
                      {std::make_shared<Tube>(td), std::make_shared<Tube>(TDomain::create(0.0, 1.0, 0.5)),
                       std::make_shared<Interval>()}),
               DimensionError);
  EXPECT_EQ(cn.nb_dom(), 0u);
  EXPECT_EQ(cn.nb_ctc(), 0u);
}

TEST(TubeContractor, AnEmptiedConstantIsNamed) {
  auto td = ten_slices();
  auto y = std::make_shared<Tube>(td, Interval(0));
  auto x = std::make_shared<Tube>(td, Interval(5));
  auto b = std::make_shared<Interval>(0.0, 1.0);  // but x - y = 5
  ContractorNetwork cn;
  cn.set_name(b, "b");
  cn.add(std::make_shared<CtcOffset>(), {x, y, b});
  const ContractStats s = cn.contract();
  EXPECT_TRUE(s.empty);
  EXPECT_EQ(s.emptiness, "CtcOffset emptied interval 'b'");
}

TEST(TubeContractor, AnEmptiedTubeIsLocatedAlongTime) {
  auto td = TDomain::create(0.0, 10.0, 1.0);
  auto x = std::make_shared<Tube>(td, Interval(-100, 100));
  auto v = std::make_shared<Tube>(td, Interval(1));
  x->set_gate(0, Interval(0));
  x->set_gate(7, Interval(0));  // but x(t) = t: x(7) = 7
  ContractorNetwork cn;
  cn.set_name(x, "x");
  cn.add(std::make_shared<CtcDeriv>(), {x, v});
  const ContractStats s = cn.contract();
  EXPECT_TRUE(s.empty);
  EXPECT_EQ(s.emptiness, "CtcDeriv emptied tube 'x' at gate 7 (t = 7)");
}

TEST(TubeContractor, ALongContractionGetsTheNetworksCancelToken) {
  ContractorNetwork cn;
  const auto x = std::make_shared<Tube>(ten_slices());
  cn.add(std::make_shared<CtcCancelling>(), {x});
  cn.add(std::make_shared<CtcCancelling>(), {x});  // not run: the network stops before it
  EXPECT_THROW(cn.contract(), Cancelled);
}
