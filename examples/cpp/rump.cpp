// Rump's expression (thesis (2.2)) at (77617, 33096): floating point gives a
// confident wrong answer; interval arithmetic gives an enclosure that contains
// the exact value -0.827396059946821368... and, by its width, says that the
// double result cannot be trusted.
#include <cstdio>
#include <sstream>

#include "example_args.h"
#include "sillage/interval/elementary.h"
#include "sillage/interval/interval.h"

using sillage::Interval;

template <class T>
T rump(T x, T y) {
  const T y2 = y * y, x2 = x * x;
  const T y4 = y2 * y2, y6 = y4 * y2, y8 = y4 * y4;
  return T(333.75) * y6 + x2 * (T(11) * x2 * y2 - y6 - T(121) * y4 - T(2)) + T(5.5) * y8 + x / (T(2) * y);
}

int example_main(int argc, char** argv) {
  example::out_dir(argc, argv);
  volatile double xv = 77617.0, yv = 33096.0;  // volatile: evaluated at run time like user data
  const double f_double = rump<double>(xv, yv);
  const Interval f_interval = rump<Interval>(Interval(xv), Interval(yv));
  const double exact = -0.827396059946821368;  // (2.2), the exact value is -54767/66192

  std::printf("Rump's expression f(77617, 33096), thesis (2.2)\n");
  std::printf("  double:    %.17g\n", f_double);
  std::printf("  interval:  %s  (diam %.3g)\n", f_interval.str().c_str(), f_interval.diam());
  std::printf("  exact:     -0.827396059946821368...\n");
  const bool ok = f_interval.lb() <= exact && exact <= f_interval.ub();
  std::printf("  the enclosure contains the exact value: %s\n", ok ? "yes" : "NO");

  std::ostringstream result;
  result.precision(3);
  result << "double " << f_double << "; enclosure " << f_interval << " contains -0.8274";
  example::print_result("rump", result.str(), ok);
  return ok ? 0 : 1;
}

int main(int argc, char** argv) { return example::run(argc, argv, example_main); }
