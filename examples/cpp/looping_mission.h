#pragma once
// A synthetic looping mission (thesis 6.4: an AUV survey whose path crosses
// itself), shared by examples/cpp/loops_survey.cpp and bench/bench_loops.cpp.
//
// The vehicle starts at the origin heading east and surveys a square in
// blocks of lawn-mower legs: block 0 along x, block 1 along y (the
// cross-legs: every leg of one block crosses every leg of the other), then
// blocks at 45°, 135°, 22.5°, ... for longer missions. Legs run `overshoot`
// metres past the square, are joined by half-turns of radius spacing/2, and
// blocks by the shortest Dubins path (arc, line, arc) into the nearest
// corner of the next block. Along legs the speed surges sinusoidally and the
// track wobbles sideways (a heading oscillation of a few degrees); both
// vanish with their rates at the ends of a leg, so the velocity is
// continuous. With the defaults (1.6 m/s, 10 legs of 250 m per block) the
// one-hour mission crosses itself about 100 times.
//
// The truth is closed-form, piece by piece: position p*(t), velocity
// v*(t) = p*'(t) and acceleration in the world frame, each also evaluated
// in interval arithmetic over a time interval (a guaranteed enclosure of the
// formula's range). Pieces are chained in floating point, so p* may jump by
// ~1e-13 m and v* by ~1e-16 m/s at a join; the velocity tube accounts for
// the velocity jumps, the crossing references ignore the position ones.
//
// Measurements, every dt: m_k = v*(t_k) + b + w_k per axis, with a bias b
// drawn once in ±0.4 e and w_k uniform so that |b + w_k| <= 0.999 e (drawn
// with std::mt19937_64 mapped to [0, 1) by the top 53 bits: the same numbers
// on every platform). The check [v*](t_k) ⊂ m_k ± e is made in interval
// arithmetic.
//
// The velocity tube: slice k must hold v*(t) for every t in [t_k, t_k+1],
// not only at the samples. With A_k >= |v*'| over the slice (the interval
// acceleration over the slice, per axis) and J_k the velocity jumps at joins
// inside it, v*(t) <= m_k + e + A_k (t - t_k) + J_k and
// v*(t) <= m_k+1 + e + A_k (t_k+1 - t) + J_k; the largest value of the
// smaller of both over the slice is
//   min(m_k + e + A_k δ, m_k+1 + e + A_k δ, (m_k + m_k+1 + 2e + A_k δ)/2) + J_k
// (δ the slice width), and symmetrically below: measured ± e widened by
// about A_k δ / 2 (0.001 m/s on legs, 0.013 in half-turns), all in interval
// arithmetic. Gates: m_k ± e.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "sillage/error.h"
#include "sillage/interval/elementary.h"
#include "sillage/loops/path_crossings.h"
#include "sillage/tube/tdomain.h"
#include "sillage/tube/tube_vector.h"

namespace looping_mission {

using namespace sillage;
using std::numbers::pi;

struct Parameters {
  double duration = 3600.0;  // s (the mission runs over [0, duration])
  double e = 0.01;           // m/s: bound of the velocity error, per axis
  std::uint64_t seed = 2017;
  double dt = 0.1;           // s: velocity sampling = tube slices
  double speed = 1.6;        // m/s: mean speed
  int legs = 10;             // legs per block
  double spacing = 20.0;     // m between legs (the square's side is legs * spacing)
  double overshoot = 25.0;   // m: legs run past the square on both ends
  double transit_radius = 15.0;  // m: turning radius of the transits between blocks
  double wobble = 1.0;       // m: sideways excursion of the track along legs (0 to 2 wobble)
  double wobble_period = 60.0;   // s
  double surge = 1.6;        // m: along-track excursion (speed varies by ± surge * 2π / surge_period)
  double surge_period = 100.0;   // s
};

// One piece of the path over [t0, t0 + duration]: a straight leg (with
// surge and wobble) or an arc of circle at constant speed.
struct Piece {
  bool arc = false;
  double t0 = 0.0, duration = 0.0;
  double px = 0.0, py = 0.0, ux = 1.0, uy = 0.0;  // leg: start, unit direction
  double speed = 0.0;
  double wobble = 0.0, wobble_rate = 0.0, surge = 0.0, surge_rate = 0.0;
  double cx = 0.0, cy = 0.0, radius = 0.0, angle0 = 0.0, turn = 1.0, rate = 0.0;  // arc (rate = speed / radius)

