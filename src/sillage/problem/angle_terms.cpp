#include "sillage/problem/angle_terms.h"

#include <algorithm>
#include <cctype>

#include "sillage/ctc/ctc_angle_equation.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/expr/function.h"

namespace sillage::detail {

namespace {

bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// Whether the sign at text[i] is a number's exponent (1e-5), not an operator.
bool exponent_sign(const std::string& text, std::size_t i) {
  if (i < 2 || (text[i - 1] != 'e' && text[i - 1] != 'E')) return false;
  std::size_t j = i - 1;
  while (j > 0 && (std::isdigit(static_cast<unsigned char>(text[j - 1])) || text[j - 1] == '.')) --j;
  return j < i - 1 && (j == 0 || !ident_char(text[j - 1]));
}

// Every angle identifier of `term` must stand under sin, cos or tan.
void check_periodic(const std::string& term, const std::set<std::string>& angle_ids, const SourcePos& pos,
                    const std::string& what) {
  std::vector<bool> periodic;  // per open parenthesis: a periodic function's
  std::size_t i = 0;
  while (i < term.size()) {
    const char c = term[i];
    if (ident_char(c) && !std::isdigit(static_cast<unsigned char>(c))) {
      std::size_t j = i;
      while (j < term.size() && ident_char(term[j])) ++j;
      const std::string id = term.substr(i, j - i);
      std::size_t k = j;
      while (k < term.size() && term[k] == ' ') ++k;
      if (k < term.size() && term[k] == '(') {
        periodic.push_back(id == "sin" || id == "cos" || id == "tan" || (!periodic.empty() && periodic.back()));
        i = k + 1;
        continue;
      }
      const bool under = !periodic.empty() && periodic.back();
      if (angle_ids.count(id) && !under)
        throw ProblemError(pos, "the angle '" + id + "' in " + what + " outside sin, cos, tan and the top-level sum",
                           "an angle (angle = true) read as sin/cos/tan(...) or as a term + " + id + " or - " + id +
                               " of the expression (the equation is then modulo 2 pi)");
      i = j;
      continue;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {  // a number, exponent included
      while (i < term.size() && (ident_char(term[i]) || term[i] == '.' || ((term[i] == '-' || term[i] == '+') && exponent_sign(term, i)))) ++i;
      continue;
    }
    if (c == '(') periodic.push_back(!periodic.empty() && periodic.back());
    if (c == ')' && !periodic.empty()) periodic.pop_back();
    ++i;
  }
}

}  // namespace

AngleTerms angle_terms(const std::string& text, const std::set<std::string>& angle_ids, const SourcePos& pos,
                       const std::string& what) {
  // The top-level terms, each with its sign.
  std::vector<std::pair<int, std::string>> terms;
  int depth = 0, sign = 1;
  std::string cur;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '(' || c == '[') ++depth;
    if (c == ')' || c == ']') --depth;
    if (depth == 0 && (c == '+' || c == '-') && !exponent_sign(text, i)) {
      const std::string t = trimmed(cur);
      if (t.empty()) {  // a sign at the start of a term
        if (c == '-') sign = -sign;
        continue;
      }
      if (t.back() == '*' || t.back() == '/' || t.back() == '^') {  // a sign inside a product: a * -b
        cur += c;
        continue;
      }
      terms.push_back({sign, t});
      sign = c == '-' ? -1 : 1;
      cur.clear();
      continue;
    }
    cur += c;
  }
  if (!trimmed(cur).empty()) terms.push_back({sign, trimmed(cur)});
  AngleTerms out;
  std::string rest;
  for (const auto& [s, term] : terms) {
    if (angle_ids.count(term)) {
      out.angles.push_back(term);
      out.signs.push_back(s);
      continue;
    }
    check_periodic(term, angle_ids, pos, what);
    rest += (s < 0 ? " - " : rest.empty() ? "" : " + ") + ("(" + term + ")");
  }
  if (out.angles.empty()) return {{}, {}, text};
  for (const std::string& a : out.angles) {
    const auto twice = std::count(out.angles.begin(), out.angles.end(), a) > 1;
    bool in_rest = false;
    for (std::size_t i = rest.find(a); i != std::string::npos && !in_rest; i = rest.find(a, i + 1))
      in_rest = (i == 0 || !ident_char(rest[i - 1])) && (i + a.size() == rest.size() || !ident_char(rest[i + a.size()]));
    if (twice || in_rest)
      throw ProblemError(pos, "the angle '" + a + "' in " + what + " as a term and elsewhere too",
                         "an angle term once in the sum (write 2*" + a + " as " + a + " + " + a +
                             " is not allowed either: modulo 2 pi it is another equation)");
  }
  out.rest = rest.empty() ? "0" : rest;
  return out;
}

namespace {

// The components of a tuple "(e1, e2, ...)" that is the whole text (commas
// inside brackets or calls are not split); the text alone otherwise.
std::vector<std::string> tuple_components(const std::string& text) {
  const std::string t = trimmed(text);
  if (t.size() < 2 || t.front() != '(' || t.back() != ')') return {text};
  std::vector<std::string> out;
  int depth = 0;
  std::string cur;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const char c = t[i];
    if (c == '(' || c == '[') ++depth;
    if (c == ')' || c == ']') --depth;
    if (depth == 0 && i + 1 < t.size()) return {text};  // "(a) + (b)": not one tuple
    if (depth == 1 && c == ',') {
      out.push_back(cur);
      cur.clear();
    } else if (i > 0 && i + 1 < t.size()) {
      cur += c;
    }
  }
  out.push_back(cur);
  return out.size() > 1 ? out : std::vector<std::string>{text};
}

