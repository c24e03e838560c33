#include "python_commands.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace sillage::cli {

namespace {

// The interpreter and the build tree's package folder, from CMake (tools/sillage/CMakeLists.txt).
constexpr const char* kPython = SILLAGE_PYTHON;
constexpr const char* kBuildPythonDir = SILLAGE_BUILD_PYTHON_DIR;

// PYTHONPATH with the build tree's package first, when it is there (a build with the bindings).
void put_build_tree_on_path() {
  if (!std::filesystem::exists(std::filesystem::path(kBuildPythonDir) / "sillage" / "distributed.py")) return;
  const char* old = std::getenv("PYTHONPATH");
  std::string path = kBuildPythonDir;
  if (old && *old) path += std::string(":") + old;
  setenv("PYTHONPATH", path.c_str(), 1);
}

}  // namespace

bool is_python_command(const char* name) {
  return std::strcmp(name, "batch") == 0 || std::strcmp(name, "sweep") == 0;
}

int run_python_command(int argc, char** argv) {
  put_build_tree_on_path();
  std::vector<char*> args{const_cast<char*>(kPython), const_cast<char*>("-m"),
                          const_cast<char*>("sillage.distributed")};
  for (int i = 1; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  std::fflush(nullptr);
  execvp(kPython, args.data());
  std::fprintf(stderr,
               "sillage %s: could not run %s (%s): this command needs Python 3 with the sillage package and Dask "
               "distributed (scripts/setup.sh installs them)\n",
               argv[1], kPython, std::strerror(errno));
  return 2;
}

}  // namespace sillage::cli
