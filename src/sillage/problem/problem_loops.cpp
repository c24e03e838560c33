#include "sillage/problem/problem_loops.h"

namespace sillage {

TPlane find_loops(const Problem& p, const BuiltProblem& b) {
  if (!p.output.loops) throw Error("find_loops: the problem asks no loops ([output] loops)");
  const LoopsSpec& l = *p.output.loops;
  const double eps = l.eps.value_or((p.time.tf - p.time.t0) / 2000);
  const TubeVector& v = *b.var(l.v).tubes;
  TPlane tp(b.td);
  if (l.p.empty()) {
    tp.compute_detections(eps, v);
    tp.compute_proofs(v);
  } else {
    const TubeVector& pos = *b.var(l.p).tubes;
    tp.compute_detections(eps, pos, v);
    tp.compute_proofs(pos, v);
  }
  return tp;
}

}  // namespace sillage
