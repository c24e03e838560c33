// [output]: the results table's times, the plots and maps, the landmarks, the truth to check.
#include "sillage/problem/problem_loader.h"

#include <algorithm>

#include <cctype>

namespace sillage::detail {

std::pair<std::string, std::size_t> ProblemLoader::tube_ref(const Fields& f, const toml::node& n, bool allow_whole) {
  const std::string s = f.string(n, "a tube such as \"x\" or \"x[0]\"");
  const auto b = s.find('[');
  const std::string name = s.substr(0, b);
  const VarSpec* v = p_.var(name);
  if (!v || !v->is_tube()) throw ProblemError(doc_.pos(n), "'" + s + "'", "a tube variable (" + known_vars(true) + ")");
  if (b == std::string::npos) {
    if (!allow_whole && v->kind == VarKind::TubeVector)
      throw ProblemError(doc_.pos(n), "'" + s + "'", "a component such as " + name + "[0]");
    return {name, static_cast<std::size_t>(-1)};
  }
  std::size_t i = 0;
  bool ok = s.back() == ']' && s.size() > b + 2 && s.size() < b + 8;
  for (std::size_t k = b + 1; ok && k + 1 < s.size(); ++k) {
    ok = std::isdigit(static_cast<unsigned char>(s[k]));
    i = i * 10 + static_cast<std::size_t>(s[k] - '0');
  }
  if (!ok || v->kind != VarKind::TubeVector || i >= v->dim)
    throw ProblemError(doc_.pos(n), "'" + s + "'",
                       "a component " + name + "[i] with i from 0 to " + std::to_string(v->dim - 1) +
                           (v->kind == VarKind::TubeVector ? "" : " (a scalar tube has none: write " + name + ")"));
  return {name, i};
}

void ProblemLoader::read_output(const toml::table& t) {
  const Fields f(doc_, t, "[output]", {"times", "plots", "maps", "truth", "landmarks", "loops"});
  if (const toml::node* ln = f.find("loops")) read_loops(f, *ln);
  if (const toml::node* ln = f.find("landmarks")) {
    const Fields lf(doc_, f.table(*ln, "a table {data = \"NAME\", columns = [\"x\", \"y\"]}"), "[output] landmarks",
                    {"data", "columns"});
    LandmarksSpec l;
    l.pos = doc_.pos(*ln);
    const DataSpec& d = data_table(lf, lf.require("data", "a [data.NAME] table"));
    l.data = d.name;
    const toml::node& cn = lf.require("columns", "two columns [\"x\", \"y\"]");
    const toml::array& a = lf.array(cn, "two columns [\"x\", \"y\"]");
    if (a.size() != 2) throw ProblemError(doc_.pos(cn), describe(cn), "two columns [\"x\", \"y\"]");
    for (const toml::node& c : a) {
      const std::string col = lf.string(c, "a column name");
      require_column(doc_.pos(c), col, d.name, d.table);
    }
    l.x = a.get(0)->as_string()->get();
    l.y = a.get(1)->as_string()->get();
    p_.output.landmarks = l;
  }
  if (const toml::node* ts = f.find("times"))
    for (const toml::node& n : f.array(*ts, "an array of times")) {
      const double v = f.number(n, "a time (number)");
      if (v < p_.time.t0 || v > p_.time.tf)
        throw ProblemError(doc_.pos(n), "the time " + doc_.raw(n) + " outside the domain",
                           "a time in [" + number_text(p_.time.t0) + ", " + number_text(p_.time.tf) + "]");
      const auto [lo, hi] = f.number_as_written(n, "a time (number)");
      p_.output.times.push_back({v, std::max(lo, p_.time.t0), std::min(hi, p_.time.tf)});
    }
  if (const toml::node* ps = f.find("plots"))
    for (const toml::node& n : f.array(*ps, "an array of tubes such as [\"x\", \"v[1]\"]"))
      p_.output.plot_tubes.push_back(tube_ref(f, n, true));
  if (const toml::node* ms = f.find("maps"))
    for (const toml::node& n : f.array(*ms, "an array of pairs such as [[\"x[0]\", \"x[1]\"]]")) {
      const toml::array& a = f.array(n, "a pair [\"x[0]\", \"x[1]\"]");
      if (a.size() != 2) throw ProblemError(doc_.pos(n), describe(n), "a pair [\"x[0]\", \"x[1]\"]");
      const auto i = tube_ref(f, *a.get(0), false), j = tube_ref(f, *a.get(1), false);
      if (i.first != j.first || p_.var(i.first)->kind != VarKind::TubeVector)
        throw ProblemError(doc_.pos(n), "components of different variables", "two components of one tube_vector");
      p_.output.maps.push_back({i.first, {i.second, j.second}});
    }
  if (const toml::node* tr = f.find("truth")) {
    const Fields tf(doc_, f.table(*tr, "a table {data, time, columns}"), "[output.truth]", {"data", "time", "columns"});
    TruthSpec ts;
    ts.pos = doc_.pos(*tr);
    const toml::node& dn = tf.require("data", "a [data.NAME] table");
    ts.data = tf.string(dn, "a data table name");
    const DataSpec* d = p_.table(ts.data);
    if (!d) throw ProblemError(doc_.pos(dn), "the unknown table '" + ts.data + "'", "a [data.NAME] table");
    auto col = [&](const toml::node& n) {
      const std::string c = tf.string(n, "a column name");
      require_column(doc_.pos(n), c, ts.data, d->table);
      return c;
    };
    const toml::node& tn = tf.require("time", "the time column");
    ts.time_column = col(tn);
    for (auto&& [key, node] : tf.table(tf.require("columns", "{var = [columns]}"), "a table {var = [columns]}")) {
      const std::string name(key.str());
      const VarSpec* v = p_.var(name);
      if (!v || !v->is_tube())
        throw ProblemError(doc_.pos(key.source()), "'" + name + "'", "a tube variable (" + known_vars(true) + ")");
      std::vector<std::string> cols;
      if (node.is_string()) cols.push_back(col(node));
      else
        for (const toml::node& c : tf.array(node, "a column name or an array of them")) cols.push_back(col(c));
      if (cols.size() != v->dim)
        throw ProblemError(doc_.pos(node), std::to_string(cols.size()) + " column(s)",
                           std::to_string(v->dim) + " (one per component of '" + name + "')");
      ts.columns[name] = cols;
    }
    // A truth is a trajectory: in time order, each time once (after its columns' own checks).
    require_increasing(doc_.pos(tn), d->table.values(ts.time_column), *d, "a truth with strictly increasing times");
    p_.output.truth = ts;
  }
}

}  // namespace sillage::detail
