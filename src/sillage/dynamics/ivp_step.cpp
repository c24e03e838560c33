// A validated Taylor step with Lohner's QR wrapping control (ivp_step.h).
#include "sillage/dynamics/ivp_step.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "sillage/interval/elementary.h"

namespace sillage::detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Σ_{k≤top} xs_k,i τ^k by Horner (an enclosure for every τ in [τ]).
Interval horner(const std::vector<Interval>& xs, std::size_t n, std::size_t i, int top, const Interval& tau) {
  Interval s = xs[static_cast<std::size_t>(top) * n + i];
  for (int k = top - 1; k >= 0; --k) s = s * tau + xs[static_cast<std::size_t>(k) * n + i];
  return s;
}

// ε-inflation of a candidate enclosure.
IntervalVector inflated(const IntervalVector& y) {
  IntervalVector b(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double w = y[i].diam();
    b[i] = y[i].inflate(0.1 * w + 1e-15 * y[i].mag() + 1e-300);
  }
  return b;
}

// Upper bound of the ∞-norm of an interval matrix (max row sum of magnitudes).
double norm_inf(const IntervalMatrix& m) {
  double best = 0.0;
  for (std::size_t i = 0; i < m.rows(); ++i) {
    Interval s(0.0);
    for (std::size_t j = 0; j < m.cols(); ++j) s += Interval(m(i, j).mag());
    best = std::max(best, s.ub());
  }
  return best;
}

// An orthogonal Q (point rows) from the columns of b taken longest first
// (length × weight), by modified Gram–Schmidt; a vanishing column is
// replaced by a unit vector so that Q stays invertible.
Matrix orthogonal_basis(const Matrix& b, const Vector& weight) {
  const std::size_t n = b.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto col_len = [&](std::size_t j) {
    double s = 0.0;
    for (std::size_t i = 0; i < n; ++i) s += b[i][j] * b[i][j];
    return std::sqrt(s) * weight[j];
  };
  std::vector<double> len(n);
  for (std::size_t j = 0; j < n; ++j) len[j] = col_len(j);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t c) { return len[a] > len[c]; });
  std::vector<Vector> q;
  auto orthonormalise = [&](Vector v) {
    for (const Vector& e : q) {
      double d = 0.0;
      for (std::size_t i = 0; i < n; ++i) d += e[i] * v[i];
      for (std::size_t i = 0; i < n; ++i) v[i] -= d * e[i];
    }
    double s = 0.0;
    for (double x : v) s += x * x;
    s = std::sqrt(s);
    if (!(s > 1e-150) || !std::isfinite(s)) return false;
    for (double& x : v) x /= s;
    q.push_back(v);
    return true;
  };
  for (std::size_t j : order) {
    Vector v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = b[i][j];
    if (orthonormalise(v)) continue;
    for (std::size_t e = 0; e < n; ++e) {
      Vector u(n, 0.0);
      u[e] = 1.0;
      if (orthonormalise(u)) break;
    }
  }
  Matrix rows(n, Vector(n, 0.0));
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) rows[i][j] = q[j][i];
  }
  return rows;
}

// An enclosure of Q⁻¹: C = Qᵀ, E = I - CQ; if |E| ≤ e < 1/2,
// Q⁻¹ = (I - E)⁻¹C ∈ C ± e/(1-e)·|C|∞ entrywise. False if E is too large.
bool inverse_enclosure(const Matrix& q, IntervalMatrix& inv) {
  const std::size_t n = q.size();
  Matrix c(n, Vector(n));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) c[i][j] = q[j][i];
  }
  const IntervalMatrix C = IntervalMatrix::from_point(c);
  const IntervalMatrix E = IntervalMatrix::identity(n) - C * IntervalMatrix::from_point(q);
  const double e = norm_inf(E);
  if (!(e < 0.5)) return false;
  const double eta = (Interval(e) / (Interval(1.0) - Interval(e)) * Interval(norm_inf(C))).ub();
  inv = C.inflate(eta);
  return true;
}

// [-|x|, |x|]: x times a symbol w in [-1, 1].
Interval symmetric(const Interval& x) { return Interval(-x.mag(), x.mag()); }

// The point part of an interval generator; the rest, times w ∈ [-1, 1],
// goes to the box `extra`.
Vector split_generator(const IntervalVector& g, IntervalVector& extra) {
  Vector mid = g.mid();
  for (std::size_t i = 0; i < g.size(); ++i) extra[i] += symmetric(g[i] - Interval(mid[i]));
  return mid;
}

// Past this many generators the cheapest to box (Girard: ‖g‖₁ − ‖g‖∞,
// zero for a generator along an axis) become a box: their correlation with
// the rest is lost, not their bound.
constexpr std::size_t kMaxGenerators = 256;

