#include "sillage/problem/write_results.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

namespace sillage {

namespace {

using nlohmann::json;

json bound(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json interval(const Interval& x) {
  if (x.is_empty()) return nullptr;
  return json::array({bound(x.lb()), bound(x.ub())});
}

std::string csv_number(double x) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  if (std::isnan(x)) return "nan";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

json stats_json(const ScheduleStep& s) {
  return {{"delta", s.delta},
          {"slices", s.slices},
          {"mean_thickness", s.mean_thickness},
          {"rounds", s.stats.iterations},
          {"contractor_calls", s.stats.contractor_calls},
          {"build_seconds", s.build_seconds},
          {"contract_seconds", s.contract_seconds},
          {"empty", s.stats.empty}};
}

}  // namespace

std::string results_json(const Problem& p, const SolveResult& r) {
  json j;
  j["problem"] = p.file;
  j["hash"] = p.hash;
  j["status"] = r.empty ? "no solution" : "solved";
  if (r.empty) j["why"] = r.why_empty;
  // Eval rows skipped as outside [t0, tf] (outside = "skip"), per constraint label.
  json outside = json::object();
  for (const ConstraintSpec& c : p.constraints)
    if (c.nb_outside > 0) outside[c.label] = c.nb_outside;
  j["rows_outside"] = outside;
  j["scheduling"] = scheduling_name(r.scheduling);
  j["schedule"] = json::array();
  for (const ScheduleStep& s : r.schedule) j["schedule"].push_back(stats_json(s));
  const TDomain& td = *r.built.td;
  j["times"] = std::vector<double>(td.times().begin(), td.times().end());
  json vars = json::object();
  for (const VarDomain& v : r.built.vars) {
    json jv{{"kind", kind_name(v.spec->kind)}, {"dim", v.spec->dim}};
    if (v.tubes) {
      json comps = json::array();
      for (std::size_t i = 0; i < v.tubes->size(); ++i) {
        const Tube& x = (*v.tubes)[i];
        json gates = json::array(), slices = json::array();
        for (const Interval& g : x.gates()) gates.push_back(interval(g));
        for (const Interval& s : x.slices()) slices.push_back(interval(s));
        comps.push_back({{"gates", gates}, {"slices", slices}});
      }
      jv["components"] = comps;
    } else if (v.interval) {
      jv["value"] = json::array({interval(*v.interval)});
    } else {
      json vals = json::array();
      for (std::size_t i = 0; i < v.box->size(); ++i) vals.push_back(interval((*v.box)[i]));
      jv["value"] = vals;
    }
    vars[v.spec->name] = jv;
  }
  j["variables"] = vars;
  return j.dump(1);
}

std::string tube_csv(const VarDomain& v) {
  const TubeVector& x = *v.tubes;
  const TDomain& td = *x.tdomain();
  std::string out = "t_lb,t_ub";
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::string n = v.spec->kind == VarKind::Tube ? v.spec->name : v.spec->name + std::to_string(i);
    out += "," + n + "_lb," + n + "_ub";
  }
  out += "\n";
  auto row = [&](double ta, double tb, auto get) {
    out += csv_number(ta) + "," + csv_number(tb);
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Interval y = get(x[i]);
      out += "," + (y.is_empty() ? std::string("nan,nan") : csv_number(y.lb()) + "," + csv_number(y.ub()));
    }
    out += "\n";
  };
  for (std::size_t k = 0; k <= td.nb_slices(); ++k) {
    row(td.t(k), td.t(k), [k](const Tube& c) { return c.gate(k); });
    if (k < td.nb_slices()) row(td.t(k), td.t(k + 1), [k](const Tube& c) { return c.slice(k); });
  }
  return out;
}

void write_text_file(const std::string& dir, const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::path(dir) / name).string();
  std::ofstream os(path, std::ios::binary);
  if (!os || !(os << text)) throw Error("cannot write " + path);
}

void write_results(const Problem& p, const SolveResult& r, const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error("cannot create the directory " + dir + ": " + ec.message());
  write_text_file(dir, "results.json", results_json(p, r));
  for (const VarDomain& v : r.built.vars)
    if (v.tubes) write_text_file(dir, v.spec->name + ".csv", tube_csv(v));
}

}  // namespace sillage