  // Closed forms in the local time tau = t - t0, for double or Interval.
  template <class T>
  std::array<T, 2> position(const T& tau) const {
    using std::cos, std::sin;
    if (arc) {
      const T a = T(angle0) + T(turn * rate) * tau;
      return {T(cx) + T(radius) * cos(a), T(cy) + T(radius) * sin(a)};
    }
    const T along = T(speed) * tau + T(surge) * (T(1.0) - cos(T(surge_rate) * tau));
    const T side = T(wobble) * (T(1.0) - cos(T(wobble_rate) * tau));
    return {T(px) + along * T(ux) - side * T(uy), T(py) + along * T(uy) + side * T(ux)};
  }
  template <class T>
  std::array<T, 2> velocity(const T& tau) const {
    using std::cos, std::sin;
    if (arc) {
      const T a = T(angle0) + T(turn * rate) * tau, r = T(turn * radius) * T(rate);
      return {-r * sin(a), r * cos(a)};
    }
    const T along = T(speed) + T(surge) * T(surge_rate) * sin(T(surge_rate) * tau);
    const T side = T(wobble) * T(wobble_rate) * sin(T(wobble_rate) * tau);
    return {along * T(ux) - side * T(uy), along * T(uy) + side * T(ux)};
  }
  template <class T>
  std::array<T, 2> acceleration(const T& tau) const {
    using std::cos, std::sin;
    if (arc) {
      const T a = T(angle0) + T(turn * rate) * tau, r = T(radius) * T(rate) * T(rate);
      return {-r * cos(a), -r * sin(a)};
    }
    const T along = T(surge) * T(surge_rate) * T(surge_rate) * cos(T(surge_rate) * tau);
    const T side = T(wobble) * T(wobble_rate) * T(wobble_rate) * cos(T(wobble_rate) * tau);
    return {along * T(ux) - side * T(uy), along * T(uy) + side * T(ux)};
  }
};

namespace detail {

inline double wrap_2pi(double a) {
  a = std::fmod(a, 2 * pi);
  return a < 0 ? a + 2 * pi : a;
}

struct Pose {
  double x = 0.0, y = 0.0, heading = 0.0;
};

// Shortest Dubins path of the form arc-line-arc (LSL, RSR, LSR, RSL) of
// radius r from `from` to `to`: turn signs (+1 left), arc angles, line
// heading and length.
struct Dubins {
  double length = INFINITY;
  double turn1 = 1, turn2 = 1, angle1 = 0, angle2 = 0, heading = 0, straight = 0;
};

inline Dubins shortest_dubins(const Pose& from, const Pose& to, double r) {
  Dubins best;
  for (double s1 : {1.0, -1.0}) {
    for (double s2 : {1.0, -1.0}) {
      // Circle centres: the pose plus r on the side of the turn.
      const double c1x = from.x - s1 * r * std::sin(from.heading), c1y = from.y + s1 * r * std::cos(from.heading);
      const double c2x = to.x - s2 * r * std::sin(to.heading), c2y = to.y + s2 * r * std::cos(to.heading);
      const double dx = c2x - c1x, dy = c2y - c1y, d = std::hypot(dx, dy);
      double heading = std::atan2(dy, dx), straight = d;
      if (s1 != s2) {  // inner tangent: c2 - c1 = l u(φ) - 2 s1 r left(φ)
        if (d < 2 * r) continue;
        straight = std::sqrt(d * d - 4 * r * r);
        heading += std::atan2(2 * s1 * r, straight);
      }
      Dubins c{0, s1, s2, wrap_2pi(s1 * (heading - from.heading)), wrap_2pi(s2 * (to.heading - heading)), heading,
               straight};
      c.length = r * (c.angle1 + c.angle2) + straight;
      if (c.length < best.length) best = c;
    }
  }
  return best;
}

// Deterministic uniform numbers in [0, 1): the top 53 bits of mt19937_64.
class Uniform {
 public:
  explicit Uniform(std::uint64_t seed) : rng_(seed) {}
  double operator()() { return double(rng_() >> 11) * 0x1p-53; }
  double operator()(double a, double b) { return a + (b - a) * (*this)(); }