void reduce_generators(std::vector<Vector>& G, IntervalVector& extra) {
  if (G.size() <= kMaxGenerators) return;
  std::vector<std::pair<double, std::size_t>> cost;
  for (std::size_t j = 0; j < G.size(); ++j) {
    double l1 = 0.0, linf = 0.0;
    for (double x : G[j]) l1 += std::abs(x), linf = std::max(linf, std::abs(x));
    cost.emplace_back(l1 - linf, j);
  }
  std::sort(cost.begin(), cost.end());
  const std::size_t drop = G.size() - kMaxGenerators / 2;
  std::vector<bool> gone(G.size(), false);
  for (std::size_t k = 0; k < drop; ++k) {
    const Vector& g = G[cost[k].second];
    for (std::size_t i = 0; i < g.size(); ++i) extra[i] += Interval(-std::abs(g[i]), std::abs(g[i]));
    gone[cost[k].second] = true;
  }
  std::vector<Vector> kept;
  for (std::size_t j = 0; j < G.size(); ++j) {
    if (!gone[j]) kept.push_back(std::move(G[j]));
  }
  G = std::move(kept);
}

// A symmetric box as generators along the axes (the zero ones skipped).
void box_to_generators(const IntervalVector& box, std::vector<Vector>& G) {
  for (std::size_t i = 0; i < box.size(); ++i) {
    const double m = box[i].mag();
    if (m == 0.0) continue;
    Vector g(box.size(), 0.0);
    g[i] = m;
    G.push_back(std::move(g));
  }
}

}  // namespace

IntervalVector LohnerSet::hull() const {
  IntervalVector b = IntervalVector::from_point(c) + A * r;
  for (const Vector& g : G) {
    for (std::size_t i = 0; i < g.size(); ++i) b[i] += Interval(-std::abs(g[i]), std::abs(g[i]));
  }
  return b;
}

LohnerSet LohnerSet::from_box(const IntervalVector& x, bool zonotope) {
  LohnerSet s;
  s.c = x.mid();
  s.A = IntervalMatrix::identity(x.size());
  s.r = x - IntervalVector::from_point(s.c);
  s.box = x;
  s.zonotope = zonotope;
  if (zonotope) {
    box_to_generators(s.r, s.G);
    s.r = IntervalVector(x.size(), Interval(0.0));
  }
  return s;
}

double IvpStepper::suggest(const LohnerSet& set, const IntervalVector& u, double sign, double tol) const {
  const std::size_t n = ode_.nb_states();
  std::vector<Interval> xs(n);
  for (std::size_t i = 0; i < n; ++i) xs[i] = Interval(set.c[i]);
  const IntervalVector u0 = IntervalVector::from_point(u.mid());
  if (!ode_.coefficients(xs, u0.components().data(), order_ + 1, sign)) return 0.0;
  double scale = 1.0;
  for (double ci : set.c) scale = std::max(scale, std::abs(ci));
  double h = kInf;
  for (int k = order_; k <= order_ + 1; ++k) {
    double m = 0.0;
    for (std::size_t i = 0; i < n; ++i) m = std::max(m, xs[static_cast<std::size_t>(k) * n + i].mag());
    if (m > 0.0) h = std::min(h, std::pow(tol * scale / m, 1.0 / k));
  }
  return h;
}

bool IvpStepper::a_priori(const IntervalVector& X, const std::vector<Interval>& xs, const Interval& h,
                          const IntervalVector& u, double sign, bool inputs, IntervalVector& B,
                          IntervalVector& last) const {
  const std::size_t n = ode_.nb_states();
  const int p = order_;
  const Interval T(0.0, h.ub());
  IntervalVector base(n);
  for (std::size_t i = 0; i < n; ++i) base[i] = inputs ? X[i] : horner(xs, n, i, p, T);
  const Interval Tlast = inputs ? T : pow(T, p + 1);
  const int q = inputs ? 1 : p + 1;
  IntervalVector guess = inflated(base);
  std::vector<Interval> cs;
  for (int attempt = 0; attempt < 12; ++attempt) {
    cs.assign(guess.components().begin(), guess.components().end());
    if (!ode_.coefficients(cs, u.components().data(), q, sign)) return false;
    IntervalVector y(n);
    for (std::size_t i = 0; i < n; ++i) y[i] = base[i] + cs[static_cast<std::size_t>(q) * n + i] * Tlast;
    if (y.is_empty() || y.is_unbounded()) return false;
    if (y.is_interior_subset(guess)) {
      B = y;
      last = IntervalVector(n);
      for (std::size_t i = 0; i < n; ++i) last[i] = cs[static_cast<std::size_t>(q) * n + i];
      return true;
    }
    // Inflate the new candidate, not the hull with the old one: the hull
    // keeps every overshoot and, when a component's slope grows with the
    // others' widths, never settles.
    guess = inflated(y);
  }
  return false;
}

