#include "sillage/problem/python_constraint.h"

#include <mutex>

#include "sillage/error.h"

namespace sillage {

namespace {

std::mutex& factory_mutex() {
  static std::mutex m;
  return m;
}

PythonConstraintFactory& factory() {
  static PythonConstraintFactory f;
  return f;
}

}  // namespace

void set_python_constraint_factory(PythonConstraintFactory f) {
  const std::lock_guard<std::mutex> lock(factory_mutex());
  factory() = std::move(f);
}

bool has_python_constraint_factory() {
  const std::lock_guard<std::mutex> lock(factory_mutex());
  return static_cast<bool>(factory());
}

std::shared_ptr<const NetworkCtc> make_python_constraint(const ConstraintSpec& c, const std::string& file,
                                                         const std::vector<const VarDomain*>& args) {
  PythonConstraintFactory f;
  {
    const std::lock_guard<std::mutex> lock(factory_mutex());
    f = factory();
  }
  if (!f)
    throw Error(c.pos.str() + ": " + c.label + " needs Python, and the sillage command runs none: solve this file "
                "from Python, where the module " + c.module + " is imported (python3 -c \"import sillage; "
                "sillage.solve('" + file + "')\", docs/cli.md)");
  return f(c, file, args);
}

}  // namespace sillage