 private:
  std::mt19937_64 rng_;
};

}  // namespace detail

class Mission {
 public:
  explicit Mission(const Parameters& p = {}) : p_(p) {
    check_parameters();
    build_path();
    build_measurements();
  }

  const Parameters& parameters() const { return p_; }
  double tf() const { return p_.duration; }
  const std::vector<Piece>& pieces() const { return pieces_; }
  std::size_t nb_blocks() const { return nb_blocks_; }
  double path_length() const { return length_; }

  // The truth (double: the formulas in floating point; Interval: a guaranteed
  // enclosure over the interval, the hull over the pieces it meets).
  std::array<double, 2> position(double t) const {
    return at(t, [](const Piece& q, double tau) { return q.position(tau); });
  }
  std::array<double, 2> velocity(double t) const {
    return at(t, [](const Piece& q, double tau) { return q.velocity(tau); });
  }
  IntervalVector velocity(const Interval& t) const {
    return over(t, [](const Piece& q, const Interval& tau) { return q.velocity(tau); });
  }
  IntervalVector acceleration(const Interval& t) const {
    return over(t, [](const Piece& q, const Interval& tau) { return q.acceleration(tau); });
  }

  const std::shared_ptr<TDomain>& tdomain() const { return td_; }
  const std::vector<std::array<double, 2>>& measurements() const { return measured_; }  // at t_k
  const TubeVector& velocity_tube() const { return *v_; }

  // The true path sampled every `step` seconds (and at tf), for self_crossings.
  struct Samples {
    std::vector<double> t, x, y;
  };
  Samples true_path(double step) const {
    if (!(step > 0)) throw Error("looping_mission: the sampling step must be > 0");
    Samples s;
    const std::size_t n = static_cast<std::size_t>(std::ceil(tf() / step));
    for (std::size_t k = 0; k <= n; ++k) {
      const double t = std::min(tf(), double(k) * step);
      if (!s.t.empty() && t <= s.t.back()) break;
      const auto q = position(t);
      s.t.push_back(t), s.x.push_back(q[0]), s.y.push_back(q[1]);
    }
    return s;
  }

  // The crossings of the true curve itself: those of the sampled polyline,
  // refined by Newton's method on p*(t1) = p*(t2).
  std::vector<PathCrossing> true_crossings(double step) const {
    const Samples s = true_path(step);
    std::vector<PathCrossing> cs = self_crossings(s.t, s.x, s.y);
    for (PathCrossing& c : cs) refine(c);
    return cs;
  }

 private:
  void check_parameters() const {
    auto positive = [](double v, const char* name) {
      if (!(v > 0) || !std::isfinite(v)) {
        throw Error(std::string("looping_mission: parameter ") + name + " must be finite and > 0, got " +
                    number_text(v));
      }
    };
    positive(p_.duration, "duration");
    positive(p_.e, "e");
    positive(p_.dt, "dt");
    positive(p_.speed, "speed");
    positive(p_.spacing, "spacing");
    positive(p_.transit_radius, "transit_radius");
    positive(p_.wobble_period, "wobble_period");
    positive(p_.surge_period, "surge_period");
    if (p_.legs < 2) throw Error("looping_mission: at least 2 legs per block, got " + std::to_string(p_.legs));
    if (!(p_.overshoot >= 0) || !(p_.wobble >= 0) || !(p_.surge >= 0)) {
      throw Error("looping_mission: overshoot, wobble and surge must be >= 0");
    }
    if (p_.duration / p_.dt > 1e8) throw Error("looping_mission: more than 1e8 samples");
  }

  template <class F>
  std::array<double, 2> at(double t, F&& f) const {
    if (!(t >= 0 && t <= tf())) throw Error("looping_mission: t = " + number_text(t) + " outside [0, tf]");
    const Piece& q = pieces_[piece_index(t)];
    return f(q, t - q.t0);
  }

  template <class F>
  IntervalVector over(const Interval& t, F&& f) const {
    if (t.is_empty() || t.lb() < 0 || t.ub() > tf()) {
      throw Error("looping_mission: time interval " + t.str() + " outside [0, tf]");
    }
    IntervalVector r(2, Interval::empty());
    for (std::size_t i = piece_index(t.lb()); i < pieces_.size() && pieces_[i].t0 <= t.ub(); ++i) {
      const Piece& q = pieces_[i];
      // The piece's own domain, up to the next piece's start (or tf): the
      // time point of a join belongs to both pieces.
      const double end = i + 1 < pieces_.size() ? pieces_[i + 1].t0 : tf();
      const Interval local = (t & Interval(q.t0, end)) - Interval(q.t0);
      if (local.is_empty()) continue;
      const auto v = f(q, local);
      r[0] |= v[0];
      r[1] |= v[1];
    }
    return r;
  }

