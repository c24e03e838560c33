// [output] loops: the t-plane of the velocity (or of the position and its velocity).
#include "sillage/problem/problem_loader.h"

namespace sillage::detail {

void ProblemLoader::read_loops(const Fields& f, const toml::node& ln) {
  const Fields lf(doc_, f.table(ln, "a table {v = \"velocity\", p = \"position\", eps = width}"), "[output] loops",
                  {"v", "p", "eps"});
  LoopsSpec l;
  l.pos = doc_.pos(ln);
  for (auto [key, out] : {std::pair{"v", &l.v}, std::pair{"p", &l.p}}) {
    const toml::node* n = lf.find(key);
    if (!n) {
      if (std::string(key) == "v") lf.require("v", "the velocity, a tube_vector of dim 2");
      continue;
    }
    const VarSpec& v = tube_var(lf, *n);
    if (v.kind != VarKind::TubeVector || v.dim != 2)
      throw ProblemError(doc_.pos(*n), "'" + v.name + "' (" + kind_name(v.kind) + ", dim " + std::to_string(v.dim) + ")",
                         "a tube_vector of dim 2");
    *out = v.name;
  }
  if (const toml::node* e = lf.find("eps")) {
    const double eps = lf.number(*e, "a paving width > 0 (time units)");
    if (!(eps > 0) || (p_.time.tf - p_.time.t0) / eps > 1e6)
      throw ProblemError(doc_.pos(*e), "eps = " + doc_.raw(*e), "a paving width in (0, tf - t0], at least (tf - t0)/1e6");
    l.eps = eps;
  }
  p_.output.loops = l;
}

}  // namespace sillage::detail
