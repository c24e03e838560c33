// [time]: the domain and δ, or the time points of a table's column.
#include "sillage/problem/problem_loader.h"

#include "sillage/problem/eval_rows.h"

namespace sillage::detail {

void ProblemLoader::read_time(const toml::table& t) {
  const Fields f(doc_, t, "[time]", {"domain", "delta", "points"});
  if (const toml::node* pn = f.find("points")) return read_time_points(f, *pn);
  const toml::node& d = f.require("domain", "[t0, tf]");
  const toml::array& a = f.array(d, "[t0, tf], two numbers");
  if (a.size() != 2) throw ProblemError(doc_.pos(d), describe(d), "[t0, tf], two numbers");
  p_.time.t0 = f.number(*a.get(0), "a number t0");
  p_.time.tf = f.number(*a.get(1), "a number tf");
  p_.time.pos = doc_.pos(d);
  if (!(p_.time.t0 < p_.time.tf))
    throw ProblemError(doc_.pos(d), "t0 >= tf", "a time domain [t0, tf] with t0 < tf");
  const toml::node& dl = f.require("delta", "a slice width (number) or \"auto\"");
  if (dl.is_string()) {
    if (dl.as_string()->get() != "auto") throw ProblemError(doc_.pos(dl), describe(dl), "a number or \"auto\"");
  } else {
    const double v = f.number(dl, "a slice width (number > 0) or \"auto\"");
    if (!(v > 0) || v > p_.time.tf - p_.time.t0)
      throw ProblemError(doc_.pos(dl), "delta = " + doc_.raw(dl), "a slice width in (0, tf - t0]");
    if ((p_.time.tf - p_.time.t0) / v > kMaxSlices)
      throw ProblemError(doc_.pos(dl), "delta = " + doc_.raw(dl) + " (more than " + number_text(kMaxSlices) + " slices)", "a larger delta");
    p_.time.delta = v;
  }
}

// [time] points = {data, column}: the stamps of a table.
void ProblemLoader::read_time_points(const Fields& f, const toml::node& pn) {
  for (const char* k : {"domain", "delta"})
    if (const toml::node* n = f.find(k))
      throw ProblemError(doc_.pos(*n), std::string("'") + k + "' with 'points'",
                         "either points = {data, column} or domain and delta");
  const Fields pf(doc_, f.table(pn, "a table {data = \"NAME\", column = \"t\"}"), "[time] points", {"data", "column"});
  const toml::node& dn = pf.require("data", "a [data.NAME] table");
  const DataSpec& d = data_table(pf, dn);
  const toml::node& cn = pf.require("column", "its time column");
  const std::string col = pf.string(cn, "a column name (string)");
  require_column(doc_.pos(cn), col, d.name, d.table);
  p_.time.points = d.table.values(col);
  p_.time.points_data = d.name;
  p_.time.pos = doc_.pos(pn);
  if (p_.time.points.size() < 2)
    throw ProblemError(doc_.pos(cn), std::to_string(p_.time.points.size()) + " time point(s)", "at least 2");
  require_increasing(doc_.pos(cn), p_.time.points, d, "strictly increasing time points");
  p_.time.t0 = p_.time.points.front();
  p_.time.tf = p_.time.points.back();
}

}  // namespace sillage::detail
