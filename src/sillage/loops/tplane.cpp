// TPlane: construction, detections (Alg. 6 and the components Ω_i) and the
// counts. The proofs are in tplane_proofs.cpp.
#include "sillage/loops/tplane.h"

#include <algorithm>
#include <iterator>
#include <string>

#include "sillage/error.h"
#include "sillage/loops/loop_function.h"
#include "sillage/loops/loop_sivia.h"

namespace sillage {

namespace {

IntervalVector square_of(const Interval& t, const char* where) {
  if (t.is_empty() || t.is_unbounded() || !(t.lb() < t.ub())) {
    throw Error(std::string(where) + ": the time domain must be bounded with t0 < tf, got " + t.str());
  }
  return {t, t};
}

// Strictly inside the square and strictly above its diagonal (see tplane.h).
bool is_complete(const std::vector<IntervalVector>& boxes, const IntervalVector& hull, const IntervalVector& square) {
  for (std::size_t i = 0; i < 2; ++i) {
    if (!(square[i].lb() < hull[i].lb() && hull[i].ub() < square[i].ub())) return false;
  }
  return std::all_of(boxes.begin(), boxes.end(), [](const IntervalVector& b) { return b[0].ub() < b[1].lb(); });
}

}  // namespace

TPlane::TPlane(const Interval& tdomain) : domain_(square_of(tdomain, "TPlane")) {}

TPlane::TPlane(const std::shared_ptr<TDomain>& td)
    : domain_(td ? square_of(td->t0_tf(), "TPlane") : throw Error("TPlane: null TDomain")) {}

void TPlane::check_tube(const TubeVector& x, const char* what, const char* where) const {
  if (x.size() != 2) {
    throw DimensionError(std::string(where) + ": the " + what + " tube has dimension " + std::to_string(x.size()) +
                         ", expected 2 (planar trajectories)");
  }
  if (!domain_[0].is_subset(x.tdomain()->t0_tf())) {
    throw Error(std::string(where) + ": the " + what + " tube is defined on " + x.tdomain()->t0_tf().str() +
                ", which does not cover the t-plane's time domain " + domain_[0].str());
  }
}

LoopFunction TPlane::checked_function(double eps, const TubeVector& v) const {
  const char* where = "TPlane::compute_detections(eps, v)";
  check_tube(v, "velocity", where);
  if (!(eps > 0)) throw Error(std::string(where) + ": eps must be > 0, got " + number_text(eps));
  return LoopFunction(v);
}

LoopFunction TPlane::checked_function(double eps, const TubeVector& p, const TubeVector& w) const {
  const char* where = "TPlane::compute_detections(eps, p, w)";
  check_tube(p, "position", where);
  check_tube(w, "velocity", where);
  if (!(eps > 0)) throw Error(std::string(where) + ": eps must be > 0, got " + number_text(eps));
  return LoopFunction(p, w);
}

void TPlane::compute_detections(double eps, const TubeVector& v, const Budget& budget) {
  detect(eps, checked_function(eps, v), budget, false);
}

void TPlane::compute_detections(double eps, const TubeVector& p, const TubeVector& w, const Budget& budget) {
  detect(eps, checked_function(eps, p, w), budget, false);
}

Summary TPlane::compute_detections_run(double eps, const TubeVector& v, const Budget& budget) {
  return detect(eps, checked_function(eps, v), budget, true);
}

Summary TPlane::compute_detections_run(double eps, const TubeVector& p, const TubeVector& w, const Budget& budget) {
  return detect(eps, checked_function(eps, p, w), budget, true);
}

Summary TPlane::detect(double eps, const LoopFunction& f, const Budget& budget, bool keep_partial) {
  SiviaResult run = detail::run_loop_paving(f, domain_, eps, budget, "TPlane::compute_detections");
  if (!keep_partial) throw_unfinished(run.summary);
  // The run form computes the components even once cancelled: without them
  // the paving so far would enclose the loops, the detections would not.
  const CancelToken cancel = keep_partial ? CancelToken{} : budget.cancel;
  std::vector<Loop> loops;
  for (Component& c : run.paving.components(cancel)) {
    Loop l;
    l.boxes_ = std::move(c.boxes);
    l.nb_inner_ = c.count(PavingTag::Inner);
    for (PavingTag tag : c.tags) l.inner_.push_back(tag == PavingTag::Inner);
    l.t_box_ = c.hull;
    l.complete_ = is_complete(l.boxes_, l.t_box_, domain_);
    loops.push_back(std::move(l));
  }
  // Chronological order; components come in pre-order, which breaks ties.
  std::stable_sort(loops.begin(), loops.end(), [](const Loop& a, const Loop& b) {
    if (a.t_box_[0].lb() != b.t_box_[0].lb()) return a.t_box_[0].lb() < b.t_box_[0].lb();
    return a.t_box_[1].lb() < b.t_box_[1].lb();
  });
  // Only now, so that an exception leaves the previous results whole.
  paving_ = std::move(run.paving);
  detections_ = std::move(loops);
  eps_ = eps;
  return run.summary;
}

std::size_t TPlane::nb_complete_detections() const {
  return static_cast<std::size_t>(
      std::count_if(detections_.begin(), detections_.end(), [](const Loop& l) { return l.complete(); }));
}

std::size_t TPlane::nb_proofs() const {
  return static_cast<std::size_t>(
      std::count_if(detections_.begin(), detections_.end(), [](const Loop& l) { return l.proven(); }));
}

std::size_t TPlane::nb_newton_proofs() const {
  return static_cast<std::size_t>(
      std::count_if(detections_.begin(), detections_.end(), [](const Loop& l) { return l.proven_newton(); }));
}

std::size_t Loop::nb_proven_pieces() const {
  return static_cast<std::size_t>(std::count_if(pieces_.begin(), pieces_.end(), [](const Loop& p) { return p.proven(); }));
}

std::vector<Loop> TPlane::proofs() const {
  std::vector<Loop> r;
  for (const Loop& l : detections_) {
    if (l.nb_proven_pieces() > 0) {
      std::copy_if(l.pieces_.begin(), l.pieces_.end(), std::back_inserter(r), [](const Loop& p) { return p.proven(); });
    } else if (l.proven()) {
      r.push_back(l);
    }
  }
  return r;
}

}  // namespace sillage