IntervalVector IvpStepper::input_deviation(const IntervalMatrix& J, const Interval& h, const IntervalVector& u,
                                           const IntervalVector& u0, double sign) const {
  const std::size_t n = ode_.nb_states(), m = ode_.nb_inputs();
  // e = x - y: |e|' ≤ P|e| + δ componentwise (Kamke's comparison; P is
  // Metzler: P_ii = max(s·J_ii, 0)⁺, P_ij = |J_ij|), δ_i ≥ |J_u (u - u0)|_i,
  // so |e(h)| ≤ ∫_0^h e^{P(h-τ)} δ dτ ≤ h·e^{Ph}·δ.
  const Interval H(h.ub());
  IntervalMatrix P(n, n);
  IntervalVector delta(n);
  for (std::size_t i = 0; i < n; ++i) {
    Interval d(0.0);
    for (std::size_t j = 0; j < m; ++j) d += J(i, n + j) * (u[j] - u0[j]);
    delta[i] = Interval(d.mag());
    for (std::size_t j = 0; j < n; ++j) {
      const double pij = i == j ? std::max((Interval(sign) * J(i, i)).ub(), 0.0) : J(i, j).mag();
      P(i, j) = Interval(pij) * H;
    }
  }
  // e^{Ph}δ = Σ_k (Ph)^k δ / k!, every term ≥ 0. Past K, with t_K the K-th
  // term, Σ_{j≥1} (Ph)^j t_K K!/(K+j)! ≤ |t_K|∞ Σ_j (|Ph|∞/(K+1))^j: a
  // geometric tail, zero when P is nilpotent (t_K = 0), as in chains of
  // integrators. K grows until the ratio is below 1/2.
  const double np = norm_inf(P);
  if (!std::isfinite(np)) return IntervalVector(n);
  IntervalVector term = delta, sum = delta;
  int k = 0;
  Interval ratio;
  do {
    ++k;
    term = P * term;
    for (std::size_t i = 0; i < n; ++i) term[i] = term[i] / Interval(static_cast<double>(k));
    sum += term;
    ratio = Interval(np) / Interval(static_cast<double>(k + 1));
  } while (k < 12 || (ratio.ub() >= 0.5 && k < 400));
  if (!(ratio.ub() < 1.0)) return IntervalVector(n);
  double tmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) tmax = std::max(tmax, term[i].mag());
  const Interval tail = Interval(tmax) * ratio / (Interval(1.0) - ratio);
  IntervalVector out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double dev = (H * (sum[i] + tail)).ub();
    out[i] = std::isfinite(dev) ? Interval(-dev, dev) : Interval();
  }
  return out;
}

bool IvpStepper::input_share(const IntervalVector& B, const Vector& c, const Interval& h, const IntervalVector& u,
                             const IntervalVector& u0, double sign, std::vector<Vector>& G,
                             IntervalVector& extra, IntervalVector& box) const {
  const std::size_t n = ode_.nb_states(), m = ode_.nb_inputs();
  IntervalVector bu(n + m), cu(n + m);
  bu.put(0, B);
  bu.put(n, u);
  cu.put(0, IntervalVector::from_point(c));
  cu.put(n, u0);
  const IntervalMatrix J = ode_.function().jacobian(bu);
  const IntervalMatrix Jc = ode_.function().jacobian(cu);
  if (J.is_unbounded() || Jc.is_unbounded()) return false;
  // e = x - y (x with u(·), y with u0, same start):
  //   e(h) = ∫ J_x(ξ) e + ∫ J_u(y, η)(u - u0)
  //        ∈ s·h·J_u^c·ū + s·h·(J_u - J_u^c)·([u] - u0) + s·h·J_x·[E],
  // ū = the mean of u - u0 over the step, any point of [u] - u0 (a new
  // symbol per input: a generator), [E] ⊇ e over the step.
  const IntervalVector E = input_deviation(J, h, u, u0, sign);
  if (E.is_unbounded()) return false;
  const Interval sh = Interval(sign) * h;
  IntervalVector rest(n, Interval(0.0));
  for (std::size_t j = 0; j < m; ++j) {
    const Interval du = u[j] - u0[j];
    IntervalVector g(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Interval jc(Jc(i, n + j).mid());
      g[i] = sh * jc * Interval(du.mag());
      rest[i] += sh * (J(i, n + j) - jc) * du;
    }
    G.push_back(split_generator(g, rest));
    for (std::size_t i = 0; i < n; ++i) box[i] += Interval(-std::abs(G.back()[i]), std::abs(G.back()[i]));
  }
  for (std::size_t i = 0; i < n; ++i) {
    Interval s(0.0);
    for (std::size_t l = 0; l < n; ++l) s += J(i, l) * E[l];
    rest[i] += sh * s;
  }
  for (std::size_t i = 0; i < n; ++i) rest[i] = symmetric(rest[i]);
  box += rest;
  extra += rest;
  return true;
}

