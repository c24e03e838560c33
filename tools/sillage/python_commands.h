#pragma once
// sillage batch and sillage sweep (docs/distributed.md): the Dask client is
// Python (python/sillage/distributed.py), so these commands hand their
// arguments to `python3 -m sillage.distributed`, the package found in the
// build tree first, else where Python finds it (installed).
namespace sillage::cli {

// True for the commands that run in Python.
bool is_python_command(const char* name);

// Replaces this process by the Python interpreter running sillage.distributed
// with argv[1..] (the command and its arguments); returns only on failure, with
// the exit status after saying why on stderr.
int run_python_command(int argc, char** argv);

}  // namespace sillage::cli
