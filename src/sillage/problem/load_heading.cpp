// [[constraint]] kinds "heading" (CtcHeading) and "heading_window" (CtcHeadingWindow): a planar vehicle's odometry.
#include "sillage/problem/problem_loader.h"

namespace sillage::detail {

void ProblemLoader::read_heading(const Fields& f, ConstraintSpec& c) {
  c.kind = ConstraintKind::Heading;
  read_odometry(f, c, {std::pair{"psi", &c.psi}, std::pair{"dist", &c.dist}, std::pair{"omega", &c.omega}});
  c.label = f.where() + ": " + c.p + " from " + c.dist + " along " + c.psi + " (track error " + c.track + ")";
}

void ProblemLoader::read_heading_window(const Fields& f, ConstraintSpec& c) {
  c.kind = ConstraintKind::HeadingWindow;
  read_odometry(f, c,
                {std::pair{"psi", &c.psi}, std::pair{"dist", &c.dist}, std::pair{"dpsi", &c.dpsi}, std::pair{"omega", &c.omega}});
  const toml::node& wn = f.require("window", "the length of the windows (s, a number > 0)");
  c.window = f.number(wn, "the length of the windows (s, a number > 0)");
  if (!(c.window > 0)) throw ProblemError(doc_.pos(wn), "window = " + doc_.raw(wn), "a window length > 0 (s)");
  if (const toml::node* an = f.find("turn_accel")) {
    if (!(f.number(*an, "a turn acceleration bound > 0 (rad/s^2)") > 0))
      throw ProblemError(doc_.pos(*an), "turn_accel = " + doc_.raw(*an), "a turn acceleration bound > 0 (rad/s^2)");
    c.turn_accel = f.bound_text(*an);
  }
  if (const toml::node* sn = f.find("stride")) {
    const std::int64_t s = f.integer(*sn, "a window every `stride` slices (an integer >= 1)");
    if (s < 1) throw ProblemError(doc_.pos(*sn), "stride = " + doc_.raw(*sn), "an integer >= 1 (slices)");
    c.stride = static_cast<std::size_t>(s);
  }
  c.label = f.where() + ": " + c.p + " over windows of " + doc_.raw(wn) + " s against " + c.psi + " and " + c.dpsi;
}

// The odometry of a planar vehicle (heading, heading_window): p a 2-D
// tube_vector, the scalar tubes of `scalars`, and the track error.
void ProblemLoader::read_odometry(const Fields& f, ConstraintSpec& c, TubeKeys scalars) {
  const VarSpec& p = tube_var(f, "p");
  if (p.kind != VarKind::TubeVector || p.dim != 2)
    throw ProblemError(doc_.pos(*f.find("p")), "'" + p.name + "' (" + kind_name(p.kind) + ", dim " + std::to_string(p.dim) + ")",
                       "a position: a tube_vector of dim 2");
  c.p = p.name;
  for (auto [key, out] : scalars) {
    const VarSpec& s = tube_var(f, key);
    if (s.kind != VarKind::Tube) throw ProblemError(doc_.pos(*f.find(key)), "the tube_vector '" + s.name + "'", "a scalar tube");
    *out = s.name;
  }
  if (const toml::node* tr = f.find("track")) {
    if (!(f.number(*tr, "a track error >= 0 (rad)") >= 0)) throw ProblemError(doc_.pos(*tr), "a negative track error", "a track error >= 0");
    c.track = f.bound_text(*tr);
  }
}

}  // namespace sillage::detail