  // The last piece starting at or before t.
  std::size_t piece_index(double t) const {
    const auto it = std::upper_bound(pieces_.begin(), pieces_.end(), t,
                                     [](double v, const Piece& q) { return v < q.t0; });
    return it == pieces_.begin() ? 0 : std::size_t(it - pieces_.begin()) - 1;
  }

  // ---- the path ----
  void add_leg(double length, bool survey) {
    Piece q;
    q.t0 = t_;
    q.duration = length / p_.speed;
    q.px = pose_.x, q.py = pose_.y, q.ux = std::cos(pose_.heading), q.uy = std::sin(pose_.heading);
    q.speed = p_.speed;
    if (survey) {  // whole numbers of periods: both excursions and their rates vanish at the ends
      const double nw = std::max(1.0, std::round(q.duration / p_.wobble_period));
      const double ns = std::max(1.0, std::round(q.duration / p_.surge_period));
      q.wobble = p_.wobble, q.wobble_rate = 2 * pi * nw / q.duration;
      q.surge = p_.surge, q.surge_rate = 2 * pi * ns / q.duration;
    }
    push(q, pose_.heading);
  }

  void add_arc(double turn, double radius, double angle) {
    Piece q;
    q.arc = true;
    q.t0 = t_;
    q.speed = p_.speed;
    q.turn = turn, q.radius = radius, q.rate = p_.speed / radius;
    q.duration = angle / q.rate;
    q.cx = pose_.x - turn * radius * std::sin(pose_.heading), q.cy = pose_.y + turn * radius * std::cos(pose_.heading);
    q.angle0 = std::atan2(pose_.y - q.cy, pose_.x - q.cx);
    push(q, pose_.heading + turn * angle);
  }

  void push(const Piece& q, double heading_after) {
    if (q.duration <= 1e-9) return;  // degenerate pieces of a transit
    pieces_.push_back(q);
    const auto end = q.position(q.duration);
    pose_ = {end[0], end[1], heading_after};
    t_ += q.duration;
    length_ += q.speed * q.duration;
  }

  // Block b: lawn-mower legs along direction θ_b over the survey square,
  // entered at the corner (and direction) nearest by Dubins path.
  void add_block(std::size_t b) {
    static const double kDirections[] = {0, pi / 2, pi / 4, 3 * pi / 4, pi / 8, 5 * pi / 8, 3 * pi / 8, 7 * pi / 8};
    const double side = p_.legs * p_.spacing, leg = side + 2 * p_.overshoot;
    const double theta = kDirections[b % 8];
    // Variants: first leg along θ or θ + π, progressing to its left (+1) or right (-1).
    detail::Pose start;
    double progress = 1;
    if (b == 0) {  // the mission starts on the first leg
      start = pose_;
      centre_x_ = pose_.x + (side / 2 + p_.overshoot), centre_y_ = pose_.y + (side / 2 - p_.spacing / 2);
    } else {
      double best = INFINITY;
      for (double h : {theta, theta + pi}) {
        for (double s : {1.0, -1.0}) {
          const double ux = std::cos(h), uy = std::sin(h), nx = -uy * s, ny = ux * s;
          const double a = side / 2 + p_.overshoot, o = side / 2 - p_.spacing / 2;
          const detail::Pose candidate{centre_x_ - a * ux - o * nx, centre_y_ - a * uy - o * ny, h};
          const double len = detail::shortest_dubins(pose_, candidate, p_.transit_radius).length;
          if (len < best) best = len, start = candidate, progress = s;
        }
      }
      const detail::Dubins d = detail::shortest_dubins(pose_, start, p_.transit_radius);
      add_arc(d.turn1, p_.transit_radius, d.angle1);
      pose_.heading = d.heading;  // equal up to rounding; the line follows the tangent
      add_leg(d.straight, false);
      add_arc(d.turn2, p_.transit_radius, d.angle2);
      if (std::hypot(pose_.x - start.x, pose_.y - start.y) > 1e-6) {
        throw Error("looping_mission: the transit to block " + std::to_string(b) + " misses its start");
      }
      pose_.heading = start.heading;
    }
    for (int k = 0; k < p_.legs; ++k) {
      add_leg(leg, true);
      if (k + 1 < p_.legs) add_arc(k % 2 == 0 ? progress : -progress, p_.spacing / 2, pi);
    }
    ++nb_blocks_;
  }

