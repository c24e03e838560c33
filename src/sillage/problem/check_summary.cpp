#include "sillage/problem/check_summary.h"

#include <cstdarg>
#include <cstdio>

#include "sillage/problem/build_network.h"
#include "sillage/problem/eval_rows.h"
#include "sillage/problem/problem_warnings.h"

namespace sillage {

namespace {

std::string line(const char* f, ...) __attribute__((format(printf, 1, 2)));
std::string line(const char* f, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, f);
  std::vsnprintf(buf, sizeof buf, f, ap);
  va_end(ap);
  return buf;
}

}  // namespace

std::string check_summary(const Problem& p) {
  const double delta = p.time.delta ? *p.time.delta : (p.time.tf - p.time.t0) / 64;
  std::size_t slices = nb_slices_for(p, delta);
  for (const ConstraintSpec& c : p.constraints)  // an upper bound: two gates per row
    if (c.kind == ConstraintKind::Eval && c.gates) slices += 2 * p.table(c.data)->table.nb_rows();
  for (const VarSpec& v : p.vars)  // an upper bound: an 'at' time inside (t0, tf) may sample the domain
    for (const GateSpec& g : v.at) slices += g.t > p.time.t0 && g.t < p.time.tf;
  std::string s = line("%s: valid (hash %s)\n", p.file.c_str(), p.hash.c_str());
  if (p.time.points.empty())
    s += line("time [%g, %g], δ = %g%s, %zu slices at most\n", p.time.t0, p.time.tf, delta,
              p.time.delta ? "" : " (auto: the first step)", slices);
  else
    s += line("time [%g, %g], the %zu stamps of '%s', %zu slices at most\n", p.time.t0, p.time.tf, p.time.points.size(),
              p.time.points_data.c_str(), slices);
  std::size_t bytes = 0, domains = 0, nodes = 0;
  s += "variables:\n";
  for (const VarSpec& v : p.vars) {
    const std::size_t b = v.is_tube() ? v.dim * (2 * slices + 1) * 16 : v.dim * 16;
    bytes += b;
    domains += v.is_tube() ? v.dim : 1;
    s += line("  %-12s %-11s dim %-3zu %10.3f MiB\n", v.name.c_str(), kind_name(v.kind), v.dim, b / 1048576.0);
  }
  s += "constraints:\n";
  for (const ConstraintSpec& c : p.constraints) {
    std::size_t n = 1;
    if (c.kind == ConstraintKind::Eval) {
      // One CtcEvalList holding the rows, or per row a CtcEval and its observation; the CtcDeriv it implies.
      const bool listed = detail::eval_rows_listed(p, c, detail::eval_observation(p, c));
      n = (listed ? 1 : 2 * p.table(c.data)->table.nb_rows()) + detail::implied_derivs(p, c).size();
      if (listed && c.q) {  // one CtcQEval per group of rows instead of the CtcEvalList
        const CsvTable& t = p.table(c.data)->table;
        const Interval terr = Function({"t"}, c.time_error).eval(IntervalVector{Interval(0)});
        std::vector<Interval> times;
        for (std::size_t row = 0; row < t.nb_rows(); ++row) {
          if (!detail::eval_row_kept(c, t, t.row(row))) continue;
          const Interval rt = detail::eval_row_time(c, t, t.row(row), terr, Interval(p.time.t0, p.time.tf));
          if (!rt.is_empty()) times.push_back(rt);
        }
        n = n + detail::outlier_groups(c, times).size() - 1;  // n >= 1 here
      }
      if (!listed) domains += 3 * p.table(c.data)->table.nb_rows();
      bytes += 6 * 16 * p.table(c.data)->table.nb_rows();
    }
    nodes += n;
    s += line("  %-8zu nodes  %s\n", n, c.label.c_str());
    if (c.nb_outside > 0)
      s += line("           %zu row(s) of '%s' outside [t0, tf] skipped (outside = \"skip\")\n", c.nb_outside,
                c.data.c_str());
    if (c.kind == ConstraintKind::Eval) {  // a 'where' that keeps no row states nothing: say so
      const CsvTable& t = p.table(c.data)->table;
      std::size_t used = 0;
      for (std::size_t row = 0; row < t.nb_rows(); ++row) used += detail::eval_row_kept(c, t, t.row(row));
      used -= c.nb_outside;
      s += line("           %zu of the %zu rows of '%s' used%s\n", used, t.nb_rows(), c.data.c_str(),
                used == 0 ? ": none, this constraint states nothing" : "");
    }
  }
  for (const std::string& w : problem_warnings(p)) s += "warning: " + w + "\n";
  s += line("network: %zu nodes, about %zu domains, about %.3f MiB of domains, %s scheduling\n", nodes, domains,
            bytes / 1048576.0, scheduling_name(p.network.scheduling));
  s += line("memory: about %.1f MiB at the peak of a solve (an estimate)\n",
            static_cast<double>(peak_memory_estimate(p, slices)) / 1048576.0);
  return s;
}

}  // namespace sillage
