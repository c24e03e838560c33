#include "sillage/slam/ctc_p_implies_z.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <optional>

#include "sillage/ctc/shrink.h"
#include "sillage/error.h"
#include "sillage/loops/tplane.h"
#include "sillage/paving/sivia.h"
#include "sillage/slam/ctc_omega.h"
#include "sillage/slam/scalar_loops.h"

namespace sillage {

namespace detail {

double width_sum(const IntervalVector& x) {
  if (x.is_empty()) return 0.0;
  double s = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) s += x[i].diam();
  return s;
}

double contraction(const IntervalVector& before, const IntervalVector& after) {
  const double b = width_sum(before), a = width_sum(after);
  if (!(b > 0.0) || std::isinf(b)) return 0.0;
  return 1.0 - a / b;
}

}  // namespace detail

namespace {

void check(const TubeVector& p, const TubeVector& w, const TubeVector& z, const char* where) {
  if (p.size() != 2 && p.size() != 1) {
    throw DimensionError(std::string(where) + ": p has " + std::to_string(p.size()) +
                         " components; the loop tests need a 2-D p (degree) or a 1-D p (sign change)");
  }
  if (w.size() != p.size() || w.tdomain() != p.tdomain()) {
    throw DimensionError(std::string(where) + ": w must have p's dimension (" + std::to_string(p.size()) +
                         ") on p's TDomain (it has " + std::to_string(w.size()) + " components)");
  }
  if (z.size() == 0) throw DimensionError(std::string(where) + ": z has no component");
  if (!p.tdomain()->t0_tf().is_subset(z.tdomain()->t0_tf())) {
    throw Error(std::string(where) + ": z's time domain " + z.tdomain()->t0_tf().str() + " does not cover p's " +
                p.tdomain()->t0_tf().str());
  }
}

// Ω ∩ 𝕋_z: the outer kernel SIVIA of (7.17) on each box of Ω.
std::vector<IntervalVector> intersect_tz(const std::vector<IntervalVector>& omega, const TubeVector& z, double eps,
                                         const CancelToken& cancel) {
  const Interval dom = z.tdomain()->t0_tf();
  const KernelBounds fz = [&z, &dom](const IntervalVector& t) {
    const IntervalVector d = z(t[0] & dom) - z(t[1] & dom);
    return std::make_pair(d, d);  // f⁻ and f⁺ both range in [f]: sound for the outer set
  };
  SiviaOptions o;
  o.parallel = false;  // components already run in parallel
  o.budget.cancel = cancel;
  std::vector<IntervalVector> out;
  for (const IntervalVector& b : omega) {
    const Paving pv = kernel_sivia(b, fz, eps, o);
    for (IntervalVector& x : pv.outer()) out.push_back(std::move(x));
  }
  return out;
}

IntervalVector hull_of(const std::vector<IntervalVector>& boxes) {
  IntervalVector h(2, Interval::empty());
  for (const auto& b : boxes) h |= b;
  return h;
}

// Planar p: the t-plane (7.28) and the degree test 𝒯 on each Ω_i as detected.
std::vector<std::vector<IntervalVector>> planar_proofs(double eps, const TubeVector& p, const TubeVector& w,
                                                       SlamRow& row, const CancelToken& cancel) {
  TPlane tp(p.tdomain());
  Budget budget;  // the caller's token alone
  budget.cancel = cancel;
  tp.compute_detections(eps, p, w, budget);
  ProofOptions po;
  po.newton = false;  // the degree test 𝒯 is the existence test of Alg. 13
  po.count = false;
  po.budget.cancel = cancel;
  tp.compute_proofs(p, w, po);
  row.nb_detections = tp.nb_complete_detections();
  row.nb_proofs = tp.nb_proofs();
  std::vector<std::vector<IntervalVector>> out;
  for (const Loop& l : tp.detections()) {
    if (l.proven()) out.push_back(l.boxes());
  }
  return out;
}

// Scalar p: the pieces of scalar_loops.h and their sign-change test.
std::vector<std::vector<IntervalVector>> scalar_proofs(double eps, const TubeVector& p, const TubeVector& w,
                                                       SlamRow& row, const CancelToken& cancel) {
  std::vector<std::vector<IntervalVector>> out;
  for (ScalarLoop& l : scalar_loops(eps, p, w, cancel)) {
    ++row.nb_detections;
    if (l.proven) out.push_back(std::move(l.boxes));
  }
  row.nb_proofs = out.size();
  return out;
}

}  // namespace