bool IvpStepper::step(LohnerSet& set, const Interval& h, const IntervalVector& u, double sign,
                      IntervalVector& range) const {
  const std::size_t n = ode_.nb_states();
  const int p = order_;
  const IntervalVector& X = set.box;
  const IntervalVector u0 = IntervalVector::from_point(u.mid());
  const bool inputs = ode_.nb_inputs() > 0 && !u.is_degenerate();
  // Coefficients and their derivatives over the box, input at u0; the
  // mean-value theorem needs the segments from c, hence the hull with c.
  const IntervalVector Xc = hull(X, IntervalVector::from_point(set.c));
  std::vector<Interval> xs(Xc.components().begin(), Xc.components().end()), vs;
  if (!ode_.coefficients(xs, vs, u0.components().data(), p, sign)) return false;
  IntervalVector B, last;
  if (!a_priori(Xc, xs, h, inputs ? u : u0, sign, inputs, B, last)) return false;
  if (inputs) {
    std::vector<Interval> bs(B.components().begin(), B.components().end());
    if (!ode_.coefficients(bs, u0.components().data(), p + 1, sign)) return false;
    for (std::size_t i = 0; i < n; ++i) last[i] = bs[static_cast<std::size_t>(p + 1) * n + i];
  }
  // The polynomial at the centre, plus the remainder: the flow with u0.
  std::vector<Interval> cs(n);
  for (std::size_t i = 0; i < n; ++i) cs[i] = Interval(set.c[i]);
  if (!ode_.coefficients(cs, u0.components().data(), p, sign)) return false;
  const Interval hp1 = pow(h, p + 1);
  IntervalVector z(n);
  for (std::size_t i = 0; i < n; ++i) z[i] = horner(cs, n, i, p, h) + last[i] * hp1;
  // M = Σ_k V_k([X]) h^k, entry by entry.
  IntervalMatrix M(n, n);
  for (std::size_t e = 0; e < n * n; ++e) {
    Interval s = vs[static_cast<std::size_t>(p) * n * n + e];
    for (int k = p - 1; k >= 0; --k) s = s * h + vs[static_cast<std::size_t>(k) * n * n + e];
    M(e / n, e % n) = s;
  }
  // The generators follow the linear part: M·g = mid(M·g) + a residual box.
  IntervalVector extra(n, Interval(0.0));
  std::vector<Vector> G;
  G.reserve(set.G.size() + ode_.nb_inputs());
  for (const Vector& g : set.G) G.push_back(split_generator(M * IntervalVector::from_point(g), extra));
  // The inputs' share: new generators and their remainder (input_share).
  IntervalVector input_box(n, Interval(0.0));
  if (inputs && !input_share(B, set.c, h, u, u0, sign, G, extra, input_box)) return false;
  reduce_generators(G, extra);
  if (set.zonotope) {
    box_to_generators(extra, G);
    extra = IntervalVector(n, Interval(0.0));
  }
  const IntervalMatrix MA = M * set.A;
  Vector weight(n);
  for (std::size_t j = 0; j < n; ++j) weight[j] = set.r[j].diam();
  Matrix Q = orthogonal_basis(MA.mid(), weight);
  IntervalMatrix Qinv;
  if (!inverse_enclosure(Q, Qinv)) {
    Q = IntervalMatrix::identity(n).mid();
    Qinv = IntervalMatrix::identity(n);
  }
  const IntervalVector zt = z + extra;
  LohnerSet next;
  next.c = zt.mid();
  next.A = IntervalMatrix::from_point(Q);
  next.r = (Qinv * MA) * set.r + Qinv * (zt - IntervalVector::from_point(next.c));
  next.G = std::move(G);
  next.zonotope = set.zonotope;
  next.box = next.hull();
  // The mean-value form (M holds over Xc ⊇ the segments), plus the inputs' share.
  next.box &= z + input_box + M * (X - IntervalVector::from_point(set.c));
  if (next.box.is_empty() || next.box.is_unbounded() || next.r.is_unbounded()) return false;
  set = std::move(next);
  range = B;
  return true;
}

}  // namespace sillage::detail