  void build_path() {
    for (std::size_t b = 0; t_ < p_.duration; ++b) add_block(b);
    // Cut the last pieces at the duration.
    while (pieces_.back().t0 >= p_.duration) pieces_.pop_back();
    pieces_.back().duration = p_.duration - pieces_.back().t0;
    length_ = 0;
    for (const Piece& q : pieces_) length_ += q.speed * q.duration;
  }

  // ---- measurements and the velocity tube ----
  void build_measurements() {
    td_ = TDomain::create(0.0, p_.duration, p_.dt);
    const std::size_t n = td_->nb_slices();
    detail::Uniform uniform(p_.seed);
    const double bias[2] = {uniform(-0.4, 0.4) * p_.e, uniform(-0.4, 0.4) * p_.e};
    const Interval e(-p_.e, p_.e);
    measured_.resize(n + 1);
    std::vector<IntervalVector> gates(n + 1);
    for (std::size_t k = 0; k <= n; ++k) {
      const double t = td_->t(k);
      const auto v = velocity(t);
      const IntervalVector exact = velocity(Interval(t));
      gates[k] = IntervalVector(2);
      for (std::size_t i = 0; i < 2; ++i) {
        const double spread = (1 - std::fabs(bias[i]) / p_.e) * 0.999 * p_.e;
        measured_[k][i] = v[i] + bias[i] + uniform(-spread, spread);
        gates[k][i] = Interval(measured_[k][i]) + e;
        if (exact[i].is_empty() || !exact[i].is_subset(gates[k][i])) {
          throw Error("looping_mission: the measurement at t = " + number_text(t) + " misses the truth");
        }
      }
    }
    std::vector<Interval> slices[2], gate_list[2];
    for (std::size_t i = 0; i < 2; ++i) slices[i].resize(n), gate_list[i].resize(n + 1);
    for (std::size_t k = 0; k < n; ++k) {
      const Interval span = td_->slice_domain(k), width = td_->slice_width(k);
      const IntervalVector acc = acceleration(span);
      const std::array<Interval, 2> jumps = jumps_in(span);
      for (std::size_t i = 0; i < 2; ++i) {
        const Interval a(acc[i].mag()), drift = a * width + jumps[i];
        const Interval& g0 = gates[k][i];
        const Interval& g1 = gates[k + 1][i];
        const Interval mid_hi = (Interval(g0.ub()) + Interval(g1.ub()) + a * width) / Interval(2) + jumps[i];
        const Interval mid_lo = (Interval(g0.lb()) + Interval(g1.lb()) - a * width) / Interval(2) - jumps[i];
        const double hi = std::min({(Interval(g0.ub()) + drift).ub(), (Interval(g1.ub()) + drift).ub(), mid_hi.ub()});
        const double lo = std::max({(Interval(g0.lb()) - drift).lb(), (Interval(g1.lb()) - drift).lb(), mid_lo.lb()});
        slices[i][k] = Interval(lo, hi);
      }
    }
    for (std::size_t k = 0; k <= n; ++k) {
      for (std::size_t i = 0; i < 2; ++i) gate_list[i][k] = gates[k][i];
    }
    v_ = std::make_unique<TubeVector>(
        std::vector<Tube>{Tube(td_, slices[0], gate_list[0]), Tube(td_, slices[1], gate_list[1])});
  }

  // Upper bounds (as [0, J] intervals) of the velocity jumps at the joins
  // inside the closed time interval.
  std::array<Interval, 2> jumps_in(const Interval& span) const {
    std::array<Interval, 2> j{Interval(0.0), Interval(0.0)};
    for (std::size_t i = piece_index(span.lb()) + 1; i < pieces_.size() && pieces_[i].t0 <= span.ub(); ++i) {
      const Piece& before = pieces_[i - 1];
      const Piece& after = pieces_[i];
      const auto vb = before.velocity(Interval(after.t0) - Interval(before.t0));
      const auto va = after.velocity(Interval(0.0));
      for (std::size_t c = 0; c < 2; ++c) j[c] += Interval((vb[c] - va[c]).mag());
    }
    if (span.lb() == pieces_[piece_index(span.lb())].t0 && piece_index(span.lb()) > 0) {
      const std::size_t i = piece_index(span.lb());  // a join at the start of the span
      const auto vb = pieces_[i - 1].velocity(Interval(pieces_[i].t0) - Interval(pieces_[i - 1].t0));
      const auto va = pieces_[i].velocity(Interval(0.0));
      for (std::size_t c = 0; c < 2; ++c) j[c] += Interval((vb[c] - va[c]).mag());
    }
    return j;
  }