CtcPImpliesZ::CtcPImpliesZ(double eps, bool fast) : eps_(eps), fast_(fast) {
  if (!(eps > 0.0) || std::isinf(eps)) {
    throw Error("CtcPImpliesZ(eps, fast): eps must be positive and finite, not " + number_text(eps));
  }
}

void CtcPImpliesZ::set_ratio(double ratio) {
  check_ratio(ratio, "CtcPImpliesZ::set_ratio");
  ratio_ = ratio;
}

void CtcPImpliesZ::set_max_iterations(std::size_t n) {
  if (n == 0) throw Error("CtcPImpliesZ::set_max_iterations: at least one iteration");
  max_iterations_ = n;
}

bool CtcPImpliesZ::iterate(TubeVector& p, const TubeVector& w, const TubeVector& z, SlamRow& row,
                           const CancelToken& cancel) const {
  check(p, w, z, "CtcPImpliesZ::iterate(p, w, z)");
  row.fast = fast_;
  if (p.is_empty()) return false;
  // 1-2. Detections and their existence tests: the proven t-sets.
  const std::vector<std::vector<IntervalVector>> proven =
      p.size() == 2 ? planar_proofs(eps_, p, w, row, cancel) : scalar_proofs(eps_, p, w, row, cancel);
  // 3-4. Per proven component, against the tube as it is now.
  const TubeVector ref = p;
  const CtcOmega omega;
  std::vector<OmegaHull> hulls(proven.size());
  tbb::enumerable_thread_specific<std::optional<TubeVector>> works;
  tbb::parallel_for(std::size_t{0}, proven.size(), [&](std::size_t i) {
    std::vector<IntervalVector> boxes = intersect_tz(proven[i], z, eps_, cancel);
    if (boxes.empty()) {
      hulls[i].empty = true;  // the proven loop is nowhere in 𝕋_z
      return;
    }
    if (fast_) boxes = {hull_of(boxes)};
    auto& work = works.local();
    if (!work) work.emplace(ref);
    hulls[i] = omega.hull(boxes, ref, w, *work, cancel);
  });
  std::size_t nb_shrunk = 0;
  for (const OmegaHull& h : hulls) {
    row.nb_atoms_touched += h.nb_touched;
    if (!h.apply_to(p, &nb_shrunk, ratio_)) return true;  // empty: inconsistent
  }
  return nb_shrunk > 0;
}

std::vector<SlamRow> CtcPImpliesZ::contract(TubeVector& p, const TubeVector& w, const TubeVector& z,
                                            const CancelToken& cancel) const {
  check(p, w, z, "CtcPImpliesZ::contract(p, w, z)");
  using clock = std::chrono::steady_clock;
  const std::size_t n = p.nb_slices();
  const IntervalVector tf0 = p.gate(n), t00 = p.gate(0);
  std::vector<SlamRow> rows;
  double cumulated = 0.0;
  for (std::size_t it = 1; it <= max_iterations_; ++it) {
    SlamRow row;
    row.iteration = it;
    const auto start = clock::now();
    const bool shrunk = iterate(p, w, z, row, cancel);
    row.seconds = std::chrono::duration<double>(clock::now() - start).count();
    cumulated += row.seconds;
    row.cumulated_seconds = cumulated;
    row.contraction_tf = detail::contraction(tf0, p.gate(n));
    row.contraction_t0 = detail::contraction(t00, p.gate(0));
    rows.push_back(row);
    if (!shrunk || p.is_empty()) break;
  }
  return rows;
}

std::vector<SlamRow> CtcPImpliesZ::contract(TubeVector& p, const TubeVector& w, const Tube& z,
                                            const CancelToken& cancel) const {
  return contract(p, w, TubeVector(std::vector<Tube>{z}), cancel);
}

}  // namespace sillage
