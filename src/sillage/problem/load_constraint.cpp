// [[constraint]]: the kind picks the reader (one file per kind); "expr", a
// pointwise expression = 0, is read here.
#include "sillage/problem/problem_loader.h"

namespace sillage::detail {

void ProblemLoader::read_constraint(const Fields& top, const toml::node& node) {
  const std::size_t index = p_.constraints.size() + 1;
  const toml::table& t = top.table(node, "a [[constraint]] table");
  const toml::node* kn = t.get("kind");
  ConstraintSpec c;
  c.pos = doc_.pos(node);
  const std::string expected_kind =
      "kind = \"expr\", \"deriv\", \"second_deriv\", \"increment\", \"eval\", \"heading\", \"heading_window\", "
      "\"p_implies_z\" or \"python\"";
  if (!kn) throw ProblemError(c.pos, "constraint " + std::to_string(index) + " without a kind", expected_kind);
  const std::string ks = top.string(*kn, expected_kind);
  const std::string where = "constraint " + std::to_string(index) + " (" + ks + ")";
  if (ks == "expr") {
    read_expr_constraint(Fields(doc_, t, where, {"kind", "expr"}), c);
  } else if (ks == "deriv" || ks == "increment" || ks == "second_deriv") {
    const char* vkey = ks == "second_deriv" ? "a" : "v";
    read_deriv(Fields(doc_, t, where, {"kind", "x", vkey}), c, ks, vkey);
  } else if (ks == "heading") {
    read_heading(Fields(doc_, t, where, {"kind", "p", "psi", "dist", "omega", "track"}), c);
  } else if (ks == "heading_window") {
    read_heading_window(
        Fields(doc_, t, where, {"kind", "p", "psi", "dist", "dpsi", "omega", "track", "window", "turn_accel", "stride"}), c);
  } else if (ks == "p_implies_z") {
    read_p_implies_z(Fields(doc_, t, where, {"kind", "p", "w", "z", "eps", "fast"}), c);
  } else if (ks == "python") {
    read_python(Fields(doc_, t, where, {"kind", "module", "class", "args", "params"}), c);
  } else if (ks == "eval") {
    read_eval(Fields(doc_, t, where, {"kind", "data", "y", "v", "time", "time_error", "errors", "where", "gates", "join", "expr", "outside", "q", "q_window", "q_rows"}), c, where);
  } else {
    throw ProblemError(doc_.pos(*kn), describe(*kn), expected_kind);
  }
  p_.constraints.push_back(std::move(c));
}

void ProblemLoader::read_expr_constraint(const Fields& f, ConstraintSpec& c) {
  auto dims = [this](const std::string& n) -> std::optional<std::size_t> {
    const VarSpec* v = p_.var(n);
    return v ? std::optional<std::size_t>(v->dim) : std::nullopt;
  };
  auto is_vec = [this](const std::string& n) {
    const VarSpec* v = p_.var(n);
    return v && (v->kind == VarKind::TubeVector || v->kind == VarKind::Box);
  };
  c.kind = ConstraintKind::Expr;
  read_expr(f, c, dims, is_vec, known_vars());
  c.label = f.where() + ": " + c.expr + " = 0";
}

}  // namespace sillage::detail
