// The registry of the binding files (SILLAGE_BINDING, bindings.h) and the
// order in which the module calls them.
#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "bindings.h"

namespace sillage::python {

std::vector<Binding>& binding_registry() {
  static std::vector<Binding> registry;  // filled by the static registrars, before the module's init
  return registry;
}

BindingRegistrar::BindingRegistrar(const char* name, std::initializer_list<const char*> after,
                                   void (*init)(py::module_&), const char* file) {
  std::string f(file);
  const auto at = f.rfind("python/src/");
  binding_registry().push_back({name, {after.begin(), after.end()}, init, at == std::string::npos ? f : f.substr(at)});
}

std::vector<const Binding*> binding_order(const std::vector<Binding>& bindings) {
  std::map<std::string, const Binding*> by_name;
  for (const Binding& b : bindings) {
    const auto [it, fresh] = by_name.emplace(b.name, &b);
    if (!fresh) {
      throw std::runtime_error("sillage bindings: '" + b.name + "' is registered twice (" + it->second->file +
                               " and " + b.file + ")");
    }
  }
  for (const Binding& b : bindings) {
    for (const std::string& d : b.after) {
      if (!by_name.count(d)) {
        throw std::runtime_error("sillage bindings: '" + b.name + "' (" + b.file + ") is declared after '" + d +
                                 "', which no SILLAGE_BINDING registers");
      }
    }
  }
  // Depth-first, the dependencies first, the bindings in name order: the same
  // order whatever the order of the static initializers.
  std::vector<const Binding*> order;
  std::map<std::string, int> state;  // 1: being visited, 2: done
  std::vector<std::string> path;
  auto visit = [&](auto&& self, const Binding& b) -> void {
    int& s = state[b.name];
    if (s == 2) return;
    if (s == 1) {
      std::string cycle;
      for (auto it = std::find(path.begin(), path.end(), b.name); it != path.end(); ++it) cycle += *it + " -> ";
      throw std::runtime_error("sillage bindings: a cycle of dependencies: " + cycle + b.name);
    }
    s = 1;
    path.push_back(b.name);
    std::vector<std::string> after = b.after;
    std::sort(after.begin(), after.end());
    for (const std::string& d : after) self(self, *by_name.at(d));
    path.pop_back();
    state[b.name] = 2;
    order.push_back(&b);
  };
  for (const auto& [name, b] : by_name) visit(visit, *b);
  return order;
}

}  // namespace sillage::python
