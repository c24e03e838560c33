// A validated Taylor step with Lohner's QR wrapping control (ivp_step.h).
#include "sillage/dynamics/ivp_step.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "sillage/dynamics/ivp_generators.h"
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

// Past this many generators they are reduced (ivp_generators.h).
constexpr std::size_t kMaxGenerators = 256;

// The secant matrix of the step's polynomial is the mean of its Jacobian
// over K boxes c + (l/K)([X] - c), l = 1..K (see step()); those boxes run
// to a low order, the higher orders of the Jacobian over [X] enclose theirs.
constexpr int kSecantBoxes = 8;
constexpr int kSecantOrder = 2;

// M = Σ_k V_k h^k from the variational coefficients v (orders 0..p), entry
// by entry; orders ≤ q taken from `low` when given.
IntervalMatrix jacobian_sum(const std::vector<Interval>& v, const std::vector<Interval>* low, int q, std::size_t n,
                            int p, const Interval& h) {
  IntervalMatrix M(n, n);
  for (std::size_t e = 0; e < n * n; ++e) {
    Interval s = v[static_cast<std::size_t>(p) * n * n + e];
    for (int k = p - 1; k >= 0; --k) {
      const std::vector<Interval>& src = low && k <= q ? *low : v;
      s = s * h + src[static_cast<std::size_t>(k) * n * n + e];
    }
    M(e / n, e % n) = s;
  }
  return M;
}

// States that no derivative depends on (their column of every V_k, k ≥ 1, is 0).
std::vector<bool> passive_states(const std::vector<Interval>& v, std::size_t n, int p) {
  std::vector<bool> passive(n, true);
  for (int k = 1; k <= p; ++k) {
    for (std::size_t e = 0; e < n * n; ++e) {
      if (v[static_cast<std::size_t>(k) * n * n + e] != Interval(0.0)) passive[e % n] = false;
    }
  }
  return passive;
}

// The set is wide enough for the secant matrix to pay for its cost.
bool wide(const IntervalVector& X, const Vector& c) {
  for (std::size_t i = 0; i < X.size(); ++i) {
    if (X[i].rad() > 1e-9 * std::max(1.0, std::abs(c[i]))) return true;
  }
  return false;
}

// The secant matrix ∫_0^1 DP(c + s(x - c)) ds of the step's polynomial P,
// for every x in [X] (c ∈ [X]): over s ∈ [(l-1)/K, l/K] the Jacobian lies in
// its enclosure over the box c + (l/K)([X] - c), whose width shrinks with l;
// the mean of the K enclosures halves the mean-value form's second-order
// overestimation as K grows ((K + 1) / 2K of it). M holds the Jacobian over
// [X] (l = K) and receives the mean. False if f is not smooth there.
bool secant_matrix(const TaylorOde& ode, const IntervalVector& X, const Vector& c, const std::vector<Interval>& vs,
                   const IntervalVector& u0, const Interval& h, int p, double sign, IntervalMatrix& M) {
  const std::size_t n = X.size();
  const Interval share = Interval(1.0) / Interval(static_cast<double>(kSecantBoxes));
  const IntervalVector cc = IntervalVector::from_point(c);
  const int q = std::min(p, kSecantOrder);
  IntervalMatrix sum = M * share;
  for (int l = 1; l < kSecantBoxes; ++l) {
    const Interval s = Interval(static_cast<double>(l)) * share;
    const IntervalVector Xl = cc + (X - cc) * s;
    std::vector<Interval> xl(Xl.components().begin(), Xl.components().end()), vl;
    if (!ode.coefficients(xl, vl, u0.components().data(), q, sign)) return false;
    sum = sum + jacobian_sum(vs, &vl, q, n, p, h) * share;
  }
  M = sum;
  return true;
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

bool IvpStepper::centre_coefficients(const Vector& c, const IntervalVector& u0, double sign,
                                     std::vector<Interval>& cs) const {
  const std::size_t n = ode_.nb_states();
  if (cache_sign_ != sign || cache_c_ != c || !(cache_u0_ == u0)) {
    cache_.assign(n, Interval());
    for (std::size_t i = 0; i < n; ++i) cache_[i] = Interval(c[i]);
    if (!ode_.coefficients(cache_, u0.components().data(), order_ + 1, sign)) {
      cache_sign_ = 0.0;
      return false;
    }
    cache_c_ = c;
    cache_u0_ = u0;
    cache_sign_ = sign;
  }
  cs = cache_;
  return true;
}

double IvpStepper::suggest(const LohnerSet& set, const IntervalVector& u, double sign, double tol) const {
  const std::size_t n = ode_.nb_states();
  std::vector<Interval> xs;
  if (!centre_coefficients(set.c, IntervalVector::from_point(u.mid()), sign, xs)) return 0.0;
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
  //        ∈ s·h·J_u^c·ū + s·h·(J_u - J_u^c)·([u] - u0) + (s·h/2)·J_x·[E],
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
  // |e(τ)| ≤ τ·e^{Pτ}δ ≤ (τ/h)·[E] on the step, so ∫_0^h J_x e ∈ (h/2)·J_x·[E].
  const Interval half_sh = sh / Interval(2.0);
  for (std::size_t i = 0; i < n; ++i) {
    Interval s(0.0);
    for (std::size_t l = 0; l < n; ++l) s += J(i, l) * E[l];
    rest[i] += half_sh * s;
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
  std::vector<Interval> cs;
  if (!centre_coefficients(set.c, u0, sign, cs)) return false;
  const Interval hp1 = pow(h, p + 1);
  IntervalVector z(n);
  for (std::size_t i = 0; i < n; ++i) z[i] = horner(cs, n, i, p, h) + last[i] * hp1;
  // M encloses the secant matrix: P(x) - P(c) = M·(x - c) for every x in
  // [X], P the step's polynomial (secant_matrix).
  IntervalMatrix M = jacobian_sum(vs, nullptr, 0, n, p, h);
  if (wide(Xc, set.c) && !secant_matrix(ode_, Xc, set.c, vs, u0, h, p, sign, M)) return false;
  // The generators follow the linear part: M·g = mid(M·g) + a residual box.
  IntervalVector extra(n, Interval(0.0));
  std::vector<Vector> G;
  G.reserve(set.G.size() + ode_.nb_inputs());
  for (const Vector& g : set.G) G.push_back(split_generator(M * IntervalVector::from_point(g), extra));
  // The inputs' share: new generators and their remainder (input_share).
  IntervalVector input_box(n, Interval(0.0));
  if (inputs && !input_share(B, set.c, h, u, u0, sign, G, extra, input_box)) return false;
  reduce_generators(G, extra, passive_states(vs, n, p), kMaxGenerators);
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
