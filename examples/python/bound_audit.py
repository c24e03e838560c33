"""The bound audit of the real-data examples (the same as examples/cpp/bound_audit.h): given a
ground truth, how much of each stated error bound the truth used ("turn rate: max 0.71 rad/s of 4
allowed (18 %)"). It reports; it never changes a bound. A bound the truth uses at more than 100 %
is violated; one it uses at nearly 100 % was probably read off the file it is applied to. The lines
are sillage.AuditLine (the library's, which also audits a problem file: sillage.audit_problem)."""
from sillage import AuditLine  # noqa: F401  (the examples build their lines with it)


def print_audit(title, lines):
    """Prints the audit; True if the truth violates no bound."""
    print(f"bound audit ({title}): how much of each bound the ground truth used")
    for line in lines:
        print("  " + line.text())
    return not any(line.percent() > 100 for line in lines)
