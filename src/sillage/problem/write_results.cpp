#include "sillage/problem/write_results.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "sillage/problem/bound_audit.h"
#include "sillage/problem/var_sizes.h"

namespace sillage {

std::size_t decimation(std::size_t n, const OutputOptions& o) {
  return o.max_slices == 0 || n <= o.max_slices ? 1 : (n + o.max_slices - 1) / o.max_slices;
}

namespace {

using nlohmann::json;

// x appended as the shortest decimal that reads back as the same double
// (std::to_chars: exact as "%.17g" is, and about ten times faster on the
// million bounds of a large problem).
void append_number(std::string& out, double x) {
  if (std::isinf(x)) {
    out += x > 0 ? "inf" : "-inf";
    return;
  }
  if (std::isnan(x)) {
    out += "nan";
    return;
  }
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}

// A bound in JSON: a number, null when infinite.
void append_bound(std::string& out, double x) {
  if (std::isfinite(x)) append_number(out, x);
  else out += "null";
}

// Intervals get(0), ..., get(n - 1) as a JSON array of [lb, ub] (null for an empty one).
template <class Get>
void append_intervals(std::string& out, std::size_t n, const Get& get) {
  out += '[';
  for (std::size_t k = 0; k < n; ++k) {
    const Interval x = get(k);
    if (k > 0) out += ", ";
    if (x.is_empty()) {
      out += "null";
      continue;
    }
    out += '[';
    append_bound(out, x.lb());
    out += ", ";
    append_bound(out, x.ub());
    out += ']';
  }
  out += ']';
}

// A tube vector as written (write_results.h): time points 0, g, 2g, ... and
// the last; the gates there and, between two of them, the slice (g = 1) or
// the hull of the slices and gates (empty if one of them is). Read on
// demand: nothing is copied.
class Written {
 public:
  Written(const TubeVector& x, const OutputOptions& o) : x_(x), n_(x.nb_slices()), g_(decimation(n_, o)) {}
  std::size_t nb_points() const { return (n_ + g_ - 1) / g_ + 1; }
  std::size_t point(std::size_t j) const { return std::min(j * g_, n_); }
  Interval gate(std::size_t i, std::size_t j) const { return x_[i].gate(point(j)); }
  Interval slice(std::size_t i, std::size_t j) const {  // between points j and j + 1
    const Tube& c = x_[i];
    const std::size_t a = point(j), b = point(j + 1);
    if (g_ == 1) return c.slice(a);
    Interval h = Interval::empty();
    for (std::size_t k = a; k < b; ++k) {
      const Interval s = c.slice(k), gk = k > a ? c.gate(k) : s;
      if (s.is_empty() || gk.is_empty()) return Interval::empty();
      h |= s;
      h |= gk;
    }
    return h;
  }

