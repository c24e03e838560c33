// Budgets of the t-plane detections and proofs (budget.h).
#include <gtest/gtest.h>

#include <numbers>

#include "sillage/budget.h"
#include "sillage/loops/loop_function.h"
#include "sillage/loops/loop_sivia.h"
#include "sillage/loops/tplane.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {
namespace {

const char* kLimaconV = "(-sin(t) - 2*sin(2*t) + [-0.01,0.01], cos(t) + 2*cos(2*t) + [-0.01,0.01])";

TEST(LoopBudget, DetectionsStopAtTheBudget) {
  auto td = TDomain::create(0.3, 2 * std::numbers::pi - 0.3, 0.001);
  const TubeVector v(td, kLimaconV);
  TPlane tp(td);
  Budget b;
  b.max_boxes = 500;
  try {
    tp.compute_detections(1e-9, v, b);
    FAIL();
  } catch (const BudgetExceeded& e) {
    EXPECT_STREQ(e.what(),
                 "TPlane::compute_detections: budget exceeded: 501 boxes > max_boxes = 500; raise budget.max_boxes "
                 "(0: no limit) or use a larger eps");
  }
  EXPECT_EQ(tp.nb_detections(), 0u);  // nothing half-done
  tp.compute_detections(0.05, v, b = Budget{});
  EXPECT_EQ(tp.nb_detections(), 1u);
  // loop_sivia names its options.
  SiviaOptions o;
  o.budget.max_boxes = 10;
  try {
    loop_sivia(LoopFunction(v), tp.domain(), 1e-9, o);
    FAIL();
  } catch (const BudgetExceeded& e) {
    EXPECT_NE(std::string(e.what()).find("loop_sivia: budget exceeded: 11 boxes > max_boxes = 10; raise "
                                         "options.budget.max_boxes"),
              std::string::npos);
  }
  // Proofs: a cancelled token stops them.
  ProofOptions po;
  po.budget.cancel.cancel();
  EXPECT_THROW(tp.compute_proofs(v, po), Cancelled);
  po.budget = Budget{};
  po.budget.max_boxes = 3;
  try {
    tp.compute_proofs(v, po);
    FAIL();
  } catch (const BudgetExceeded& e) {
    EXPECT_STREQ(e.what(), "TPlane::compute_proofs: budget exceeded: 4 boxes > max_boxes = 3; raise "
                           "options.budget.max_boxes (0: no limit)");
  }
  EXPECT_NO_THROW(tp.compute_proofs(v));
  EXPECT_TRUE(tp.detections()[0].proven());
}

}  // namespace
}  // namespace sillage
