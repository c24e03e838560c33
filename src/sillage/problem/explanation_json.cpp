// explanation_json: the explanation for programs (results.json).
#include <cmath>

#include <nlohmann/json.hpp>

#include "sillage/problem/explain_empty.h"

namespace sillage {

namespace {

using nlohmann::json;

json interval_json(const Interval& x) {
  if (x.is_empty()) return nullptr;
  const auto bound = [](double b) { return std::isfinite(b) ? json(b) : json(nullptr); };
  return json::array({bound(x.lb()), bound(x.ub())});
}

json item_json(const ExplainItem& it) {
  json j = {{"label", it.label}, {"kind", kind_name(it.kind)}, {"file", it.pos.file}, {"line", it.pos.line},
            {"stated", it.stated}, {"time", interval_json(it.time)}};
  if (it.kind == ItemKind::Rows) j["rows"] = it.nb_rows;
  return j;
}

}  // namespace

std::string explanation_json(const Explanation& e) {
  json j = {{"empty", e.empty}, {"why_empty", e.why_empty}, {"delta", e.delta},     {"slices", e.slices},
            {"complete", e.complete}, {"stopped", e.stopped}, {"seconds", e.seconds}, {"trials", e.trials.size()}};
  j["relaxations"] = json::array();
  for (const Relaxation& r : e.relaxations) {
    json x = {{"minimal", r.minimal}, {"items", json::array()}, {"values", json::array()}};
    for (const std::size_t i : r.items) x["items"].push_back(item_json(e.items[i]));
    for (const ProvenValue& v : r.values) {
      json pieces = json::array();
      for (const Interval& piece : v.pieces) pieces.push_back(interval_json(piece));
      x["values"].push_back({{"what", v.what}, {"stated", interval_json(v.stated)}, {"proven", interval_json(v.proven)},
                             {"window", interval_json(v.window)}, {"pieces", pieces}, {"disjoint", v.disjoint()}});
    }
    j["relaxations"].push_back(std::move(x));
  }
  return j.dump(1);
}

}  // namespace sillage