 private:
  const TubeVector& x_;
  std::size_t n_, g_;
};

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

json size_json(const SizeStats& s) {  // an unbounded size (+inf) is null, as a bound is
  auto n = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
  return {{"mean", n(s.mean)}, {"median", n(s.median)}, {"max", n(s.max)}, {"samples", s.samples}};
}

// Per variable: its box diameter over time and at the truth's times (var_sizes.h).
json sizes_json(const std::vector<VarSize>& sizes) {
  json out = json::object();
  for (const VarSize& v : sizes) {
    json j = {{"unit", v.unit}, {"over_time", size_json(v.over_time)}};
    if (v.at_truth) j["at_truth"] = size_json(*v.at_truth);
    out[v.name] = j;
  }
  return out;
}

}  // namespace

std::string results_json(const Problem& p, const SolveResult& r, const OutputOptions& o, const Explanation* e) {
  json j;
  j["problem"] = p.file;
  j["hash"] = p.hash;
  j["status"] = r.empty ? "no solution" : !r.stopped.empty() ? "stopped" : "solved";
  if (r.empty) j["why"] = r.why_empty;
  if (r.empty) j["before_empty"] = r.before_empty.has_value();
  if (e) j["explanation"] = json::parse(explanation_json(*e));
  if (!r.stopped.empty()) j["why"] = r.stopped;
  // The one outcome type of long computations (outcome.h), as in C++ and Python.
  j["summary"] = {{"status", status_name(r.summary.status)},
                  {"reason", r.summary.reason},
                  {"rounds", r.summary.rounds},
                  {"work", r.summary.work},
                  {"seconds", r.summary.seconds}};
  j["warnings"] = r.warnings;
  // The box diameter (the largest width over the components) of each variable; none without a solution.
  if (!r.empty) j["sizes"] = sizes_json(var_sizes(p, r.built));
  // With a truth: how much of each stated bound it used (bound_audit.h); null: not measurable.
  if (p.output.truth) {
    j["bound_audit"] = json::array();
    auto n = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
    for (const AuditLine& l : audit_problem(p))
      j["bound_audit"].push_back({{"bound", l.name}, {"unit", l.unit}, {"allowed", n(l.allowed)}, {"used", n(l.used)},
                                  {"percent", n(audit_percent(l))}, {"how", l.how}});
  }
  // Eval rows skipped as outside [t0, tf] (outside = "skip"), per constraint label.
  json outside = json::object();
  for (const ConstraintSpec& c : p.constraints)
    if (c.nb_outside > 0) outside[c.label] = c.nb_outside;
  j["rows_outside"] = outside;
  j["scheduling"] = scheduling_name(r.scheduling);
  j["schedule"] = json::array();
  for (const ScheduleStep& s : r.schedule) j["schedule"].push_back(stats_json(s));
  const TDomain& td = *r.built.td;
  const std::size_t g = decimation(td.nb_slices(), o);
  std::vector<double> times;
  for (std::size_t k = 0; k < td.nb_slices(); k += g) times.push_back(td.t(k));
  times.push_back(td.tf());
  j["times"] = times;
  j["decimated"] = g;  // 1: every slice; g: every g-th time point, hulls between them
  // The variables are written as text, not as a JSON tree: a tree of their
  // million bounds (plaza1) took most of the time and memory of the output.
  std::string out = j.dump(1);
  out.erase(out.find_last_of('}'));  // reopened to append "variables"
  while (!out.empty() && std::isspace(static_cast<unsigned char>(out.back()))) out.pop_back();
  out += ",\n \"variables\": {";
  for (std::size_t n = 0; n < r.built.vars.size(); ++n) {
    const VarDomain& v = r.built.vars[n];
    out += n == 0 ? "\n  " : ",\n  ";
    out += json(v.spec->name).dump() + ": {\"kind\": " + json(kind_name(v.spec->kind)).dump() +
           ", \"dim\": " + std::to_string(v.spec->dim);
    if (v.tubes) {
      out += ", \"components\": [";
      const Written w(*v.tubes, o);
      for (std::size_t i = 0; i < v.tubes->size(); ++i) {
        out += i == 0 ? "{\"gates\": " : ", {\"gates\": ";
        append_intervals(out, w.nb_points(), [&](std::size_t j) { return w.gate(i, j); });
        out += ", \"slices\": ";
        append_intervals(out, w.nb_points() - 1, [&](std::size_t j) { return w.slice(i, j); });
        out += "}";
      }
      out += "]";
    } else {
      out += ", \"value\": ";
      const std::vector<Interval> value = v.interval ? std::vector<Interval>{*v.interval} : v.box->components();
      append_intervals(out, value.size(), [&](std::size_t k) { return value[k]; });
    }
    out += "}";
  }
  out += "\n }\n}";
  return out;
}

std::string tube_csv(const VarDomain& v, const OutputOptions& o) {
  const TubeVector& x = *v.tubes;
  const TDomain& td = *x.tdomain();
  const Written w(x, o);
  std::string out = "t_lb,t_ub";
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::string n = v.spec->kind == VarKind::Tube ? v.spec->name : v.spec->name + std::to_string(i);
    out += "," + n + "_lb," + n + "_ub";
  }
  out += "\n";
  auto row = [&](double ta, double tb, auto get) {
    append_number(out, ta);
    out += ',';
    append_number(out, tb);
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Interval y = get(i);
      if (y.is_empty()) {
        out += ",nan,nan";
        continue;
      }
      out += ',';
      append_number(out, y.lb());
      out += ',';
      append_number(out, y.ub());
    }
    out += '\n';
  };
  for (std::size_t j = 0; j < w.nb_points(); ++j) {
    const double t = td.t(w.point(j));
    row(t, t, [&](std::size_t i) { return w.gate(i, j); });
    if (j + 1 < w.nb_points()) row(t, td.t(w.point(j + 1)), [&](std::size_t i) { return w.slice(i, j); });
  }
  return out;
}

void write_text_file(const std::string& dir, const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::path(dir) / name).string();
  std::ofstream os(path, std::ios::binary);
  if (!os || !(os << text)) throw Error("cannot write " + path);
}

std::vector<std::string> output_names(const Problem& p, bool tube_files) {
  std::vector<std::string> names{"results.json", "report.html"};
  for (const VarSpec& v : p.vars) {
    if (!v.is_tube()) continue;
    names.push_back(v.name + ".csv");
    if (tube_files) names.push_back(v.name + ".tube");
  }
  return names;
}

void check_output_dir(const Problem& p, const std::string& dir, bool tube_files) {
  check_output_dir(p, dir, output_names(p, tube_files));
}

void check_output_dir(const Problem& p, const std::string& dir, const std::vector<std::string>& names) {
  std::vector<std::pair<std::string, std::string>> inputs{{p.file, "the problem file"}};
  for (const DataSpec& d : p.data) inputs.push_back({d.path, "the table '" + d.name + "' (" + d.pos.str() + ")"});
  for (const std::string& name : names) {
    const std::filesystem::path out = std::filesystem::path(dir) / name;
    for (const auto& [path, what] : inputs) {
      std::error_code ec;  // false with an error when either does not exist: nothing to overwrite
      if (std::filesystem::equivalent(out, path, ec))
        throw Error("the output " + out.string() + " would overwrite " + what + ", " + path +
                    ": choose another output directory (--out)");
    }
  }
}

void write_results(const Problem& p, const SolveResult& r, const std::string& dir, const OutputOptions& o,
                   const Explanation* e) {
  check_output_dir(p, dir, false);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error("cannot create the directory " + dir + ": " + ec.message());
  write_text_file(dir, "results.json", results_json(p, r, o, e));
  for (const VarDomain& v : r.built.vars)
    if (v.tubes) write_text_file(dir, v.spec->name + ".csv", tube_csv(v, o));
}

}  // namespace sillage