  void refine(PathCrossing& c) const {
    double t1 = c.t1, t2 = c.t2;
    for (int it = 0; it < 8; ++it) {
      const auto p1 = position(t1), p2 = position(t2), v1 = velocity(t1), v2 = velocity(t2);
      // F = p(t1) - p(t2), J = [v(t1) | -v(t2)].
      const double fx = p1[0] - p2[0], fy = p1[1] - p2[1];
      const double det = -v1[0] * v2[1] + v1[1] * v2[0];
      if (det == 0) return;
      const double d1 = (-v2[1] * fx + v2[0] * fy) / det, d2 = (-v1[1] * fx + v1[0] * fy) / det;
      const double n1 = t1 - d1, n2 = t2 - d2;
      if (std::fabs(n1 - c.t1) > 1.0 || std::fabs(n2 - c.t2) > 1.0 || !(n1 >= 0 && n2 <= tf())) return;
      t1 = n1, t2 = n2;
    }
    c.t1 = t1, c.t2 = t2;
    const auto q = position(t1);
    c.x = q[0], c.y = q[1];
  }

  Parameters p_;
  std::vector<Piece> pieces_;
  detail::Pose pose_;
  double t_ = 0.0, length_ = 0.0, centre_x_ = 0.0, centre_y_ = 0.0;
  std::size_t nb_blocks_ = 0;
  std::shared_ptr<TDomain> td_;
  std::vector<std::array<double, 2>> measured_;
  std::unique_ptr<TubeVector> v_;
};

// The open Lissajous path of bench_tplane: p*(t) = (A sin(w1 t), A sin(w2 t + 0.4)),
// A = 120 m, w1 = 7 and w2 = 8.3 cycles per hour (up to ~1.7 m/s), crossing
// itself about 70 times in the first hour; the velocity tube p*' +- e sliced
// every dt (the expression is evaluated in interval arithmetic over each slice).
class Lissajous {
 public:
  explicit Lissajous(double duration, double e = 0.01, double dt = 0.1)
      : td_(TDomain::create(0, duration, dt)) {
    char err[80];
    std::snprintf(err, sizeof err, "[-%.17g,%.17g]", e, e);
    const std::string w1 = "(2*pi*7/3600)", w2 = "(2*pi*8.3/3600)";
    v_ = std::make_unique<TubeVector>(td_, "(120*" + w1 + "*cos(" + w1 + "*t) + " + std::string(err) + ", 120*" + w2 + "*cos(" +
                                               w2 + "*t + 0.4) + " + err + ")");
  }
  double tf() const { return td_->tf(); }
  const std::shared_ptr<TDomain>& tdomain() const { return td_; }
  const TubeVector& velocity_tube() const { return *v_; }
  std::array<double, 2> position(double t) const { return {kA * std::sin(kW1 * t), kA * std::sin(kW2 * t + 0.4)}; }
  std::array<double, 2> velocity(double t) const {
    return {kA * kW1 * std::cos(kW1 * t), kA * kW2 * std::cos(kW2 * t + 0.4)};
  }
  // The crossings of the path sampled every `step` seconds.
  std::vector<PathCrossing> true_crossings(double step) const {
    std::vector<double> t, x, y;
    for (std::size_t k = 0; double(k) * step < tf(); ++k) {
      const auto q = position(double(k) * step);
      t.push_back(double(k) * step), x.push_back(q[0]), y.push_back(q[1]);
    }
    return self_crossings(t, x, y);
  }

 private:
  static constexpr double kA = 120.0, kW1 = 2 * pi * 7 / 3600, kW2 = 2 * pi * 8.3 / 3600;
  std::shared_ptr<TDomain> td_;
  std::unique_ptr<TubeVector> v_;
};

}  // namespace looping_mission
