// Inclusion monotonicity (thesis 2.26): y ⊆ x implies f(y) ⊆ f(x), down to
// the last ulp (issue 12, item 7: atan2([1e20], [1.5]) ⊄ atan2([1e20], [0, 1.5])).
#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <string>
#include <vector>

#include "sillage/interval/elementary.h"

using namespace sillage;

namespace {

// Bounds near the special points of the elementary functions (0, ±1, ±pi/2,
// huge, tiny), where the exact special cases meet the widened libm values.
class Boxes {
 public:
  explicit Boxes(std::uint64_t seed) : rng_(seed) {}

  double value() {
    static const double special[] = {0.0, 1.0, -1.0, 1.5, 1e20, -1e20, 1e-20, 1e300, 1e-300, 0x1.921fb54442d18p+0,
                                     3.141592653589793, 710.0, 4.9e-324};
    switch (rng_() % 4) {
      case 0: return special[rng_() % std::size(special)];
      case 1: return std::nextafter(special[rng_() % std::size(special)], rng_() % 2 ? 1e308 : -1e308);
      case 2: return std::uniform_real_distribution<double>(-4, 4)(rng_);
      default: return std::ldexp(std::uniform_real_distribution<double>(-1, 1)(rng_), static_cast<int>(rng_() % 140) - 70);
    }
  }

  Interval box() {
    double a = value(), b = rng_() % 4 == 0 ? a : value();
    if (a > b) std::swap(a, b);
    return Interval(a, b);
  }

  // A sub-box of x: a degenerate end point, an end point kept, or random.
  Interval sub(const Interval& x) {
    auto inside = [&] {
      const double t = std::uniform_real_distribution<double>(0, 1)(rng_);
      return std::clamp(x.lb() + t * (x.ub() - x.lb()), x.lb(), x.ub());
    };
    switch (rng_() % 4) {
      case 0: return Interval(x.lb());
      case 1: return Interval(x.ub());
      case 2: return Interval(x.lb(), std::max(x.lb(), inside()));
      default: {
        double a = inside(), b = inside();
        if (a > b) std::swap(a, b);
        return Interval(a, std::min(b, x.ub()));
      }
    }
  }

 private:
  std::mt19937_64 rng_;
};

using Unary = std::function<Interval(const Interval&)>;
using Binary = std::function<Interval(const Interval&, const Interval&)>;

}  // namespace

TEST(Monotonicity, Atan2ListedCase) {
  EXPECT_TRUE(atan2(Interval(1e20), Interval(1.5)).is_subset(atan2(Interval(1e20), Interval(0, 1.5))));
  EXPECT_TRUE(atan2(Interval(-1e20), Interval(1.5)).is_subset(atan2(Interval(-1e20), Interval(0, 1.5))));
  EXPECT_TRUE(atan2(Interval(1e20), Interval(-1.5)).is_subset(atan2(Interval(1e20), Interval(-1.5, 0))));
  EXPECT_TRUE(atan2(Interval(1e-20), Interval(-1.5)).is_subset(atan2(Interval(0, 1e-20), Interval(-1.5))));
}

TEST(Monotonicity, UnaryFunctionsRandom) {
  const std::vector<std::pair<std::string, Unary>> fs = {
      {"exp", [](const Interval& x) { return exp(x); }},   {"log", [](const Interval& x) { return log(x); }},
      {"sqrt", [](const Interval& x) { return sqrt(x); }}, {"sin", [](const Interval& x) { return sin(x); }},
      {"cos", [](const Interval& x) { return cos(x); }},   {"tan", [](const Interval& x) { return tan(x); }},
      {"asin", [](const Interval& x) { return asin(x); }}, {"acos", [](const Interval& x) { return acos(x); }},
      {"atan", [](const Interval& x) { return atan(x); }}, {"sinh", [](const Interval& x) { return sinh(x); }},
      {"cosh", [](const Interval& x) { return cosh(x); }}, {"tanh", [](const Interval& x) { return tanh(x); }},
      {"sqr", [](const Interval& x) { return sqr(x); }},   {"abs", [](const Interval& x) { return abs(x); }},
      {"pow3", [](const Interval& x) { return pow(x, 3); }},
      {"pow-2", [](const Interval& x) { return pow(x, -2); }},
      {"root3", [](const Interval& x) { return root(x, 3); }},
      {"root4", [](const Interval& x) { return root(x, 4); }},
  };
  Boxes g(7);
  for (const auto& [name, f] : fs) {
    for (int k = 0; k < 20000; ++k) {
      const Interval x = g.box(), y = g.sub(x);
      if (f(y).is_subset(f(x))) continue;
      ADD_FAILURE() << name << " " << y << " in " << x << ": " << f(y) << " vs " << f(x);
      break;  // one report per function
    }
  }
}

TEST(Monotonicity, BinaryFunctionsRandom) {
  const std::vector<std::pair<std::string, Binary>> fs = {
      {"atan2", [](const Interval& a, const Interval& b) { return atan2(a, b); }},
      {"pow", [](const Interval& a, const Interval& b) { return pow(a, b); }},
      {"+", [](const Interval& a, const Interval& b) { return a + b; }},
      {"*", [](const Interval& a, const Interval& b) { return a * b; }},
      {"/", [](const Interval& a, const Interval& b) { return a / b; }},
      {"min", [](const Interval& a, const Interval& b) { return min(a, b); }},
  };
  Boxes g(8);
  for (const auto& [name, f] : fs) {
    for (int k = 0; k < 40000; ++k) {
      const Interval x1 = g.box(), x2 = g.box();
      const Interval y1 = k % 3 == 0 ? x1 : g.sub(x1), y2 = k % 3 == 1 ? x2 : g.sub(x2);
      if (f(y1, y2).is_subset(f(x1, x2))) continue;
      ADD_FAILURE() << name << " (" << y1 << ", " << y2 << ") in (" << x1 << ", " << x2 << "): " << f(y1, y2)
                    << " vs " << f(x1, x2);
      break;
    }
  }
}
