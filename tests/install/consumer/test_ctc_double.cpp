// The contractor test kit, installed with sillage, on a contractor written
// outside it (ctc_double.h): the generic laws, and monotonicity.
#include <random>
#include <string>

#include "ctc_double.h"
#include "sillage/interval/elementary.h"
#include "sillage/testing/contractor_kit.h"

using namespace sillage;

namespace {

// x around a random trajectory f, y around 2 f: the truth is (f, 2 f).
kit::Case double_case(std::mt19937_64& rng) {
  const kit::SineSum f(rng);
  const auto td = kit::random_tdomain(rng, 20);
  const kit::Trajectory1 x = kit::position(f);
  const kit::Trajectory1 y = [f](const Interval& t) { return Interval(2.0) * f.x(t); };
  return {{kit::tube_around(td, x, rng, 0.3, 0.2), kit::tube_around(td, y, rng, 0.5, 0.2)}, {x, y}};
}

void contract(kit::Domains& d) { CtcDouble().contract(std::get<Tube>(d[0]), std::get<Tube>(d[1])); }

}  // namespace

TEST(CtcDouble, Laws) {
  kit::Options o;
  o.cases = 20;
  o.idempotence = kit::Idempotence::Exact;  // doubling and halving are exact
  EXPECT_TRUE(kit::check_laws(contract, double_case, o));
}

TEST(CtcDouble, Monotone) { EXPECT_TRUE(kit::check_monotone(contract, double_case)); }

// The kit catches a contractor that loses the truth.
TEST(CtcDouble, KitFindsAWrongContractor) {
  const kit::Contract wrong = [](kit::Domains& d) {
    contract(d);
    std::get<Tube>(d[1]).set(Interval(1e6, 1e7));
  };
  const testing::AssertionResult r = kit::check_laws(wrong, double_case);
  ASSERT_FALSE(r);
  EXPECT_NE(std::string(r.message()).find("case 0"), std::string::npos) << r.message();
}
