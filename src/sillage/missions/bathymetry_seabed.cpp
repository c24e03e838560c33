#include "sillage/missions/bathymetry_seabed.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "sillage/error.h"
#include "sillage/missions/bathymetry_rng.h"

namespace sillage {

using detail::BathymetryRng;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Gaussian {  // A exp(-(a^2/(2 s1^2) + b^2/(2 s2^2))), (a, b) the rotated offsets
  double cx, cy, amp, s1, s2, cth, sth;
  double operator()(double x, double y) const {
    const double dx = x - cx, dy = y - cy, a = cth * dx + sth * dy, b = -sth * dx + cth * dy;
    return amp * std::exp(-(a * a / (2 * s1 * s1) + b * b / (2 * s2 * s2)));
  }
  double smin() const { return std::min(s1, s2); }
};

struct Wave {  // amp sin(k (cos th x + sin th y) + phase)
  double amp, k, cth, sth, phase;
  double operator()(double x, double y) const { return amp * std::sin(k * (cth * x + sth * y) + phase); }
};

// Three sand-wave trains (wavelengths 10-16, 18-26, 28-40 m, random directions
// and phases) whose amplitudes sum to `height`: relief at the scale of a
// drift window with no single period.
std::vector<Wave> dune_trains(detail::BathymetryRng rng, double height) {
  if (!(height > 0)) return {};
  const double lmin[3] = {10, 18, 28}, lmax[3] = {16, 26, 40}, share[3] = {0.3, 0.33, 0.37};
  std::vector<Wave> out;
  for (int i = 0; i < 3; ++i) {
    const double wl = rng.uniform(lmin[i], lmax[i]), th = rng.uniform(0, kPi);
    out.push_back({height * share[i], 2 * kPi / wl, std::cos(th), std::sin(th), rng.uniform(0, 2 * kPi)});
  }
  return out;
}

// A channel flank (ChannelBank): a tanh step across a straight line.
struct Flank {
  double amp, width, cth, sth, cx, cy;
  double operator()(double x, double y) const {
    return amp * (1 + std::tanh((cth * (x - cx) + sth * (y - cy)) / width)) / 2;
  }
};

// 1 / (1 + exp(-(x - x0)/w)): 0 in the smooth west, 1 in the rough east.
double logistic(double x, double x0, double w) { return 1 / (1 + std::exp(-(x - x0) / w)); }

}  // namespace

