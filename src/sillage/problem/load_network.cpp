// [network]: how the propagation runs (wake ratio, order of the constraints, scheduling).
#include "sillage/problem/problem_loader.h"

namespace sillage::detail {

void ProblemLoader::read_network(const toml::table& t) {
  const Fields f(doc_, t, "[network]", {"ratio", "order", "scheduling"});
  if (const toml::node* o = f.find("order")) {
    const std::string os = f.string(*o, "\"file\" or \"cost\"");
    if (os == "cost") p_.network.order = ConstraintOrder::Cost;
    else if (os != "file") throw ProblemError(doc_.pos(*o), describe(*o), "\"file\" or \"cost\"");
  }
  if (const toml::node* s = f.find("scheduling")) {
    const std::string ss = f.string(*s, "\"fifo\" or \"priority\"");
    if (ss == "priority") p_.network.scheduling = Scheduling::Priority;
    else if (ss != "fifo") throw ProblemError(doc_.pos(*s), describe(*s), "\"fifo\" or \"priority\"");
  }
  p_.network.pos = f.pos();
  if (const toml::node* r = f.find("ratio")) {
    const double v = f.number(*r, "a ratio in [0, 1)");
    if (!(v >= 0 && v < 1)) throw ProblemError(doc_.pos(*r), "ratio = " + doc_.raw(*r), "a ratio in [0, 1)");
    p_.network.ratio = v;
  }
}

}  // namespace sillage::detail
