#pragma once
// [[constraint]] kind = "python" (docs/cli.md): a user's contractor written in
// Python, a sillage.TubeCtc subclass, joins a problem file. The library has
// no Python interpreter: the sillage Python module, when imported, sets the
// factory that imports the user's class and makes its network contractor.
// Without it (the sillage command), building such a problem is an Error
// saying to solve the file from Python (sillage.solve(path)).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sillage/cn/network_ctc.h"
#include "sillage/problem/build_network.h"

namespace sillage {

// Makes the contractor of the python constraint c of the problem file `file`, on the domains
// of its args (in the order of c.args).
using PythonConstraintFactory = std::function<std::shared_ptr<const NetworkCtc>(
    const ConstraintSpec& c, const std::string& file, const std::vector<const VarDomain*>& args)>;

// Sets the factory (the Python module does, when imported); an empty one removes it.
void set_python_constraint_factory(PythonConstraintFactory f);

// True once a factory is set (in a Python process).
bool has_python_constraint_factory();

// The contractor of c through the factory; Error naming c and its place when none is set.
std::shared_ptr<const NetworkCtc> make_python_constraint(const ConstraintSpec& c, const std::string& file,
                                                         const std::vector<const VarDomain*>& args);

}  // namespace sillage
