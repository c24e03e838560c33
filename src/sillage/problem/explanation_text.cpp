// Explanation::str(): the explanation as `sillage solve` and `sillage explain` print it.
#include <cstdio>

#include "sillage/problem/explain_empty.h"
#include "sillage/problem/interval_text.h"

namespace sillage {

namespace {

using detail::interval_text;

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f s", s);
  return buf;
}

std::string items_text(const Explanation& e, const Relaxation& r) {
  std::string s;
  for (std::size_t k = 0; k < r.items.size(); ++k) s += (k ? k + 1 == r.items.size() ? " and " : ", " : "") + e.items[r.items[k]].str();
  return s;
}


std::string value_text(const ProvenValue& v) {
  std::string s = v.what + " is then proven in " + v.proven_text() +
                  (v.window.is_unbounded() ? "" : " (searched within " + interval_text(v.window) + ")") +
                  "; the file states " + interval_text(v.stated);
  return s + (v.disjoint() ? ": impossible given the rest of the file" : "");
}

}  // namespace

std::string ProvenValue::proven_text() const {
  if (pieces.empty()) return interval_text(proven);
  std::string s;
  for (std::size_t k = 0; k < pieces.size(); ++k) s += (k ? " ∪ " : "") + interval_text(pieces[k]);
  return s;
}

std::string Explanation::str() const {
  if (!empty) {
    if (!stopped.empty()) return "nothing explained: " + stopped + "\n";
    return "nothing to explain: the problem's contraction is not empty (no contradiction found)\n";
  }
  std::string s = "Explanation (δ = " + number_text(delta) + ", " + std::to_string(slices) + " slices; " +
                  std::to_string(trials.size()) + " trials in " + seconds_text(seconds) + "):\n";
  for (std::size_t k = 0; k < relaxations.size(); ++k) {
    const Relaxation& r = relaxations[k];
    s += "  " + std::to_string(k + 1) + ". relaxing " + items_text(*this, r) + " restores a solution (no contradiction found" +
         (r.items.size() > 1 ? std::string(r.minimal ? "; each of them is needed" : "; not checked minimal") : "") + ")\n";
    for (const ProvenValue& v : r.values) s += "     " + value_text(v) + "\n";
  }
  if (relaxations.empty())
    s += complete ? "  no set of the file's statements found whose relaxation removes the contradiction\n"
                  : "  no relaxation found in the time given\n";
  else
    s += "  (\"restores a solution\": the relaxed problem's contraction is not empty, which every solution needs but "
         "does not prove one)\n";
  if (!stopped.empty()) s += "  partial: " + stopped + "\n";
  return s;
}

}  // namespace sillage
