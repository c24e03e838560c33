#include "sillage/problem/report_html.h"

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "sillage/figures/html.h"
#include "sillage/interval/angle.h"
#include "sillage/figures/loops_map_figure.h"
#include "sillage/figures/map_envelope.h"
#include "sillage/figures/tplane_figure.h"
#include "sillage/problem/problem_loops.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/figures/tube_figure.h"
#include "sillage/problem/bound_audit.h"
#include "sillage/problem/explain_figure.h"
#include "sillage/problem/interval_text.h"
#include "sillage/problem/var_sizes.h"

namespace sillage {

namespace {

std::string fmt(double x, const char* f = "%.6g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

std::string itv(const Interval& x) { return detail::interval_text(x); }

std::string comp_name(const VarDomain& v, std::size_t i) {
  const bool scalar = v.spec->kind == VarKind::Tube || v.spec->kind == VarKind::Interval;
  return scalar ? v.spec->name : v.spec->name + "[" + std::to_string(i) + "]";
}

const std::vector<std::string>* truth_columns(const Problem& p, const std::string& var) {
  if (!p.output.truth) return nullptr;
  const auto it = p.output.truth->columns.find(var);
  return it == p.output.truth->columns.end() ? nullptr : &it->second;
}

Trajectory truth_trajectory(const Problem& p, const std::string& column) {
  const CsvTable& t = p.table(p.output.truth->data)->table;
  return Trajectory(t.values(p.output.truth->time_column), t.values(column));
}

// A figure, or a note saying why it could not be drawn (an unbounded tube).
std::string figure_block(const std::function<Figure()>& make, const std::string& caption) {
  std::string svg;
  try {
    svg = make().svg();
    // Inline in HTML: the XML declaration of the file form is not wanted.
    if (svg.rfind("<?xml", 0) == 0) svg.erase(0, svg.find("?>") + 2);
  } catch (const Error& e) {
    return "<figure><p class=\"note\">" + xml_escape(caption) + ": not drawn (" + xml_escape(e.what()) + ")</p></figure>\n";
  }
  return "<figure>" + svg + "<figcaption>" + xml_escape(caption) + "</figcaption></figure>\n";
}

// [output] loops: the counts, the complete detections and the t-plane and map figures.
std::string loops_section(const Problem& p, const BuiltProblem& b) {
  std::ostringstream h;
  h << "<h2>Loops (t-plane)</h2>\n";
  std::optional<TPlane> tp;
  try {
    tp = find_loops(p, b);
  } catch (const Error& e) {
    h << "<p class=\"note\">Loops not computed: " << xml_escape(e.what()) << "</p>\n";
    return h.str();
  }
  const LoopsSpec& l = *p.output.loops;
  h << "<p id=\"loops\">t-plane of " << xml_escape(l.p.empty() ? l.v : l.p + ", " + l.v) << " paved to ε = " << fmt(tp->eps())
    << ": " << tp->nb_detections() << " detections, " << tp->nb_complete_detections() << " complete, " << tp->nb_proofs()
    << " proven loops (degree test), " << tp->nb_newton_proofs() << " unique loops (Newton).</p>\n";
  h << "<table id=\"loop_table\"><tr><th>[t1]</th><th>[t2]</th><th>map box</th><th>degree</th><th>loops</th></tr>";
  for (const Loop& loop : tp->detections()) {
    if (!loop.complete()) continue;
    h << "<tr><td>" << itv(loop.t_box()[0]) << "</td><td>" << itv(loop.t_box()[1]) << "</td><td>"
      << itv(loop.map_box()[0]) << " × " << itv(loop.map_box()[1]) << "</td><td>"
      << (loop.degree() ? std::to_string(*loop.degree()) : std::string("?")) << "</td><td>"
      << (loop.count() ? std::to_string(*loop.count()) : std::string("?")) << "</td></tr>";
  }
  h << "</table>\n";
  h << figure_block([&] { return tplane_figure(*tp, nullptr, "t-plane of " + (l.p.empty() ? l.v : l.p)); },
                    "The t-plane: detections of loops, proven ones marked");
  const TubeVector* pos = l.p.empty() ? nullptr : b.var(l.p).tubes.get();
  h << figure_block([&] { return loops_map_figure(*tp, nullptr, nullptr, pos, nullptr, "Loops on the map", 700, {},
                                                  pos ? l.p + "[0]" : "x", pos ? l.p + "[1]" : "y"); },
                    std::string("The loops on the map") + (pos ? "" : " (positions relative to the start)"));
  return h.str();
}

// Eval rows skipped as outside [t0, tf] (outside = "skip"): "0", or "3 (constraint 2 ...: 3)".
std::string rows_outside(const Problem& p) {
  std::size_t n = 0;
  std::string which;
  for (const ConstraintSpec& c : p.constraints) {
    if (c.nb_outside == 0) continue;
    n += c.nb_outside;
    which += (which.empty() ? "" : "; ") + xml_escape(c.label) + ": " + std::to_string(c.nb_outside);
  }
  return std::to_string(n) + (which.empty() ? "" : " (" + which + ")");
}

// The maps of [output] maps on the domains b (`what` after each title: " before the contradiction").
std::string map_figures(const Problem& p, const BuiltProblem& b, const std::string& what) {
  std::ostringstream h;
  for (const auto& [var, pair] : p.output.maps) {
    const VarDomain& v = b.var(var);
    const auto* cols = truth_columns(p, var);
    std::optional<Trajectory> ti, tj;
    if (cols) ti = truth_trajectory(p, (*cols)[pair.first]), tj = truth_trajectory(p, (*cols)[pair.second]);
    const std::string title = comp_name(v, pair.first) + " × " + comp_name(v, pair.second);
    const auto* marks = p.output.landmarks ? &*p.output.landmarks : nullptr;
    std::vector<Vector> points;  // the landmarks: in the map's window, dots distinct from the truth's line
    if (marks) {
      const CsvTable& t = p.table(marks->data)->table;
      for (std::size_t r = 0; r < t.nb_rows(); ++r)
        points.push_back(Vector{t.row(r)[t.column(marks->x)], t.row(r)[t.column(marks->y)]});
    }
    h << figure_block(
        [&] {
          return map_envelope_figure(*v.tubes, pair.first, pair.second, title + what, {}, ti ? &*ti : nullptr,
                                     tj ? &*tj : nullptr, 600, marks ? &points : nullptr, comp_name(v, pair.first),
                                     comp_name(v, pair.second));
        },
        "Map " + title + what + ": the envelope of the boxes of every slice (within a grid cell), a few of them drawn" +
            (cols ? ", the truth as a red line" : "") +
            (marks ? ", landmarks of '" + marks->data + "' as yellow dots" : ""));
  }
  return h.str();
}

// No solution: what to relax (the explanation), best first.
std::string explanation_section(const Explanation& e) {
  std::ostringstream h;
  h << "<h2>Why there is no solution</h2>\n";
  if (e.relaxations.empty())
    h << "<p id=\"explanation\" class=\"note\">" << (e.complete ? "No set of the file's statements was found whose relaxation removes the contradiction."
                                                              : "No relaxation was found in the time given.") << "</p>\n";
  else {
    h << "<ol id=\"explanation\">";
    for (const Relaxation& r : e.relaxations) {
      h << "<li>relaxing ";
      for (std::size_t k = 0; k < r.items.size(); ++k)
        h << (k ? ", " : "") << "<b>" << xml_escape(e.items[r.items[k]].str()) << "</b>";
      h << " restores a solution (no contradiction found)";
      if (!r.values.empty()) h << "<ul>";
      for (const ProvenValue& v : r.values)
        h << "<li>" << xml_escape(v.what) << " is then proven in " << xml_escape(v.proven_text())
          << (v.window.is_unbounded() ? "" : " (searched within " + itv(v.window) + ")") << "; the file states " << itv(v.stated)
          << (v.disjoint() ? ": <span class=\"empty\">impossible given the rest of the file</span>" : "") << "</li>";
      if (!r.values.empty()) h << "</ul>";
      h << "</li>";
    }
    h << "</ol>\n<p class=\"note\">\"Restores a solution\": with that statement relaxed (a bound made the whole line; a "
         "gate, table, constraint or rows dropped) the contraction is not empty. Every solution needs that, but it does "
         "not prove one. The values proven hold for every solution of the relaxed problem.</p>\n";
  }
  h << "<p class=\"note\">" << e.trials.size() << " trials at δ = " << fmt(e.delta) << " (" << e.slices << " slices) in "
    << fmt(e.seconds, "%.2f") << " s" << (e.complete ? "" : "; partial: " + xml_escape(e.stopped)) << ".</p>\n";
  return h.str();
}

// No solution: each tube component as it was just before the contradiction, the blamed statements marked.
std::string before_empty_figures(const Problem& p, const BuiltProblem& b, const Explanation* e) {
  std::ostringstream h;
  h << "<p class=\"note\" id=\"before_empty\">The tubes as the propagation had contracted them just before the "
       "contractor that emptied a domain ran: every value outside them is in no solution; they show where the "
       "constraints met before the contradiction"
    << (e ? " (red: a blamed statement's value; green: the value the relaxed problem proves; orange: blamed rows)" : "")
    << ".</p>\n";
  h << map_figures(p, b, " before the contradiction");
  std::size_t shown = 0;
  for (const VarDomain& v : b.vars) {
    if (!v.tubes) continue;
    for (std::size_t i = 0; i < v.spec->dim && shown < 24; ++i, ++shown) {
      const std::string name = comp_name(v, i);
      const std::vector<detail::FigureMark> marks =
          e ? detail::blamed_marks(p, *e, v.spec->name, i) : std::vector<detail::FigureMark>{};
      h << figure_block([&] { return detail::marked_tube_figure((*v.tubes)[i], name, "[" + name + "](t) before the contradiction", marks); },
                        "The tube [" + name + "](·) just before the contradiction" + (marks.empty() ? "" : ", the blamed statements marked"));
    }
  }
  return h.str();
}

// The sizes of the variables (var_sizes.h): what a user reads first.
std::string sizes_section(const Problem& p, const BuiltProblem& b) {
  const std::vector<VarSize> sizes = var_sizes(p, b);
  const bool truth = p.output.truth.has_value();
  std::ostringstream h;
  h << "<h2>Sizes</h2>\n<p class=\"note\">The box diameter of each variable: the largest width over its components, "
       "over time (mean and median weighted by the slices' durations)"
    << (truth ? " and at the truth's time points" : "") << "; in the unit the file states ([var.NAME] unit).</p>\n"
    << "<table id=\"sizes\"><tr><th>variable</th><th>unit</th><th>mean</th><th>median</th><th>max</th>";
  if (truth) h << "<th>mean at truth times</th><th>median</th><th>max</th>";
  h << "</tr>\n";
  for (const VarSize& v : sizes) {
    h << "<tr><td>" << xml_escape(v.name) << "</td><td>" << xml_escape(v.unit) << "</td><td>" << fmt(v.over_time.mean, "%.4g")
      << "</td><td>" << fmt(v.over_time.median, "%.4g") << "</td><td>" << fmt(v.over_time.max, "%.4g") << "</td>";
    if (v.at_truth)
      h << "<td>" << fmt(v.at_truth->mean, "%.4g") << "</td><td>" << fmt(v.at_truth->median, "%.4g") << "</td><td>"
        << fmt(v.at_truth->max, "%.4g") << "</td>";
    else if (truth)
      h << "<td></td><td></td><td></td>";
    h << "</tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

// The truth check of [output.truth].
std::string truth_section(const Problem& p, const BuiltProblem& b) {
  std::ostringstream h;
  h << "<h2>Truth check</h2>\n";
  const TruthCheck c = check_truth(p, b);
  h << "<p id=\"truth\">" << c.inside << " of " << c.samples
    << " truth time points inside the tubes (every component of the truth inside).</p>\n";
  if (!c.first_misses.empty()) {
    h << "<ul>";
    for (const std::string& m : c.first_misses) h << "<li>" << xml_escape(m) << "</li>";
    h << "</ul>\n";
  }
  return h.str();
}

// The bound audit of the file against its truth (bound_audit.h).
std::string audit_section(const Problem& p) {
  std::ostringstream h;
  h << "<h2>Bound audit</h2>\n<p class=\"note\">How much of each stated bound the truth used: its distance from the "
       "middle of the bound over the bound's half-width (100 %: at an edge; above: violated, the guarantee is void). "
       "It changes no bound.</p>\n<table id=\"audit\"><tr><th>bound</th><th>used</th><th>allowed</th><th>%</th>"
       "<th>how</th></tr>\n";
  for (const AuditLine& l : audit_problem(p)) {
    const double pc = audit_percent(l);
    const std::string unit = l.unit.empty() ? "" : " " + xml_escape(l.unit);
    h << "<tr" << (pc > 100 ? " class=\"empty\"" : "") << "><td>" << xml_escape(l.name) << "</td><td>"
      << (std::isnan(l.used) ? "not measurable" : fmt(l.used, "%.4g") + unit) << "</td><td>"
      << (std::isnan(l.allowed) ? "" : fmt(l.allowed, "%.4g") + unit) << "</td><td>"
      << (std::isnan(pc) ? "" : fmt(pc, "%.0f") + (pc > 100 ? " VIOLATED" : "")) << "</td><td>" << xml_escape(l.how)
      << "</td></tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

// One thickness figure per tube variable: its box diameter over time, the measure of the sizes.
std::string thickness_figures(const BuiltProblem& b) {
  std::ostringstream h;
  for (const VarDomain& v : b.vars) {
    if (!v.tubes) continue;
    const std::string name = v.spec->name, unit = v.spec->unit.empty() ? "" : " (" + v.spec->unit + ")";
    h << figure_block([&] { return thickness_figure(*v.tubes, ThicknessMeasure::MaxDiameter, "Box diameter of " + name + unit); },
                      "Box diameter of " + name + " over time (the largest width over its components)" + unit);
  }
  return h.str();
}

}  // namespace

TruthCheck check_truth(const Problem& p, const BuiltProblem& b) {
  TruthCheck c;
  if (!p.output.truth) return c;
  const CsvTable& t = p.table(p.output.truth->data)->table;
  const std::size_t tc = t.column(p.output.truth->time_column);
  // Per time point (row), not per component: a point is inside when all its components are.
  for (std::size_t r = 0; r < t.nb_rows(); ++r) {
    const double time = t.row(r)[tc];
    if (time < b.td->t0() || time > b.td->tf()) continue;
    ++c.samples;
    bool inside = true;
    for (const auto& [var, cols] : p.output.truth->columns) {
      const VarDomain& v = b.var(var);
      for (std::size_t i = 0; i < cols.size(); ++i) {
        const double value = t.row(r)[t.column(cols[i])];
        const Interval x = (*v.tubes)[i](time);
        // An angle's truth is on its arc modulo 2π; the whole circle proves nothing.
        if (v.spec->angle ? angle_contains(x, value) && !angle_is_circle(x) : x.contains(value) && x.is_bounded()) continue;
        inside = false;  // an unbounded domain holds anything: it proves nothing, so it is no pass
        if (c.first_misses.size() < 10)
          c.first_misses.push_back(comp_name(v, i) + " = " + fmt(value) + " at t = " + fmt(time) +
                                   (x.is_unbounded()                              ? " in the unbounded "
                                    : v.spec->angle && angle_is_circle(x) ? " in the whole circle "
                                                                          : " outside ") +
                                   itv(x));
      }
    }
    c.inside += inside;
  }
  return c;
}

std::string report_html(const Problem& p, const SolveResult& r, const Explanation* e) {
  const BuiltProblem& b = r.built;
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>sillage: " << xml_escape(p.file)
    << "</title>\n<style>body{font-family:sans-serif;max-width:1000px;margin:auto;padding:1em}"
       "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:2px 6px;font-size:90%}"
       "pre{background:#f4f4f4;padding:.5em;overflow:auto}.empty{color:#b00;font-weight:bold}"
       "figure{margin:1em 0}figcaption{font-size:90%;color:#444}.note{color:#777}summary{cursor:pointer}</style></head><body>\n";
  h << "<h1>sillage solve " << xml_escape(p.file) << "</h1>\n";
  if (r.empty)
    h << "<p class=\"empty\" id=\"status\">No solution: " << xml_escape(r.why_empty) << "</p>\n";
  else if (!r.stopped.empty())
    h << "<p class=\"empty\" id=\"status\">Stopped before the fixed point: " << xml_escape(r.stopped)
      << ". Every domain below still encloses every solution; a larger budget may contract them further.</p>\n";
  else
    h << "<p id=\"status\">Solved: every domain below encloses every solution of the problem.</p>\n";

  if (!r.warnings.empty()) {
    h << "<ul id=\"warnings\">";
    for (const std::string& w : r.warnings) h << "<li class=\"empty\">Warning: " << xml_escape(w) << "</li>";
    h << "</ul>\n";
  }

  if (r.empty && e && e->empty) h << explanation_section(*e);

  // What a user reads first: how well each variable is known, and whether the truth is inside.
  if (!r.empty) h << sizes_section(p, b);
  if (p.output.truth) {
    if (!r.empty) h << truth_section(p, b);
    h << audit_section(p);
  }

  std::vector<OutputTime> times = p.output.times;
  if (times.empty())
    for (const double t : {b.td->t0(), (b.td->t0() + b.td->tf()) / 2, b.td->tf()}) times.push_back({t, t, t});
  h << "<h2>Results</h2>\n<table id=\"results\"><tr><th>variable</th>";
  for (const OutputTime& t : times) h << "<th>t = " << fmt(t.t) << "</th>";
  h << "</tr>\n";
  for (const VarDomain& v : b.vars) {
    // A time as written may lie between two doubles: the tube over that interval,
    // through its derivative when a deriv constraint gives one (the polygon, not the slice).
    const ConstraintSpec* d = v.tubes ? p.deriv_of(v.spec->name) : nullptr;
    for (std::size_t i = 0; i < v.spec->dim; ++i) {
      h << "<tr><td>" << xml_escape(comp_name(v, i)) << "</td>";
      for (const OutputTime& t : times) {
        const Interval at(t.lo, t.hi);
        const Interval x = r.empty  ? Interval::empty()  // no solution: every set is empty
                           : !v.tubes ? (v.interval ? *v.interval : (*v.box)[i])
                           : d        ? (*v.tubes)[i].eval(at, (*b.var(d->v).tubes)[i])
                                      : (*v.tubes)[i](at);
        h << "<td>" << itv(x) << "</td>";
      }
      h << "</tr>\n";
    }
  }
  h << "</table>\n";

  h << "<h2>Figures</h2>\n";
  if (r.empty && r.before_empty) h << before_empty_figures(p, *r.before_empty, e);
  else if (r.empty) h << "<p class=\"note\">No figure: the domains are empty.</p>\n";
  else {
    h << map_figures(p, b, "");
    h << thickness_figures(b);
    std::vector<std::pair<std::string, std::size_t>> plots = p.output.plot_tubes;
    if (plots.empty())
      for (const VarDomain& v : b.vars)
        if (v.tubes) plots.push_back({v.spec->name, static_cast<std::size_t>(-1)});
    std::size_t shown = 0;
    for (const auto& [var, comp] : plots) {
      const VarDomain& v = b.var(var);
      for (std::size_t i = 0; i < v.spec->dim && shown < 24; ++i) {
        if (comp != static_cast<std::size_t>(-1) && comp != i) continue;
        ++shown;
        const auto* cols = truth_columns(p, var);
        std::optional<Trajectory> tr;
        if (cols) tr = truth_trajectory(p, (*cols)[i]);
        const std::string name = comp_name(v, i);
        h << figure_block([&] { return tube_figure((*v.tubes)[i], "[" + name + "](t)", {}, tr ? &*tr : nullptr, 600, 300, name); },
                          "The tube [" + name + "](·)" + (tr ? " and the truth" : ""));
      }
    }
  }

  if (p.output.loops && !r.empty) h << loops_section(p, b);

  h << "<h2>Schedule</h2>\n<table id=\"schedule\"><tr><th>δ</th><th>slices</th><th>Σ mean thickness (all tubes, "
       "the automatic δ's criterion)</th><th>rounds</th><th>contractor runs</th><th>build (s)</th><th>contract (s)</th></tr>\n";
  for (const ScheduleStep& s : r.schedule)
    h << "<tr><td>" << fmt(s.delta) << "</td><td>" << s.slices << "</td><td>" << fmt(s.mean_thickness) << "</td><td>"
      << s.stats.iterations << "</td><td>" << s.stats.contractor_calls << "</td><td>" << fmt(s.build_seconds, "%.4f")
      << "</td><td>" << fmt(s.contract_seconds, "%.4f") << "</td></tr>\n";
  h << "</table>\n<p id=\"scheduling\">Scheduling: " << scheduling_name(r.scheduling)
    << (r.scheduling == Scheduling::Priority ? " (each round by expected contraction over cost)" : " (each round in the order woken)")
    << ".</p>\n";

  const double build = r.build_seconds(), contract = r.contract_seconds();
  h << "<h2>Run statistics</h2>\n<table id=\"stats\">"
    << "<tr><td>variables</td><td>" << b.vars.size() << "</td></tr>"
    << "<tr><td>constraints (file)</td><td>" << p.constraints.size() << "</td></tr>"
    << "<tr><td>eval rows outside [t0, tf], skipped</td><td>" << rows_outside(p) << "</td></tr>"
    << "<tr><td>network nodes</td><td>" << b.cn->nb_ctc() << "</td></tr>"
    << "<tr><td>network domains</td><td>" << b.cn->nb_dom() << "</td></tr>"
    << "<tr><td>scheduling</td><td>" << scheduling_name(r.scheduling) << "</td></tr>"
    << "<tr><td>slices</td><td>" << b.td->nb_slices() << "</td></tr>"
    << "<tr><td>tube memory</td><td>" << fmt(b.memory_bytes() / 1048576.0, "%.2f") << " MiB</td></tr>"
    << "<tr><td>build time (all steps)</td><td>" << fmt(build, "%.4f") << " s ("
    << fmt(build + contract > 0 ? 100 * build / (build + contract) : 0, "%.1f") << " %)</td></tr>"
    << "<tr><td>contraction time (all steps)</td><td>" << fmt(contract, "%.4f") << " s</td></tr>"
    << "</table>\n";

  // The file itself last, folded: it is long and the reader has it.
  h << "<h2>Problem</h2>\n<details id=\"problem\"><summary>" << xml_escape(p.file) << " (hash " << p.hash
    << ", " << std::count(p.text.begin(), p.text.end(), '\n') << " lines)</summary><pre>" << xml_escape(p.text)
    << "</pre></details>\n</body></html>\n";
  return h.str();
}

}  // namespace sillage