// Several equations over one box, each on its own components, to a fixed
// point (a few passes): a tuple whose components hold angle terms.
class CtcEquations : public Ctc {
 public:
  explicit CtcEquations(std::size_t n) : Ctc(n) {}
  void add(std::shared_ptr<const Ctc> c, std::vector<std::size_t> at) { parts_.push_back({std::move(c), std::move(at)}); }
  std::string name() const override { return "CtcEquations"; }
  void contract(IntervalVector& x) const override {
    check_dim(x);
    for (int pass = 0; pass < 8; ++pass) {
      const IntervalVector before = x;
      for (const auto& [ctc, at] : parts_) {
        IntervalVector sub(at.size());
        for (std::size_t i = 0; i < at.size(); ++i) sub[i] = x[at[i]];
        ctc->contract(sub);
        if (sub.is_empty()) return x.set_empty();
        for (std::size_t i = 0; i < at.size(); ++i) x[at[i]] = sub[i];
      }
      if (x == before) return;
    }
  }

 private:
  std::vector<std::pair<std::shared_ptr<const Ctc>, std::vector<std::size_t>>> parts_;
};

}  // namespace

std::shared_ptr<const Ctc> equation_ctc(const RewrittenExpr& r, const std::set<std::string>& angles, const SourcePos& pos,
                                        const std::string& what, std::vector<std::size_t>& order) {
  order.clear();
  std::set<std::string> ids;
  for (const VarRef& ref : r.refs)
    if (angles.count(ref.var)) ids.insert(ref.id);
  const std::vector<std::string> parts = tuple_components(r.text);
  if (parts.size() > 1 && !ids.empty()) {  // each equation of the tuple on its own, modulo 2π where it has angle terms
    auto all = std::make_shared<CtcEquations>(r.refs.size());
    for (const std::string& part : parts) {
      std::vector<std::size_t> at;
      auto ctc = equation_ctc({part, r.refs}, angles, pos, what, at);
      all->add(std::move(ctc), std::move(at));
    }
    for (std::size_t i = 0; i < r.refs.size(); ++i) order.push_back(i);
    return all;
  }
  const AngleTerms terms = angle_terms(r.text, ids, pos, what);
  if (terms.angles.empty()) {
    for (std::size_t i = 0; i < r.refs.size(); ++i) order.push_back(i);
    return std::make_shared<CtcFunction>(Function(r.ids(), r.text));
  }
  const auto index_of = [&](const std::string& id) {
    for (std::size_t i = 0; i < r.refs.size(); ++i)
      if (r.refs[i].id == id) return i;
    return r.refs.size();
  };
  for (const std::string& a : terms.angles) order.push_back(index_of(a));
  std::vector<std::string> rest_ids;
  for (std::size_t i = 0; i < r.refs.size(); ++i) {
    if (std::find(terms.angles.begin(), terms.angles.end(), r.refs[i].id) != terms.angles.end()) continue;
    order.push_back(i);
    rest_ids.push_back(r.refs[i].id);
  }
  return std::make_shared<CtcAngleEquation>(terms.signs, Function(rest_ids, terms.rest));
}

bool has_angle_terms(const std::string& text, const std::set<std::string>& angle_ids, const SourcePos& pos,
                     const std::string& what) {
  bool any = false;
  for (const std::string& part : tuple_components(text)) any = !angle_terms(part, angle_ids, pos, what).angles.empty() || any;
  return any;
}

std::set<std::string> angle_names(const Problem& p) {
  std::set<std::string> out;
  for (const VarSpec& v : p.vars)
    if (v.angle) out.insert(v.name);
  return out;
}

void check_angle_uses(const Problem& p) {
  const std::set<std::string> angles = angle_names(p);
  if (angles.empty()) return;
  for (const ConstraintSpec& c : p.constraints) {
    const auto refuse = [&](const std::string& name) {
      if (angles.count(name))
        throw ProblemError(c.pos, "the angle '" + name + "' in " + c.label,
                           "an angle tube (angle = true) as x of a deriv (x' = v), y of an eval (with its rate v), or in "
                           "an expression; the other kinds read it as a real value");
    };
    switch (c.kind) {
      case ConstraintKind::Expr:
        (void)has_angle_terms(c.expr, angles, c.expr_pos, c.label);
        break;
      case ConstraintKind::Deriv:
        refuse(c.v);
        break;
      case ConstraintKind::Eval:
        (void)has_angle_terms(c.expr, angles, c.expr_pos, c.label);
        for (std::size_t j = 0; j < c.ys.size(); ++j) {
          if (!angles.count(c.ys[j])) continue;
          if (c.vs[j].empty())
            throw ProblemError(c.pos, "the angle '" + c.ys[j] + "' evaluated without its rate in " + c.label,
                               "v = [...] naming the rate of " + c.ys[j] + " (its value between two slices' gates)");
          refuse(c.vs[j]);
          if (c.q) throw ProblemError(c.pos, "q on an eval of the angle '" + c.ys[j] + "'", "q on evals of real tubes");
        }
        break;
      default:
        for (const std::string* n : {&c.x, &c.v, &c.p, &c.psi, &c.dist, &c.omega, &c.dpsi, &c.w, &c.z}) refuse(*n);
    }
  }
}

}  // namespace sillage::detail
