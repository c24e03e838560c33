#include "sillage/problem/eval_rows.h"

#include <algorithm>
#include <charconv>
#include <optional>
#include <span>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "sillage/expr/tape.h"
#include "sillage/interval/rounding.h"

namespace sillage::detail {

// rounding.h's steps rather than std::nextafter: the same doubles without a
// libm call (plaza1.toml reads about 10 000 cells; nextafter was 5 % of its build).
Interval csv_cell(double d) { return Interval(rounding::next_down(d), rounding::next_up(d)); }

std::string cell_text(double d) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, d).ptr);
}

void check_join_keys(const ConstraintSpec& c, const CsvTable& table, const CsvTable& joined, const SourcePos& at) {
  const std::vector<double> keys = joined.values(c.join_on);
  std::unordered_map<double, std::size_t> known;  // key -> its first row
  for (std::size_t row = 0; row < keys.size(); ++row) {
    const auto [it, fresh] = known.emplace(keys[row], row);
    const std::span<const double> a = joined.row(it->second), b = joined.row(row);
    // The same key twice: which row a measurement joins would decide the answer.
    if (!fresh && !std::equal(a.begin(), a.end(), b.begin(), b.end(), [](double x, double y) {
          return x == y || (std::isnan(x) && std::isnan(y));  // text cells are NaN: compared by the columns read
        }))
      throw ProblemError(at, "the " + c.join_on + " " + cell_text(keys[row]) + " in two rows of '" + c.join_data +
                                 "' with other values: " + joined.where(it->second) + " and line " +
                                 std::to_string(joined.line(row)),
                         "one row per " + c.join_on + " in the joined table");
  }
  const std::size_t on = table.column(c.join_on);
  for (std::size_t row = 0; row < table.nb_rows(); ++row) {
    const std::span<const double> values = table.row(row);
    if (!eval_row_kept(c, table, values) || known.count(values[on])) continue;
    throw ProblemError(at, "the row of '" + c.data + "' at " + table.where(row) + " with " + c.join_on + " = " +
                               cell_text(values[on]) + ", which is in no row of '" + c.join_data + "'",
                       "a row of '" + c.join_data + "' with that " + c.join_on + " ('where' leaves rows out)");
  }
}

bool eval_row_kept(const ConstraintSpec& c, const CsvTable& table, std::span<const double> values) {
  for (const auto& [col, range] : c.where) {
    const double v = values[table.column(col)];
    if (!(v >= range.first && v <= range.second)) return false;
  }
  return true;
}

std::vector<std::size_t> read_vars(const Function& f) {
  std::unordered_set<std::string> names;
  for (const Expr& e : detail::topological_order(f.exprs()))
    if (e.op() == Op::Var) names.insert(e.node().name);
  std::vector<std::size_t> read;
  for (std::size_t i = 0; i < f.nb_vars(); ++i)
    if (names.count(f.var_names()[i])) read.push_back(i);
  return read;
}

std::vector<std::vector<std::size_t>> outlier_groups(const ConstraintSpec& c, const std::vector<Interval>& row_times) {
  const std::size_t q = c.q.value_or(0), n = row_times.size();
  std::vector<std::vector<std::size_t>> groups;
  const auto keep = [&](std::vector<std::size_t> g) {
    if (g.size() > q) groups.push_back(std::move(g));
  };
  if (c.q_rows > 0) {
    const std::size_t step = std::max<std::size_t>(1, c.q_rows / 2);
    for (std::size_t first = 0; first < n; first += step) {
      std::vector<std::size_t> g;
      for (std::size_t i = first; i < std::min(n, first + c.q_rows); ++i) g.push_back(i);
      keep(std::move(g));
      if (first + c.q_rows >= n) break;
    }
  } else if (c.q_window > 0 && n > 0) {
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return row_times[a].mid() < row_times[b].mid(); });
    const double s0 = row_times[order.front()].mid(), last = row_times[order.back()].mid();
    std::size_t from = 0;
    for (std::size_t k = 0;; ++k) {
      const double a = s0 + static_cast<double>(k) * c.q_window / 2, b = a + c.q_window;
      while (from < n && row_times[order[from]].mid() < a) ++from;
      std::vector<std::size_t> g;
      for (std::size_t j = from; j < n && row_times[order[j]].mid() <= b; ++j) g.push_back(order[j]);
      keep(std::move(g));
      if (b >= last) break;
    }
  } else {
    std::vector<std::size_t> g(n);
    for (std::size_t i = 0; i < n; ++i) g[i] = i;
    keep(std::move(g));
  }
  return groups;
}

