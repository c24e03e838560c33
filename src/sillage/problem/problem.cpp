#include "sillage/problem/problem.h"

namespace sillage {

const VarSpec* Problem::var(const std::string& name) const {
  for (const VarSpec& v : vars)
    if (v.name == name) return &v;
  return nullptr;
}

const ConstraintSpec* Problem::deriv_of(const std::string& x) const {
  for (const ConstraintSpec& c : constraints)
    if (c.kind == ConstraintKind::Deriv && c.x == x) return &c;
  return nullptr;
}

const DataSpec* Problem::table(const std::string& name) const {
  for (const DataSpec& d : data)
    if (d.name == name) return &d;
  return nullptr;
}

const char* kind_name(VarKind k) {
  switch (k) {
    case VarKind::Tube: return "tube";
    case VarKind::TubeVector: return "tube_vector";
    case VarKind::Interval: return "interval";
    case VarKind::Box: return "box";
  }
  return "?";
}

const char* kind_name(ConstraintKind k) {
  switch (k) {
    case ConstraintKind::Expr: return "expr";
    case ConstraintKind::Deriv: return "deriv";
    case ConstraintKind::Increment: return "increment";
    case ConstraintKind::Eval: return "eval";
    case ConstraintKind::Heading: return "heading";
    case ConstraintKind::SecondDeriv: return "second_deriv";
    case ConstraintKind::HeadingWindow: return "heading_window";
    case ConstraintKind::PImpliesZ: return "p_implies_z";
    case ConstraintKind::Python: return "python";
  }
  return "?";
}

const char* scheduling_name(Scheduling s) { return s == Scheduling::Priority ? "priority" : "fifo"; }

}  // namespace sillage
