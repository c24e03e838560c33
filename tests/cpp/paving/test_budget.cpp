// Budgets and cancellation of SIVIA (budget.h): a clear BudgetExceeded when
// the paving would grow past max_boxes or max_seconds, and Cancelled soon
// after another thread cancels the token, in parallel runs too.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "sillage/budget.h"
#include "sillage/paving/sivia_function.h"

using namespace sillage;

namespace {

// The unit sphere in dimension n: its boundary needs ~ (1/eps)^(n-1) boxes.
Paving sphere(std::size_t n, double eps, const SiviaOptions& o) {
  std::string text = "x0^2";
  std::vector<std::string> vars{"x0"};
  for (std::size_t i = 1; i < n; ++i) {
    vars.push_back(std::string(1, 'x').append(std::to_string(i)));
    text.append(" + ").append(vars.back()).append("^2");
  }
  return sivia(IntervalVector(n, Interval(-2, 2)), Function(vars, text), Interval(0, 1), eps, o);
}

std::string budget_error(std::size_t n, double eps, const SiviaOptions& o) {
  try {
    sphere(n, eps, o);
  } catch (const BudgetExceeded& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(Budget, MaxBoxesGivesAClearError) {
  SiviaOptions o;
  o.parallel = false;
  o.budget.max_boxes = 1000;
  EXPECT_EQ(budget_error(2, 1e-6, o),
            "sivia: budget exceeded: 1001 boxes > max_boxes = 1000; raise options.budget.max_boxes (0: no limit) "
            "or use a larger eps");
  // Within the budget: the same paving as without one.
  o.budget.max_boxes = 100000;
  SiviaOptions unlimited;
  unlimited.budget.max_boxes = 0;
  EXPECT_EQ(sphere(2, 0.05, o), sphere(2, 0.05, unlimited));
  // In parallel, the tasks share the count.
  o.parallel = true;
  o.budget.max_boxes = 5000;
  EXPECT_NE(budget_error(2, 1e-6, o).find("budget exceeded"), std::string::npos);
}

TEST(Budget, DefaultBoundsTenDimensions) {
  // Without a budget, a 10-D sphere at 1e-3 would run for ever: the default
  // (10^7 boxes) stops it. A smaller one keeps the test short.
  EXPECT_EQ(Budget{}.max_boxes, 10'000'000u);
  SiviaOptions o;
  o.budget.max_boxes = 200000;
  EXPECT_NE(budget_error(10, 1e-3, o).find("200001 boxes > max_boxes = 200000"), std::string::npos);
}

TEST(Budget, MaxBytes) {
  // A node of a 10-D paving: 8 bytes and 10 intervals of 16 bytes.
  SiviaOptions o;
  o.budget.max_boxes = 0;
  o.budget.max_bytes = 168 * 1000 + 100;
  EXPECT_EQ(budget_error(10, 1e-3, o),
            "sivia: budget exceeded: 1001 boxes of 168 bytes > max_bytes = 168100; raise options.budget.max_bytes "
            "(0: no limit) or use a larger eps");
  // The default: 1 GiB, 6.4 million boxes in 10-D, more than 10^7 in 2-D.
  EXPECT_EQ(Budget{}.max_bytes, std::size_t{1} << 30);
  o.budget.max_bytes = 100;
  EXPECT_THROW(sphere(10, 0.1, o), Error);  // not even one box
}

TEST(Budget, MaxSeconds) {
  SiviaOptions o;
  o.budget.max_boxes = o.budget.max_bytes = 0;
  o.budget.max_seconds = 0.2;
  const auto start = std::chrono::steady_clock::now();
  const std::string m = budget_error(10, 1e-3, o);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(m.rfind("sivia: budget exceeded: 0.", 0), 0u) << m;
  EXPECT_NE(m.find(" s > max_seconds = 0.20000000000000001 (after "), std::string::npos) << m;
  EXPECT_NE(m.find("raise options.budget.max_seconds (0: no limit)"), std::string::npos) << m;
  EXPECT_LT(s, 5.0);
  o.budget.max_seconds = -1;
  EXPECT_THROW(sphere(2, 0.1, o), Error);
}

TEST(Budget, CancelledFromAnotherThread) {
  for (bool parallel : {false, true}) {
    SiviaOptions o;
    o.parallel = parallel;
    o.budget.max_boxes = o.budget.max_bytes = 0;
    const CancelToken token = o.budget.cancel;
    std::thread canceller([token] {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      token.cancel();
    });
    const auto start = std::chrono::steady_clock::now();
    try {
      sphere(10, 1e-3, o);
      ADD_FAILURE() << "not cancelled";
    } catch (const Cancelled& e) {
      EXPECT_STREQ(e.what(), "sivia: cancelled");
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    canceller.join();
    EXPECT_LT(s, 2.0) << parallel;
    // Copies share the flag; reset() makes the options usable again.
    EXPECT_TRUE(o.budget.cancel.cancelled());
    o.budget.cancel.reset();
    EXPECT_NO_THROW(sphere(2, 0.1, o));
  }
}