Interval eval_row_time(const ConstraintSpec& c, const CsvTable& table, std::span<const double> values,
                       const Interval& terr, const Interval& domain) {
  if (c.time_columns.empty()) return domain;
  Interval t = csv_cell(values[table.column(c.time_columns[0])]);
  if (c.time_columns.size() == 2) t |= csv_cell(values[table.column(c.time_columns[1])]);
  return (t + Interval(-1, 1) * terr) & domain;
}

namespace {

bool eval_has_column(const Problem& p, const ConstraintSpec& c, const std::string& n) {
  return p.table(c.data)->table.has_column(n) || (!c.join_data.empty() && p.table(c.join_data)->table.has_column(n));
}

bool evaluated(const ConstraintSpec& c, const std::string& n) {
  return std::find(c.ys.begin(), c.ys.end(), n) != c.ys.end();
}

}  // namespace

RewrittenExpr eval_observation(const Problem& p, const ConstraintSpec& c) {
  const auto dims = [&](const std::string& n) -> std::optional<std::size_t> {
    if (evaluated(c, n)) return p.var(n)->dim;
    if (eval_has_column(p, c, n)) return 1;
    const VarSpec* v = p.var(n);
    return v ? std::optional<std::size_t>(v->dim) : std::nullopt;
  };
  const auto vec = [&](const std::string& n) {
    if (evaluated(c, n)) return p.var(n)->kind == VarKind::TubeVector;
    const VarSpec* v = p.var(n);
    return !eval_has_column(p, c, n) && v && (v->kind == VarKind::TubeVector || v->kind == VarKind::Box);
  };
  return rewrite_refs(c.expr, c.expr_pos, dims, vec, "");
}

std::vector<std::size_t> implied_derivs(const Problem& p, const ConstraintSpec& c) {
  std::vector<std::size_t> out;
  for (std::size_t j = 0; j < c.ys.size(); ++j) {
    const bool written = std::any_of(p.constraints.begin(), p.constraints.end(), [&](const ConstraintSpec& d) {
      return d.kind == ConstraintKind::Deriv && d.x == c.ys[j] && d.v == c.vs[j];
    });
    if (!c.vs[j].empty() && !written) out.push_back(j);
  }
  return out;
}

bool eval_rows_listed(const Problem& p, const ConstraintSpec& c, const RewrittenExpr& r) {
  return c.ys.size() == 1 && !c.vs[0].empty() && !p.var(c.ys[0])->angle && std::all_of(r.refs.begin(), r.refs.end(), [&](const VarRef& ref) {
           return evaluated(c, ref.var) || eval_has_column(p, c, ref.var);
         });
}

RowObservation::RowObservation(std::shared_ptr<const Ctc> obs, std::shared_ptr<const std::vector<int>> slots,
                               std::size_t nz, IntervalVector values)
    : Ctc(nz), obs_(std::move(obs)), slots_(std::move(slots)), values_(std::move(values)) {}

void RowObservation::contract(IntervalVector& z) const {
  check_dim(z);
  thread_local IntervalVector box(1);  // scratch, per thread
  const std::vector<int>& slots = *slots_;
  if (box.size() != slots.size()) box = IntervalVector(slots.size());
  std::size_t v = 0;
  for (std::size_t k = 0; k < slots.size(); ++k) box[k] = slots[k] >= 0 ? z[static_cast<std::size_t>(slots[k])] : values_[v++];
  obs_->contract(box);
  if (box.is_empty()) {  // a value emptied is the row's inconsistency too, whatever the contractor
    z.set_empty();
    return;
  }
  for (std::size_t k = 0; k < slots.size(); ++k)
    if (slots[k] >= 0) z[static_cast<std::size_t>(slots[k])] &= box[k];
}

}  // namespace sillage::detail
