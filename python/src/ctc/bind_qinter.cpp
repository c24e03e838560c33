// Outliers: the q-relaxed intersection (q_inter, CtcQInter), the GOMNE loop
// (gomne, GomneResult) and position fixes on a tube (TubeObservation;
// CtcEvalList: all true, CtcQEval: at most q wrong). gomne releases the GIL (Python subclasses of Ctc take it back in
// their overrides).
#include <pybind11/stl.h>

#include <climits>
#include <optional>
#include <vector>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/ctc/ctc_qinter.h"
#include "sillage/ctc/gomne.h"
#include "sillage/dynamics/ctc_eval_list.h"
#include "sillage/dynamics/ctc_qeval.h"
#include "sillage/dynamics/gomne_tube.h"

namespace sillage::python {

std::shared_ptr<const Ctc> hold_ctc(const py::handle& h);  // bind_ctc.cpp

namespace {

std::vector<CtcPtr> hold_ctcs(const py::iterable& list) {
  std::vector<CtcPtr> v;
  for (const auto& h : list) v.push_back(hold_ctc(h));
  return v;
}

}  // namespace

SILLAGE_BINDING(qinter, "cn", "ctc", "interval", "tube") {
  m.def("q_inter", py::overload_cast<const std::vector<Interval>&, int>(&q_inter), py::arg("xs"), py::arg("q"),
        R"doc(The hull of the points lying in at least m - q of the m intervals xs
(an empty interval contains no point). Exact; the whole line when q >= m.)doc");
  m.def("q_inter", py::overload_cast<const std::vector<IntervalVector>&, int>(&q_inter), py::arg("boxes"),
        py::arg("q"),
        R"doc(Component-wise q-relaxed intersection of boxes of the same size: an outer
approximation of the points lying in at least m - q of them. An empty box
counts as a constraint violated everywhere.)doc");

  py::class_<CtcQInter, Ctc, std::shared_ptr<CtcQInter>>(m, "CtcQInter", R"doc(
The q-relaxed intersection of m contractors: contract(x) keeps every point of x
that satisfies at least m - q of the m constraints ("at most q are wrong"):
x & q_inter([c.contract(copy of x) for c in ctcs], q). q = 0 is CtcInter; q >= m
leaves x unchanged. Not idempotent: wrap it in CtcFixPoint to iterate.)doc")
      .def(py::init([](const py::iterable& ctcs, int q) { return std::make_shared<CtcQInter>(hold_ctcs(ctcs), q); }),
           py::arg("ctcs"), py::arg("q"),
           "The q-relaxed intersection of the contractors ctcs (all on the same variables); 0 <= q (else Error).")
      .SILLAGE_DEF(CtcQInter, q);

  py::class_<GomneResult>(m, "GomneResult", DOC(GomneResult))
      .SILLAGE_READONLY_FIELDS(GomneResult, q, box, outliers, leaves)
      .SILLAGE_DEF(GomneResult, is_empty)
      .def("__repr__", [](const GomneResult& r) {
        return "<GomneResult q=" + std::to_string(r.q) + " box=" + r.box.str() + " outliers=" +
               py::repr(py::cast(r.outliers)).cast<std::string>() + ">";
      });

  m.def(
      "gomne",
      [](const py::iterable& ctcs, const IntervalVector& box, double eps, std::optional<int> q_max, double ratio) {
        const auto list = hold_ctcs(ctcs);
        GomneOptions o;
        o.eps = eps;
        o.q_max = q_max.value_or(INT_MAX);
        o.ratio = ratio;
        py::gil_scoped_release release;
        return gomne(list, box, o);
      },
      py::arg("ctcs"), py::arg("box"), py::arg("eps") = GomneOptions{}.eps, py::arg("q_max") = py::none(),
      py::arg("ratio") = GomneOptions{}.ratio,
      R"doc(GOMNE, the guaranteed outlier minimal number estimator. For q = 0, 1, ... the
set S_q of the points of box satisfying at least m - q of the m constraints is
contracted by CtcFixPoint(CtcQInter(ctcs, q), ratio) and, if eps is finite,
paved to precision eps; the first q not proven empty is returned.

Guarantees, if the truth lies in box: at least result.q measurements are
wrong. If moreover at most result.q are wrong, the truth lies in result.box
(and in one of result.leaves) and every index of result.outliers is a wrong
measurement (its contractor empties every leaf). eps > 0 (a finite eps needs a
bounded box), q_max >= 0 (default: the number of contractors).)doc");

  py::class_<TubeObservation>(m, "TubeObservation", R"doc(
A fix x(t) in z for some t in the interval t, z satisfying the contractor ctc
(None: no constraint). A range r to a beacon b: z = IntervalVector(n) and
ctc = CtcFunction(|z - b|, r). name: what the fix is, for the reports (e.g.
'ranges line 12').)doc")
      .def(py::init([](const Interval& t, const IntervalVector& z, const py::object& ctc, const std::string& name) {
             return TubeObservation{t, z, ctc.is_none() ? nullptr : hold_ctc(ctc), name};
           }),
           py::arg("t"), py::arg("z"), py::arg("ctc") = py::none(), py::arg("name") = "",
           "The fix x(t') in z for some t' in t, z satisfying ctc (None: no constraint), named name for the reports.")
      .SILLAGE_FIELDS(TubeObservation, t, z, name)
      .def("__repr__", [](const TubeObservation& o) {
        return "<TubeObservation t=" + o.t.str() + " z=" + o.z.str() + (o.name.empty() ? "" : " name='" + o.name + "'") +
               ">";
      });

  py::class_<CtcEvalList, NetworkCtc, std::shared_ptr<CtcEvalList>>(m, "CtcEvalList", R"doc(
Fixes on a tube, all true, as one network node: CtcEvalList(obs), then
cn.add(ctc, [x, v]) (x, v TubeVectors or Tubes of one size). Each run contracts
the fixes whose slices changed: CtcEval on (t_i, z_i, x, v), then the fix's
contractor on z_i, again while they shrink; t_i and z_i are held by the node.
The set of one CtcEval and one observation node per fix, without a node, a
domain and a name per fix. A fix found inconsistent empties x and the network's
emptiness names it (TubeObservation.name).)doc")
      .def(py::init<std::vector<TubeObservation>>(), py::arg("obs"), DOC(CtcEvalList, CtcEvalList))
      .SILLAGE_DEF(CtcEvalList, observations)
      .def("__repr__", [](const CtcEvalList& c) {
        return "CtcEvalList(" + std::to_string(c.observations().size()) + " observations)";
      });

  py::class_<CtcQEval, NetworkCtc, std::shared_ptr<CtcQEval>>(m, "CtcQEval", R"doc(
Position fixes on a tube, at most q of them wrong. contract(x, v, obs) contracts
a copy of the TubeVector x by each fix alone (CtcEval with the derivative v),
then intersects x, gate by gate and slice by slice, with the q-relaxed
intersection of the copies: a trajectory satisfying m - q fixes is kept. Returns
the indices of the fixes no trajectory of the input x satisfies (wrong, if at
most q are). The TDomain is never sampled. In a ContractorNetwork:
CtcQEval(q, obs) holds the fixes and cn.add(ctc, [x, v]) contracts x.)doc")
      .def(py::init<int>(), py::arg("q"), DOC(CtcQEval, CtcQEval, int))
      .def(py::init<int, std::vector<TubeObservation>>(), py::arg("q"), py::arg("obs"),
           DOC(CtcQEval, CtcQEval, int_vector_TubeObservation))
      .SILLAGE_DEFS(CtcQEval, q, observations)
      .def("__repr__",
           [](const CtcQEval& c) {
             return "CtcQEval(q=" + std::to_string(c.q()) +
                    (c.observations().empty() ? "" : ", " + std::to_string(c.observations().size()) + " observations") +
                    ")";
           })
      .SILLAGE_DEF(CtcQEval, contract, py::arg("x"), py::arg("v"), py::arg("obs"), nogil);

  py::class_<TubeGomneResult>(m, "TubeGomneResult", DOC(TubeGomneResult))
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .SILLAGE_READONLY_FIELDS(TubeGomneResult, q, x, outliers);
  m.def(
      "gomne_tube",
      [](const TubeVector& x, const TubeVector& v, const std::vector<TubeObservation>& obs, std::optional<int> q_max,
         int max_passes) {
        TubeGomneOptions o;
        o.q_max = q_max.value_or(INT_MAX);
        o.max_passes = max_passes;
        return gomne_tube(x, v, obs, o);
      },
      py::arg("x"), py::arg("v"), py::arg("obs"), py::arg("q_max") = py::none(),
      py::arg("max_passes") = TubeGomneOptions{}.max_passes,
      R"doc(GOMNE over the fixes of a tube: for q = 0, 1, ... contracts a copy of x by
CtcQEval(q) (passes repeated while it changes, at most max_passes) and stops at
the first q that does not empty it. If the true trajectory lies in x (with its
derivative in v), at least result.q fixes are wrong; if moreover at most
result.q are, the truth lies in result.x and result.outliers are wrong fixes.)doc");
}

}  // namespace sillage::python
