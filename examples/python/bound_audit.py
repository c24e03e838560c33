"""The bound audit of the real-data examples (the same as examples/cpp/bound_audit.h): given a
ground truth, how much of each stated error bound the truth used ("turn rate: max 0.71 rad/s of 4
allowed (18 %)"). It reports; it never changes a bound. A bound the truth uses at more than 100 %
is violated; one it uses at nearly 100 % was probably read off the file it is applied to."""
import math
from dataclasses import dataclass


@dataclass
class AuditLine:
    name: str      # the bound
    unit: str
    allowed: float  # the stated bound (a magnitude, > 0)
    used: float     # the largest value the truth needs (nan: not measurable from the truth)
    how: str        # how `used` was measured

    def percent(self):
        return 100.0 * self.used / self.allowed

    def text(self):
        if math.isnan(self.used):
            return f"{self.name}: {self.allowed:.4g} {self.unit} allowed, not measurable from the truth ({self.how})"
        p = self.percent()
        return (f"{self.name}: max {self.used:.4g} {self.unit} of {self.allowed:.4g} allowed ({p:.0f} %; {self.how})"
                + ("  <-- VIOLATED" if p > 100 else ""))


def print_audit(title, lines):
    """Prints the audit; True if the truth violates no bound."""
    print(f"bound audit ({title}): how much of each bound the ground truth used")
    for line in lines:
        print("  " + line.text())
    return not any(line.percent() > 100 for line in lines)
