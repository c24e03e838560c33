#include "sillage/problem/explain_items.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <tuple>

#include "sillage/problem/eval_rows.h"

namespace sillage {

const char* kind_name(ItemKind k) {
  switch (k) {
    case ItemKind::Bound: return "bound";
    case ItemKind::Gate: return "gate";
    case ItemKind::TableBound: return "table bound";
    case ItemKind::Constraint: return "constraint";
    case ItemKind::Rows: return "rows";
  }
  return "?";
}

std::string ExplainItem::str() const {
  // file:line: the column adds nothing a reader needs to find the statement.
  return label + " (" + pos.file + (pos.line > 0 ? ":" + std::to_string(pos.line) : "") + ")";
}

namespace {

std::string joined(const std::vector<BoundSpec>& bounds) {
  if (bounds.size() == 1) return bounds[0].expr;
  std::string s = "[";
  for (std::size_t i = 0; i < bounds.size(); ++i) s += (i ? ", \"" : "\"") + bounds[i].expr + "\"";
  return s + "]";
}

void add_var_items(const VarSpec& v, std::vector<ExplainItem>& items) {
  const std::string head = "[var." + v.name + "]";
  for (std::size_t i = 0; i < v.value.size(); ++i) {
    if (v.value[i].expr.empty()) continue;  // the whole line already: nothing to relax
    ExplainItem it;
    it.kind = ItemKind::Bound;
    it.label = head + " value" + (v.dim > 1 ? "[" + std::to_string(i) + "]" : "");
    it.pos = v.value[i].pos;
    it.stated = v.value[i].expr;
    it.var = v.name;
    it.index = i;
    items.push_back(std::move(it));
  }
  for (std::size_t g = 0; g < v.at.size(); ++g) {
    ExplainItem it;
    it.kind = ItemKind::Gate;
    it.label = head + " at t = " + detail::cell_text(v.at[g].t);
    it.pos = v.at[g].pos;
    it.stated = joined(v.at[g].value);
    it.time = Interval(v.at[g].t_lo, v.at[g].t_hi);
    it.var = v.name;
    it.index = g;
    items.push_back(std::move(it));
  }
  for (const bool gates : {false, true}) {
    const std::optional<SliceDataSpec>& s = gates ? v.gates : v.slices;
    if (!s) continue;
    ExplainItem it;
    it.kind = ItemKind::TableBound;
    it.label = head + (gates ? " gates" : " slices") + " from " + s->data;
    it.pos = s->value.pos;
    it.stated = s->value.expr;
    it.var = v.name;
    it.index = gates ? 1 : 0;
    items.push_back(std::move(it));
  }
}

// The kept rows of eval c (its `where`, a time within [t0, tf]): table rows and their times.
struct KeptRows {
  std::vector<std::size_t> rows;
  std::vector<Interval> times;
  Interval hull(std::size_t a, std::size_t b) const {  // of the times of kept rows [a, b)
    Interval h = Interval::empty();
    for (std::size_t k = a; k < b; ++k) h |= times[k];
    return h;
  }
};

KeptRows kept_rows(const Problem& p, const ConstraintSpec& c) {
  const CsvTable& table = p.table(c.data)->table;
  const Interval terr = Function(std::vector<std::string>{}, c.time_error).eval(IntervalVector(0));
  KeptRows k;
  for (std::size_t r = 0; r < table.nb_rows(); ++r) {
    if (!detail::eval_row_kept(c, table, table.row(r))) continue;
    const Interval t = detail::eval_row_time(c, table, table.row(r), terr, Interval(p.time.t0, p.time.tf));
    if (t.is_empty()) continue;
    k.rows.push_back(r);
    k.times.push_back(t);
  }
  return k;
}

}  // namespace

std::vector<ExplainItem> explain_items(const Problem& p) {
  std::vector<ExplainItem> items;
  for (const VarSpec& v : p.vars) add_var_items(v, items);
  for (std::size_t i = 0; i < p.constraints.size(); ++i) {
    const ConstraintSpec& c = p.constraints[i];
    ExplainItem it;
    it.kind = c.kind == ConstraintKind::Eval ? ItemKind::Rows : ItemKind::Constraint;
    it.label = c.label;
    it.pos = c.pos;
    it.index = i;
    if (c.kind == ConstraintKind::Eval) {
      const KeptRows k = kept_rows(p, c);
      if (k.rows.empty()) continue;  // states nothing
      it.first_row = k.rows.front();
      it.last_row = k.rows.back() + 1;
      it.nb_rows = k.rows.size();
      it.time = k.hull(0, k.rows.size());
    }
    items.push_back(std::move(it));
  }
  // In the order of the file (the variables are read as TOML tables, by name).
  std::stable_sort(items.begin(), items.end(), [](const ExplainItem& a, const ExplainItem& b) {
    return std::tie(a.pos.line, a.pos.column) < std::tie(b.pos.line, b.pos.column);
  });
  return items;
}

std::vector<ExplainItem> row_runs(const Problem& p, const ExplainItem& rows, std::size_t parts) {
  const ConstraintSpec& c = p.constraints.at(rows.index);
  KeptRows all = kept_rows(p, c), in;  // the kept rows of the run `rows`
  for (std::size_t k = 0; k < all.rows.size(); ++k) {
    if (all.rows[k] < rows.first_row || all.rows[k] >= rows.last_row) continue;
    in.rows.push_back(all.rows[k]);
    in.times.push_back(all.times[k]);
  }
  const std::vector<std::size_t>& kept = in.rows;
  const CsvTable& table = p.table(c.data)->table;
  std::vector<ExplainItem> runs;
  const std::size_t n = kept.size(), k = std::min(parts, n);
  for (std::size_t j = 0; j < k; ++j) {
    const std::size_t a = j * n / k, b = (j + 1) * n / k;  // kept rows [a, b)
    if (a == b) continue;
    ExplainItem it = rows;
    it.all_rows = false;
    it.first_row = kept[a];
    it.last_row = kept[b - 1] + 1;
    it.nb_rows = b - a;
    it.time = in.hull(a, b);
    const std::size_t l0 = table.line(kept[a]), l1 = table.line(kept[b - 1]);
    const std::string lines = l0 == l1 ? std::to_string(l0) : std::to_string(l0) + "-" + std::to_string(l1);
    it.label = c.data + (l0 == l1 ? " line " + std::to_string(l0) : " lines " + std::to_string(l0) + " to " + std::to_string(l1)) +
               " (" + std::to_string(it.nb_rows) + (it.nb_rows == 1 ? " row" : " rows") + " of " +
               c.label.substr(0, c.label.find(':')) + ", " + std::filesystem::path(table.source()).filename().string() +
               ":" + lines + ")";
    runs.push_back(std::move(it));
  }
  return runs;
}

Problem relaxed_problem(const Problem& p, const std::vector<ExplainItem>& items, const std::vector<std::size_t>& relaxed) {
  Problem q = p;
  std::vector<bool> dropped(q.constraints.size(), false);
  std::map<std::string, std::vector<std::size_t>> gates_dropped;  // per variable, the entries of `at`
  std::map<std::size_t, std::vector<std::pair<std::size_t, std::size_t>>> runs;  // per eval, the rows dropped
  for (const std::size_t i : relaxed) {
    const ExplainItem& it = items.at(i);
    VarSpec* v = nullptr;
    for (VarSpec& s : q.vars)
      if (s.name == it.var) v = &s;
    switch (it.kind) {
      case ItemKind::Bound: v->value.at(it.index).expr.clear(); break;
      case ItemKind::Gate: gates_dropped[it.var].push_back(it.index); break;
      case ItemKind::TableBound: (it.index ? v->gates : v->slices).reset(); break;
      case ItemKind::Constraint: dropped.at(it.index) = true; break;
      case ItemKind::Rows:
        if (it.all_rows) dropped.at(it.index) = true;
        else runs[it.index].push_back({it.first_row, it.last_row});
        break;
    }
  }
  // An eval with runs dropped reads a copy of its table without them (other statements may read
  // the table), the runs removed from the last one so that the rows before keep their indices.
  for (auto& [ci, ranges] : runs) {
    ConstraintSpec& c = q.constraints.at(ci);
    DataSpec d = *p.table(c.data);
    std::sort(ranges.begin(), ranges.end());
    std::size_t end = d.table.nb_rows();
    for (auto r = ranges.rbegin(); r != ranges.rend(); ++r) {
      const std::size_t last = std::min(r->second, end);  // overlapping runs: what is left of this one
      if (r->first < last) d.table = d.table.without_rows(r->first, last);
      end = std::min(end, r->first);
    }
    d.name += " (runs of rows relaxed)";
    c.data = d.name;
    q.data.push_back(std::move(d));
  }
  for (auto& [name, entries] : gates_dropped) {
    for (VarSpec& s : q.vars) {
      if (s.name != name) continue;
      std::vector<GateSpec> kept;
      for (std::size_t g = 0; g < s.at.size(); ++g)
        if (std::find(entries.begin(), entries.end(), g) == entries.end()) kept.push_back(s.at[g]);
      s.at = std::move(kept);
    }
  }
  std::vector<ConstraintSpec> kept;
  for (std::size_t i = 0; i < q.constraints.size(); ++i)
    if (!dropped[i]) kept.push_back(std::move(q.constraints[i]));
  q.constraints = std::move(kept);
  return q;
}

}  // namespace sillage