Seabed generate_seabed(std::uint64_t seed, const SeabedOptions& o) {
  if (!(o.size > 10) || !(o.cell > 0) || !std::isfinite(o.size) || !std::isfinite(o.base_depth) ||
      !(o.smooth_width >= 0) || o.smooth_width > o.size || o.nb_rocks < 0 || o.nb_banks < 0 || !(o.relief >= 0) ||
      !std::isfinite(o.relief))
    throw Error("generate_seabed: size > 10, cell > 0, 0 <= smooth_width <= size, counts >= 0, finite relief >= 0 expected");
  if (!(o.rock_height_min >= 0) || !(o.rock_height_max >= o.rock_height_min) || !(o.rock_sigma_min > 0) ||
      !(o.rock_sigma_max >= o.rock_sigma_min) || !std::isfinite(o.rock_height_max + o.rock_sigma_max) ||
      !(o.dune_height >= 0) || !std::isfinite(o.dune_height))
    throw Error("generate_seabed: 0 <= rock_height_min <= rock_height_max, 0 < rock_sigma_min <= rock_sigma_max, "
                "finite dune_height >= 0 expected");
  for (const ChannelBank& b : o.channel_banks)
    if (!std::isfinite(b.height + b.direction + b.x + b.y) || !(b.width > 0) || !std::isfinite(b.width))
      throw Error("generate_seabed: a channel bank needs a finite height, direction, x, y and a finite width > 0");
  const double R = o.relief;  // scales every relief amplitude (and so the class bounds)
  detail::BathymetryRng rng(seed);
  const double L = o.size;
  // Regional slope: deeper towards the south-east, ~3-5 m across the area.
  const double sx = R * rng.uniform(0.004, 0.007), sy = -R * rng.uniform(0.002, 0.004);
  // Smooth strip in the west, rough part beyond a transition of width tw.
  const double x_edge = o.smooth_width, tw = 15;
  std::vector<Gaussian> banks, rocks;
  for (int k = 0; k < o.nb_banks; ++k) {  // sandbanks: shallower ridges, 150-250 m long
    const double th = rng.uniform(0, kPi);
    banks.push_back({rng.uniform(x_edge + 60, L - 60), rng.uniform(60, L - 60), -R * rng.uniform(2.0, 3.5),
                     rng.uniform(90, 130), rng.uniform(35, 50), std::cos(th), std::sin(th)});
  }
  // Rocks (default 0.8-1.5 m high, sigma 8-12 m), at least 8 sigma_max apart.
  const double rock_smax = o.rock_sigma_max;
  for (int k = 0, tries = 0; k < o.nb_rocks && tries < 10000; ++tries) {
    const double s = rng.uniform(o.rock_sigma_min, rock_smax), cx = rng.uniform(x_edge + 30, L - 20),
                 cy = rng.uniform(20, L - 20);
    const double amp = -R * rng.uniform(o.rock_height_min, o.rock_height_max);
    bool far = true;
    for (const auto& r : rocks) far = far && std::hypot(r.cx - cx, r.cy - cy) >= 8 * rock_smax;
    if (!far) continue;
    rocks.push_back({cx, cy, amp, s, s, 1, 0});
    ++k;
  }
  // Sand waves: crests across a random direction, wavelength 40-55 m, amplitude 0.2-0.3 m.
  const double wl = rng.uniform(40, 55), wamp = R * rng.uniform(0.2, 0.3), wth = rng.uniform(0, kPi);
  const double kx = 2 * kPi / wl * std::cos(wth), ky = 2 * kPi / wl * std::sin(wth), wph = rng.uniform(0, 2 * kPi);
  // A gentle swell in the smooth part too (0.3 m over 200 m).
  const double gamp = R * 0.3, gk = 2 * kPi / 200, gph = rng.uniform(0, 2 * kPi);
  const double roughness = 0.03;
  // The dune field, from its own stream (drawn only when asked: the smoother seabed's draws are unchanged).
  const std::vector<Wave> dunes = o.dune_height > 0 ? dune_trains(rng.fork(2), R * o.dune_height) : std::vector<Wave>{};
  // The channel flanks draw nothing: the other features of a seed are the same with or without them.
  std::vector<Flank> flanks;
  for (const ChannelBank& b : o.channel_banks) {
    const double th = b.direction * kPi / 180;
    flanks.push_back({R * b.height, b.width, std::cos(th), std::sin(th), b.x, b.y});
  }

  // The class, from the parameters. Gaussian: |H| <= A/s_min^2, |grad| <= A/s_min e^{-1/2}.
  // Rocks >= 8 s_max apart: at any point all but one are >= 4 s away, each adding at most
  // (A/s^2)(1 + 16) e^{-8} < 0.0058 A/s^2 to the Hessian norm.
  double curv = gamp * gk * gk, slope = std::hypot(sx, sy) + gamp * gk;
  for (const auto& b : banks) curv += std::abs(b.amp) / (b.smin() * b.smin()), slope += std::abs(b.amp) / b.smin();
  double rock_h = 0, rock_g = 0;
  for (const auto& r : rocks) rock_h = std::max(rock_h, std::abs(r.amp) / (r.s1 * r.s1)),
                              rock_g = std::max(rock_g, std::abs(r.amp) / r.s1);
  curv += rock_h * (1 + 0.0058 * static_cast<double>(rocks.size())), slope += rock_g * (1 + 0.0058 * rocks.size());
  // Sand waves E(x) A sin(k.p): |H| <= A (k^2 + 2 k |E'| + |E''|), |E'| <= 1/(4 w), |E''| <= 0.0963 / w^2.
  const double kk = 2 * kPi / wl;
  curv += wamp * (kk * kk + 2 * kk / (4 * tw) + 0.0963 / (tw * tw));
  slope += wamp * (kk + 1 / (4 * tw));
  for (const Wave& d : dunes) {
    curv += d.amp * (d.k * d.k + 2 * d.k / (4 * tw) + 0.0963 / (tw * tw));
    slope += d.amp * (d.k + 1 / (4 * tw));
  }
  // Flank A (1 + tanh(s / w)) / 2: |grad| <= |A| / (2 w); |Hessian| = |A| |tanh''| / (2 w^2)
  // with |tanh''| = 2 |tanh| sech^2 <= 4 / (3 sqrt 3), so <= 0.385 |A| / w^2 (2 / (3 sqrt 3) = 0.38490).
  for (const Flank& f : flanks) {
    slope += std::abs(f.amp) / (2 * f.width);
    curv += 0.385 * std::abs(f.amp) / (f.width * f.width);
  }
  // Every term rounded up by a relative margin for the floating-point evaluation.
  curv *= 1.01, slope *= 1.01;

  const std::size_t n = static_cast<std::size_t>(std::llround(L / o.cell)) + 1;
  std::vector<double> z(n * n);
  detail::BathymetryRng noise = rng.fork(1);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const double x = static_cast<double>(i) * o.cell, y = static_cast<double>(j) * o.cell;
      double d = o.base_depth + sx * x + sy * y + gamp * std::sin(gk * (x + 0.6 * y) / std::hypot(1.0, 0.6) + gph);
      for (const auto& b : banks) d += b(x, y);
      for (const auto& r : rocks) d += r(x, y);
      for (const Flank& f : flanks) d += f(x, y);
      double waves = wamp * std::sin(kx * x + ky * y + wph);
      for (const Wave& w : dunes) waves += w(x, y);
      d += logistic(x, x_edge, tw) * waves;
      d += noise.uniform(-roughness, roughness);
      z[j * n + i] = std::round(d * 1000) / 1000;  // millimetre quantization
    }
  Seabed s{BathymetryDem(0, 0, o.cell, n, n, std::move(z)), {curv, slope, roughness + 0.0005},
           IntervalVector{Interval(0, x_edge), Interval(0, L)}};
  return s;
}

SeabedOptions coastal_seabed_options() {
  SeabedOptions o;
  o.nb_rocks = 24;
  o.rock_height_min = 1.5, o.rock_height_max = 3;
  o.rock_sigma_min = 5, o.rock_sigma_max = 8;
  o.dune_height = 0.9;
  return o;
}

SeabedOptions bank_seabed_options() {
  SeabedOptions o;
  ChannelBank west, north;
  west.height = 15, west.width = 30, west.direction = 180, west.x = 110, west.y = 250;
  north.height = 12, north.width = 24, north.direction = 90, north.x = 250, north.y = 350;
  o.channel_banks = {west, north};
  return o;
}

std::string repr(const SeabedClass& c) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "SeabedClass(curvature=%.4g /m, slope=%.4g, roughness=%.4g m)", c.curvature, c.slope,
                c.roughness);
  return buf;
}

}  // namespace sillage
