// [online]: how the problem runs online (window, forgetting, lead, outputs).
#include <cmath>

#include "sillage/problem/problem_loader.h"

namespace sillage::detail {

void ProblemLoader::read_online(const toml::table& t) {
  const Fields f(doc_, t, "[online]", {"window", "forget_every", "lead", "outputs", "output_every"});
  OnlineSpec& o = p_.online;
  o.pos = f.pos();
  const auto seconds = [&](const char* key, bool positive, double& into) {
    const toml::node* n = f.find(key);
    if (!n) return false;
    const std::string expected = positive ? "seconds > 0" : "seconds >= 0";
    into = f.number(*n, expected);
    if (!(positive ? into > 0 : into >= 0)) throw ProblemError(doc_.pos(*n), std::string(key) + " = " + doc_.raw(*n), expected);
    return true;
  };
  if (const toml::node* w = f.find("window"); w && !(w->is_string() && f.string(*w, "") == "inf")) {
    double v = 0;
    seconds("window", true, v);
    o.window = v;
  }
  seconds("forget_every", false, o.forget_every);
  seconds("lead", false, o.lead);
  seconds("output_every", false, o.output_every);
  if (const toml::node* n = f.find("outputs")) {
    for (const toml::node& e : f.array(*n, "an array of tube variable names")) {
      const std::string name = f.string(e, "a tube variable's name");
      const VarSpec* v = p_.var(name);
      if (!v || !v->is_tube()) throw ProblemError(doc_.pos(e), "\"" + name + "\"", "a tube variable's name");
      o.outputs.push_back(name);
    }
  }
}

}  // namespace sillage::detail
