#include "sillage/problem/stream_lines.h"

#include <nlohmann/json.hpp>

#include "sillage/error.h"
#include "sillage/outcome.h"

namespace sillage {

using nlohmann::json;
using nlohmann::ordered_json;

namespace {

double number_of(const json& v, const std::string& what) {
  if (!v.is_number()) throw Error(what + " is " + std::string(v.type_name()) + " " + v.dump() + ", not a number");
  return v.get<double>();
}

}  // namespace

StreamRow parse_stream_line(const std::string& line) {
  json j;
  try {
    j = json::parse(line);
  } catch (const json::parse_error& e) {
    throw Error("not JSON: " + std::string(e.what()));
  }
  if (!j.is_object()) throw Error("a JSON " + std::string(j.type_name()) + ", not an object {\"table\": ..., \"t\": ..., \"columns\": {...}}");
  StreamRow row;
  for (const auto& [key, v] : j.items()) {
    if (key == "table") {
      if (!v.is_string()) throw Error("\"table\" is " + std::string(v.type_name()) + ", not a table's name");
      row.table = v.get<std::string>();
      if (row.table.empty()) throw Error("\"table\" is empty");
    } else if (key == "t") {
      row.t = number_of(v, "\"t\"");
    } else if (key == "columns") {
      if (!v.is_object()) throw Error("\"columns\" is " + std::string(v.type_name()) + ", not an object {\"column\": value}");
      for (const auto& [name, x] : v.items()) row.columns[name] = number_of(x, "column \"" + name + "\"");
    } else {
      throw Error("unknown key \"" + key + "\" (keys: table, t, columns)");
    }
  }
  if (row.table.empty() && !row.columns.empty()) throw Error("\"columns\" without \"table\"");
  if (row.table.empty() && !row.t) throw Error("an empty row: neither \"table\" nor \"t\"");
  return row;
}

std::string stream_line(const StreamRow& row) {
  ordered_json j;
  if (!row.table.empty()) j["table"] = row.table;
  if (row.t) j["t"] = *row.t;
  if (!row.columns.empty()) {
    ordered_json cols = ordered_json::object();
    for (const auto& [name, value] : row.columns) cols[name] = value;
    j["columns"] = cols;
  }
  return j.dump();
}

std::string estimate_line(const OnlineProblem& op) {
  const OnlineEstimator& est = op.estimator();
  ordered_json j;
  j["t"] = est.now();
  const Summary& s = est.last_update().summary;
  j["status"] = status_name(s.status);
  if (s.status == Status::NoSolution) j["reason"] = s.reason;
  j["window"] = {est.window_start(), est.now()};
  for (const std::string& name : op.outputs()) {
    const IntervalVector x = est.now(name);
    ordered_json box = ordered_json::array();
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (x[i].is_empty()) box.push_back(nullptr);
      else box.push_back({x[i].lb(), x[i].ub()});
    }
    j[name] = box;
  }
  return j.dump();
}

}  // namespace sillage
