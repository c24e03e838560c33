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

}  // namespace

LohnerSet LohnerSet::from_box(const IntervalVector& x) {
  LohnerSet s;
  s.c = x.mid();
  s.A = IntervalMatrix::identity(x.size());
  s.r = x - IntervalVector::from_point(s.c);
  s.box = x;
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
  for (int attempt = 0; attempt < 10; ++attempt) {
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
    guess = inflated(hull(y, guess));
  }
  return false;
}

IntervalVector IvpStepper::input_deviation(const IntervalVector& B, const Interval& h, const IntervalVector& u,
                                           const IntervalVector& u0, double sign) const {
  const std::size_t n = ode_.nb_states(), m = ode_.nb_inputs();
  IntervalVector bu(n + m);
  bu.put(0, B);
  bu.put(n, u);
  const IntervalMatrix J = ode_.function().jacobian(bu);
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
  // e^{Ph}δ ≤ Σ_{k≤K} (Ph)^k δ / k! + |Ph|^{K+1}/(K+1)! e^{|Ph|} |δ| (norms ∞).
  constexpr int K = 12;
  IntervalVector term = delta, sum = delta;
  for (int k = 1; k <= K; ++k) {
    term = P * term;
    for (std::size_t i = 0; i < n; ++i) term[i] = term[i] / Interval(static_cast<double>(k));
    sum += term;
  }
  const Interval np(norm_inf(P));
  double dmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) dmax = std::max(dmax, delta[i].ub());
  Interval tail = exp(np) * Interval(dmax);
  for (int k = 1; k <= K + 1; ++k) tail = tail * np / Interval(static_cast<double>(k));
  IntervalVector out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double dev = (H * (sum[i] + tail)).ub();
    out[i] = std::isfinite(dev) ? Interval(-dev, dev) : Interval();
  }
  return out;
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
  // The polynomial at the centre, plus the remainder (and the inputs' share).
  std::vector<Interval> cs(n);
  for (std::size_t i = 0; i < n; ++i) cs[i] = Interval(set.c[i]);
  if (!ode_.coefficients(cs, u0.components().data(), p, sign)) return false;
  const Interval hp1 = pow(h, p + 1);
  IntervalVector z(n);
  for (std::size_t i = 0; i < n; ++i) z[i] = horner(cs, n, i, p, h) + last[i] * hp1;
  if (inputs) z += input_deviation(B, h, u, u0, sign);
  // M = Σ_k V_k([X]) h^k, entry by entry.
  IntervalMatrix M(n, n);
  for (std::size_t e = 0; e < n * n; ++e) {
    Interval s = vs[static_cast<std::size_t>(p) * n * n + e];
    for (int k = p - 1; k >= 0; --k) s = s * h + vs[static_cast<std::size_t>(k) * n * n + e];
    M(e / n, e % n) = s;
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
  LohnerSet next;
  next.c = z.mid();
  next.A = IntervalMatrix::from_point(Q);
  next.r = (Qinv * MA) * set.r + Qinv * (z - IntervalVector::from_point(next.c));
  next.box = IntervalVector::from_point(next.c) + next.A * next.r;
  next.box &= z + M * (X - IntervalVector::from_point(set.c));  // M holds over Xc ⊇ the segments
  if (next.box.is_empty() || next.box.is_unbounded() || next.r.is_unbounded()) return false;
  set = std::move(next);
  range = B;
  return true;
}

}  // namespace sillage::detail
