// A TubeVector bound into a ContractorNetwork (whole or by components) stays a
// live domain when the user assigns a new value to the vector: the network
// holds the components (heap objects), never the address of a slot of the
// vector's storage. Resizing the vector or moving it to another TDomain is
// reported at contract() (DimensionError), never a read of freed memory.
#include <gtest/gtest.h>

#include <memory>

#include "sillage/cn/contractor_network.h"
#include "sillage/ctc/ctc_function.h"

using namespace sillage;

namespace {

std::shared_ptr<CtcFunction> equal() { return std::make_shared<CtcFunction>(Function({"a", "b"}, "a - b")); }

// contract() throws DimensionError with exactly this message.
void expect_layout_error(ContractorNetwork& cn, const char* message) {
  try {
    cn.contract();
    ADD_FAILURE() << "no DimensionError";
  } catch (const DimensionError& e) {
    EXPECT_STREQ(e.what(), message);
  }
}

}  // namespace

TEST(ContractorNetworkTubeVector, AssignedVectorStaysLive) {
  auto td = TDomain::create(0.0, 1.0, 0.5);
  auto x = std::make_shared<TubeVector>(td, 2, Interval(-10, 10));
  ContractorNetwork cn;
  cn.add(equal(), {DomainRef::component(x, 0), DomainRef::component(x, 1)});
  // A move assignment: the vector's former storage is released.
  *x = TubeVector(td, IntervalVector{{0, 1}, {0.5, 2}});
  const ContractStats s = cn.contract();
  EXPECT_FALSE(s.empty);
  EXPECT_EQ((*x)[0].codomain(), Interval(0.5, 1));
  EXPECT_EQ((*x)[1].codomain(), Interval(0.5, 1));
}

TEST(ContractorNetworkTubeVector, WholeVectorAssignedThenContracted) {
  auto td = TDomain::create(0.0, 1.0, 0.5);
  auto x = std::make_shared<TubeVector>(td, 2, Interval(-10, 10));
  ContractorNetwork cn;
  cn.add(equal(), {x});
  const TubeVector y(td, IntervalVector{{0, 1}, {0.5, 2}});
  *x = y;  // a copy assignment
  EXPECT_FALSE(cn.contract().empty);
  EXPECT_EQ(x->codomain(), (IntervalVector{{0.5, 1}, {0.5, 1}}));
  EXPECT_EQ(y.codomain(), (IntervalVector{{0, 1}, {0.5, 2}}));  // the source is not shared
}

TEST(ContractorNetworkTubeVector, ComponentReferencesSurviveAssignment) {
  auto td = TDomain::create(0.0, 1.0, 0.5);
  TubeVector x(td, 2, Interval(-1, 1));
  const Tube* first = &x[0];
  const std::shared_ptr<Tube> second = x.shared_component(1);
  x = TubeVector(td, IntervalVector{{0, 1}, {2, 3}});
  EXPECT_EQ(first, &x[0]);
  EXPECT_EQ(second.get(), &x[1]);
  EXPECT_EQ(second->codomain(), Interval(2, 3));
  // Copies never share components.
  TubeVector c = x;
  c[0].set(Interval(5));
  EXPECT_EQ(x[0].codomain(), Interval(0, 1));
}

TEST(ContractorNetworkTubeVector, ResizedVectorIsAnError) {
  auto td = TDomain::create(0.0, 1.0, 0.5);
  auto x = std::make_shared<TubeVector>(td, 2, Interval(-10, 10));
  ContractorNetwork cn;
  cn.add(equal(), {DomainRef::component(x, 0), DomainRef::component(x, 1)});
  *x = TubeVector(td, 1);
  expect_layout_error(cn,
                      "ContractorNetwork: domain 0 (Tube(2 slices), component 0 of a TubeVector) was registered in a "
                      "TubeVector of 2 components, which now has 1");
}

TEST(ContractorNetworkTubeVector, VectorMovedToAnotherTDomainIsAnError) {
  auto td = TDomain::create(0.0, 1.0, 0.5);
  auto x = std::make_shared<TubeVector>(td, 2, Interval(-10, 10));
  ContractorNetwork cn;
  cn.add(equal(), {x});
  // Same number of slices, other times: the network's nodes were built for td.
  *x = TubeVector(TDomain::create(0.0, 2.0, 1.0), 2);
  expect_layout_error(cn,
                      "ContractorNetwork: domain 0 (Tube(2 slices), component 0 of a TubeVector) was registered on "
                      "another TDomain (assign tubes of the same TDomain)");
}

TEST(ContractorNetworkTubeVector, SwappedVectorIsAnError) {
  auto td = TDomain::create(0.0, 1.0, 0.5);
  auto x = std::make_shared<TubeVector>(td, 2, Interval(-10, 10));
  TubeVector y(td, 2, Interval(0, 1));
  ContractorNetwork cn;
  cn.add(equal(), {x});
  std::swap(*x, y);  // x now holds y's component objects
  EXPECT_EQ(x->codomain(), (IntervalVector{{0, 1}, {0, 1}}));
  expect_layout_error(cn,
                      "ContractorNetwork: domain 0 (Tube(2 slices), component 0 of a TubeVector) is no longer in its "
                      "TubeVector (the vector was swapped or moved from)");
}

TEST(ContractorNetworkTubeVector, ComponentAndSharedComponentAreOneDomain) {
  auto td = TDomain::create(0.0, 1.0, 0.5);
  auto x = std::make_shared<TubeVector>(td, 2, Interval(-10, 10));
  auto y = std::make_shared<Tube>(td, Interval(0, 1));
  ContractorNetwork cn;
  cn.add(equal(), {x});
  cn.add(equal(), {x->shared_component(0), y});
  EXPECT_EQ(cn.nb_dom(), 3u);
  EXPECT_FALSE(cn.contract().empty);
  EXPECT_EQ(x->codomain(), (IntervalVector{{0, 1}, {0, 1}}));  // y reached component 1 through component 0
}

namespace {

// A contractor that samples the TDomain of the tubes while the network runs.
class Sampler : public Ctc {
 public:
  explicit Sampler(std::shared_ptr<TDomain> td) : Ctc(1), td_(std::move(td)) {}
  void contract(IntervalVector&) const override {
    if (td_->nb_slices() == 2) td_->sample(0.25);
  }
  std::string name() const override { return "Sampler"; }

 private:
  std::shared_ptr<TDomain> td_;
};

}  // namespace

TEST(ContractorNetworkTubeVector, LayoutChangedDuringContractIsAnError) {
  auto td = TDomain::create(0.0, 1.0, 0.5);
  auto x = std::make_shared<TubeVector>(td, 2, Interval(-10, 10));
  ContractorNetwork cn;
  cn.add(equal(), {x});
  cn.add(std::make_shared<Sampler>(td), {cn.create_dom(Interval(0, 1))});
  expect_layout_error(cn,
                      "ContractorNetwork: domain 0 (Tube(2 slices), component 0 of a TubeVector), changed during "
                      "contract(), was registered with 2 slices but now has 3 (sample the TDomain before building "
                      "the network)");
}
