// Problem files (sillage/problem) in Python: load_problem, check_summary,
// solve_problem and solve(path), which returns the domains as sillage objects.
#include <filesystem>

#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <map>

#include "bindings.h"
#include "docstrings.h"
#include "interruptible.h"
#include "sillage/problem/bound_audit.h"
#include "sillage/problem/check_summary.h"
#include "sillage/problem/load_problem.h"
#include "sillage/problem/problem_loops.h"
#include "sillage/problem/problem_warnings.h"
#include "sillage/problem/python_constraint.h"
#include "sillage/problem/report_html.h"
#include "sillage/problem/set_problem_key.h"
#include "sillage/problem/write_results.h"
#include "sillage/problem/solve_problem.h"
#include "sillage/problem/var_sizes.h"

namespace sillage::python {

bool is_tube_ctc(const py::handle& h);  // bind_tube_node.cpp
std::shared_ptr<const NetworkCtc> bind_tube_ctc(const py::handle& ctc, const py::list& domains);

namespace {

// kind = "python" (python_constraint.h): imports c.module (the problem file's folder first on
// sys.path), builds c.cls(**c.params), a sillage.TubeCtc, on the tube variables of c.args.
std::shared_ptr<const NetworkCtc> python_constraint(const ConstraintSpec& c, const std::string& file,
                                                    const std::vector<const VarDomain*>& args) {
  py::gil_scoped_acquire gil;
  const std::string at = c.pos.str() + ": " + c.label + ": ";
  try {
    const std::string dir = std::filesystem::absolute(std::filesystem::path(file)).parent_path().string();
    py::list path = py::module_::import("sys").attr("path");
    if (!path.contains(py::str(dir))) path.insert(0, py::str(dir));
    const py::module_ mod = py::module_::import(c.module.c_str());
    if (!py::hasattr(mod, c.cls.c_str()))
      throw Error(at + "found no class '" + c.cls + "' in the module " + c.module + " (" +
                  std::string(py::str(mod.attr("__file__"))) + ")");
    py::dict kwargs;
    for (const auto& [k, v] : c.params) kwargs[py::str(k)] = v;
    const py::object ctc = mod.attr(c.cls.c_str())(**kwargs);
    if (!is_tube_ctc(ctc))
      throw Error(at + "found " + c.module + "." + c.cls + ", which is not a sillage.TubeCtc subclass");
    py::list domains;
    for (const VarDomain* v : args) {
      if (v->spec->kind == VarKind::Tube) domains.append(py::cast(v->tubes->shared_component(0)));
      else domains.append(py::cast(v->tubes));
    }
    return bind_tube_ctc(ctc, domains);
  } catch (py::error_already_set& e) {  // an import or constructor error, said where
    throw Error(at + "cannot build " + c.module + "." + c.cls + ": " + e.what());
  }
}

// {name: Tube | TubeVector | Interval | IntervalVector}, copies of the solved domains
// (a Tube is the solved object itself, shared).
py::dict domains(BuiltProblem& b) {
  py::dict d;
  for (VarDomain& v : b.vars) {
    const char* name = v.spec->name.c_str();
    if (v.tubes && v.spec->kind == VarKind::Tube) d[name] = v.tubes->shared_component(0);
    else if (v.tubes) d[name] = TubeVector(*v.tubes);
    else if (v.interval) d[name] = *v.interval;
    else d[name] = *v.box;
  }
  return d;
}

py::list schedule(const SolveResult& r) {
  py::list l;
  for (const ScheduleStep& s : r.schedule) {
    py::dict d;
    d["delta"] = s.delta;
    d["slices"] = s.slices;
    d["mean_thickness"] = s.mean_thickness;
    d["build_seconds"] = s.build_seconds;
    d["contract_seconds"] = s.contract_seconds;
    d["stats"] = s.stats;
    l.append(d);
  }
  return l;
}

// The options of `sillage solve` under the same names: delta = a width or "auto", refine = "halving" |
// "regions" (or refinement = DeltaRefinement), scheduling = "fifo" | "priority" or a Scheduling.
SolveOptions options_of(const py::object& delta, bool auto_delta, DeltaRefinement refinement,
                        const std::optional<std::string>& refine, const py::object& scheduling) {
  SolveOptions o;
  o.auto_delta = auto_delta;
  if (py::isinstance<py::str>(delta)) {
    if (delta.cast<std::string>() != "auto") throw py::value_error("delta: expected a slice width > 0 or \"auto\"");
    o.auto_delta = true;
  } else if (!delta.is_none()) {
    o.delta = delta.cast<double>();
  }
  o.refinement = refinement;
  if (refine) {
    if (*refine != "halving" && *refine != "regions")
      throw py::value_error("refine: found \"" + *refine + "\", expected \"halving\" or \"regions\"");
    o.refinement = *refine == "regions" ? DeltaRefinement::Regions : DeltaRefinement::Halving;
  }
  if (py::isinstance<py::str>(scheduling)) {
    const std::string s = scheduling.cast<std::string>();
    if (s != "fifo" && s != "priority")
      throw py::value_error("scheduling: found \"" + s + "\", expected \"fifo\" or \"priority\"");
    o.scheduling = s == "priority" ? Scheduling::Priority : Scheduling::Fifo;
  } else if (!scheduling.is_none()) {
    o.scheduling = scheduling.cast<Scheduling>();
  }
  return o;
}

// On a worker thread: Ctrl-C stops the contraction at its next contractor run (KeyboardInterrupt).
std::shared_ptr<SolveResult> solve_with(const Problem& p, const py::object& delta, bool auto_delta,
                                        double tolerance, double budget_seconds, DeltaRefinement refinement,
                                        const std::optional<std::string>& refine, const py::object& scheduling,
                                        const std::optional<Budget>& budget, bool keep_before_empty) {
  SolveOptions o = options_of(delta, auto_delta, refinement, refine, scheduling);
  o.keep_before_empty = keep_before_empty;
  o.tolerance = tolerance;
  o.budget_seconds = budget_seconds;
  if (budget) o.budget = *budget;
  return run_interruptible(o.budget.cancel, [&](const CancelToken& token) {
    return std::make_shared<SolveResult>(solve_problem(p, with_token(o, token)));
  });
}

}  // namespace

SILLAGE_BINDING(problem, "budget", "cn", "loops", "tube") {
  set_python_constraint_factory(&python_constraint);
  py::enum_<DeltaRefinement>(m, "DeltaRefinement", DOC(DeltaRefinement))
      .value("Halving", DeltaRefinement::Halving)
      .value("Regions", DeltaRefinement::Regions);
  py::class_<Problem>(m, "Problem", DOC(Problem))
      .def_readonly("file", &Problem::file, "The path of the file.")
      .SILLAGE_READONLY_FIELDS(Problem, hash)
      .def_property_readonly("variables", [](const Problem& p) {
        std::vector<std::string> v;
        for (const VarSpec& s : p.vars) v.push_back(s.name);
        return v;
      }, "The names of its variables.")
      .def_property_readonly("data_files", [](const Problem& p) {
        std::map<std::string, std::string> d;
        for (const DataSpec& s : p.data) d[s.name] = s.path;
        return d;
      }, "{name: path} of its [data.NAME] tables, the paths as resolved (against the file's folder, ${VAR} expanded).")
      .def_property_readonly("nb_constraints", [](const Problem& p) { return p.constraints.size(); },
                             "The number of [[constraint]] tables.")
      .def("__repr__", [](const Problem& p) {
        return "Problem('" + p.file + "', " + std::to_string(p.vars.size()) + " variables, " +
               std::to_string(p.constraints.size()) + " constraints, hash " + p.hash + ")";
      });

  py::class_<SolveResult, std::shared_ptr<SolveResult>>(
      m, "SolveResult", DOC(SolveResult))
      .SILLAGE_READONLY_FIELDS(SolveResult, empty, why_empty, scheduling, stopped, warnings, summary)
      .def_property_readonly("domains", [](SolveResult& r) { return domains(r.built); },
                             "{name: Tube | TubeVector | Interval | IntervalVector}, the contracted domains.")
      .def_property_readonly("before_empty", [](SolveResult& r) -> py::object {
        if (!r.before_empty) return py::none();
        return domains(*r.before_empty);
      }, DOC(SolveResult, before_empty))
      .def_property_readonly("schedule", &schedule,
                             "One dict per δ tried: delta, slices, mean_thickness, build_seconds, "
                             "contract_seconds, stats.")
      .SILLAGE_DEFS(SolveResult, build_seconds, contract_seconds)
      .def("__repr__", [](const SolveResult& r) {
        const ScheduleStep& s = r.schedule.back();
        return std::string("SolveResult(") + (r.empty ? "no solution" : r.stopped.empty() ? "solved" : "stopped") + ", delta=" + number_text(s.delta) +
               ", slices=" + std::to_string(s.slices) + ", steps=" + std::to_string(r.schedule.size()) + ")";
      });

  py::class_<TruthCheck>(m, "TruthCheck", DOC(TruthCheck))
      .def_readonly("samples", &TruthCheck::samples, "The truth time points within [t0, tf].")
      .def_readonly("inside", &TruthCheck::inside, "Those with every component inside a bounded tube value.")
      .SILLAGE_READONLY_FIELDS(TruthCheck, first_misses)
      .def("__repr__", [](const TruthCheck& c) {
        return "TruthCheck(" + std::to_string(c.inside) + " of " + std::to_string(c.samples) + " inside)";
      });
  py::class_<SizeStats>(m, "SizeStats", DOC(SizeStats))
      .SILLAGE_READONLY_FIELDS(SizeStats, mean, median, max, samples)
      .def("__repr__", [](const SizeStats& s) {
        return "SizeStats(mean=" + number_text(s.mean) + ", median=" + number_text(s.median) + ", max=" +
               number_text(s.max) + ", samples=" + std::to_string(s.samples) + ")";
      });
  py::class_<VarSize>(m, "VarSize", DOC(VarSize))
      .SILLAGE_READONLY_FIELDS(VarSize, name, unit, dim, over_time, at_truth)
      .SILLAGE_DEFS(VarSize, str)
      .def("__repr__", [](const VarSize& v) { return "VarSize(" + v.str() + ")"; });
  m.def(
      "var_sizes", [](const Problem& p, const SolveResult& r) { return var_sizes(p, r.built); },
      py::arg("problem"), py::arg("result"), DOC(var_sizes));
  py::class_<AuditLine>(m, "AuditLine", DOC(AuditLine))
      .def(py::init([](std::string name, std::string unit, double allowed, double used, std::string how) {
             return AuditLine{std::move(name), std::move(unit), allowed, used, std::move(how)};
           }),
           py::arg("name"), py::arg("unit"), py::arg("allowed"), py::arg("used"), py::arg("how"),
           "A line of the bound audit: the bound, its unit, the stated bound (> 0), the largest value the truth "
           "needs (nan: not measurable) and how it was measured.")
      .SILLAGE_FIELDS(AuditLine, name, unit, allowed, used, how)
      .def("percent", &audit_percent, DOC(audit_percent))
      .def("text", &audit_text, DOC(audit_text))
      .def("__repr__", [](const AuditLine& l) { return "AuditLine(" + audit_text(l) + ")"; });
  m.SILLAGE_FN(audit_percent, py::arg("line"));
  m.SILLAGE_FN(audit_text, py::arg("line"));
  m.SILLAGE_FN(audit_problem, py::arg("problem"));
  m.SILLAGE_FN(size_stats, py::arg("values"), py::arg("weights"));
  m.SILLAGE_FN(sizes_table, py::arg("sizes"));
  m.SILLAGE_FN(check_delta, py::arg("problem"), py::arg("delta"), py::arg("name") = "delta");
  m.def(
      "check_truth", [](const Problem& p, const SolveResult& r) { return check_truth(p, r.built); },
      py::arg("problem"), py::arg("result"), DOC(check_truth));

  m.def("load_problem", &load_problem, py::arg("path"),
        "Reads and validates a problem file; sillage.ParseError 'file:line:column: found ..., expected ...' otherwise.");
  m.def("parse_problem", &parse_problem, py::arg("text"), py::arg("path"), DOC(parse_problem));
  m.SILLAGE_FN(set_problem_key, py::arg("text"), py::arg("file"), py::arg("key"), py::arg("value"));
  m.SILLAGE_FN(check_summary, py::arg("problem"));
  m.def("solve_problem", &solve_with, py::arg("problem"), py::arg("delta") = py::none(), py::arg("auto_delta") = false,
        py::arg("tolerance") = 0.01, py::arg("budget_seconds") = 60.0,
        py::arg("refinement") = DeltaRefinement::Halving, py::arg("refine") = py::none(),
        py::arg("scheduling") = py::none(), py::arg("budget") = py::none(), py::arg("keep_before_empty") = true,
        DOC(solve_problem));
  m.def(
      "check_solve_options",
      [](const Problem& p, const py::object& delta, bool auto_delta, DeltaRefinement refinement,
         const std::optional<std::string>& refine, const std::string& prefix) {
        check_solve_options(p, options_of(delta, auto_delta, refinement, refine, py::none()), prefix);
      },
      py::arg("problem"), py::arg("delta") = py::none(), py::arg("auto_delta") = false,
      py::arg("refinement") = DeltaRefinement::Halving, py::arg("refine") = py::none(), py::arg("prefix") = "",
      DOC(check_solve_options));
  m.def(
      "solve",
      [](const std::string& path, const py::object& delta, bool auto_delta, double tolerance,
         double budget_seconds, DeltaRefinement refinement, const std::optional<std::string>& refine,
         const py::object& scheduling, const std::optional<Budget>& budget, bool keep_before_empty) {
        return solve_with(load_problem(path), delta, auto_delta, tolerance, budget_seconds, refinement, refine,
                          scheduling, budget, keep_before_empty);
      },
      py::arg("path"), py::arg("delta") = py::none(), py::arg("auto_delta") = false, py::arg("tolerance") = 0.01,
      py::arg("budget_seconds") = 60.0, py::arg("refinement") = DeltaRefinement::Halving,
      py::arg("refine") = py::none(), py::arg("scheduling") = py::none(), py::arg("budget") = py::none(),
      py::arg("keep_before_empty") = true,
      "solve_problem(load_problem(path)): the problem file solved; .domains holds the sillage objects.");
  m.def(
      "find_loops",
      [](const Problem& p, const SolveResult& r) {
        py::gil_scoped_release release;
        return find_loops(p, r.built);
      },
      py::arg("problem"), py::arg("result"),
      DOC(find_loops));
  m.SILLAGE_FN(problem_warnings, py::arg("problem"));
  m.SILLAGE_FN(peak_memory_estimate, py::arg("problem"), py::arg("slices"));
  m.SILLAGE_FN(check_memory, py::arg("problem"), py::arg("slices"), py::arg("what"));
  m.SILLAGE_FN(output_names, py::arg("problem"), py::arg("tube_files") = false);
  m.def("check_output_dir", py::overload_cast<const Problem&, const std::string&, bool>(&check_output_dir),
        py::arg("problem"), py::arg("dir"), py::arg("tube_files") = false,
        DOC(check_output_dir, Problem_string_bool));
  m.def("check_output_dir",
        py::overload_cast<const Problem&, const std::string&, const std::vector<std::string>&>(&check_output_dir),
        py::arg("problem"), py::arg("dir"), py::arg("names"), DOC(check_output_dir, Problem_string_vector_string));
  m.SILLAGE_FN(constraint_order, py::arg("problem"));
}

}  // namespace sillage::python
