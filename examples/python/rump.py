"""Rump's expression (thesis (2.2)) at (77617, 33096): floating point gives a
confident wrong answer; interval arithmetic encloses the exact value
-0.827396059946821368... and its width warns that the double result is meaningless."""
from fractions import Fraction

from example_args import bound, out_dir, print_result, run
from sillage import Function, IntervalVector


def rump(x, y, a=333.75, b=5.5):
    return a * y**6 + x**2 * (11 * x**2 * y**2 - y**6 - 121 * y**4 - 2) + b * y**8 + x / (2 * y)


def main():
    out_dir(__doc__)
    f_double = rump(77617.0, 33096.0)
    exact = rump(Fraction(77617), Fraction(33096), Fraction(1335, 4), Fraction(11, 2))  # = -54767/66192
    f = Function(["x", "y"], "333.75*y^6 + x^2*(11*x^2*y^2 - y^6 - 121*y^4 - 2) + 5.5*y^8 + x/(2*y)")
    enclosure = bound(f.eval(IntervalVector([[77617, 77617], [33096, 33096]])))
    ok = Fraction(enclosure.lb()) <= exact <= Fraction(enclosure.ub())
    print("Rump's expression f(77617, 33096), thesis (2.2)")
    print(f"  double:    {f_double!r}")
    print(f"  interval:  {enclosure}  (diam {enclosure.diam():.3g})")
    print(f"  exact:     {float(exact)!r}  (= {exact})")
    print(f"  the enclosure contains the exact value: {'yes' if ok else 'NO'}")
    print_result("rump", f"double {f_double:.4g}; enclosure {enclosure} contains {float(exact):.4f}", ok)
    return 0 if ok else 1


if __name__ == "__main__":
    run(main)
