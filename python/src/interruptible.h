#pragma once
// Ctrl-C for long C++ computations. Python runs its signal handlers only on
// the main thread when it holds the GIL, so a computation that releases the
// GIL never sees a KeyboardInterrupt. run_interruptible runs the computation
// on a worker thread, with a fresh CancelToken in its budget, while the
// calling thread waits without the GIL and wakes every 50 ms to take it and
// call PyErr_CheckSignals(). When a handler raises (KeyboardInterrupt), the
// token is cancelled, the worker stops at its next box and that error is
// raised; the user's own token, cancelled from another thread, is relayed the
// same way and gives sillage.Cancelled.
#include <chrono>
#include <exception>
#include <future>
#include <thread>
#include <utility>

#include "bindings.h"
#include "sillage/budget.h"

namespace sillage::python {

// `run(token)` computes the result, checking `token` (the budget it uses must
// hold this token); `user` is the token of the caller's options.
template <class Run>
auto run_interruptible(const CancelToken& user, Run&& run) {
  const CancelToken token;
  if (user.cancelled()) token.cancel();  // cancelled before the start: stop at the first box
  using Result = decltype(run(token));
  std::packaged_task<Result()> task([&run, &token] { return run(token); });
  std::future<Result> result = task.get_future();
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    std::thread worker(std::move(task));
    while (result.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
      if (user.cancelled()) token.cancel();
      py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {
        token.cancel();
        interrupted = true;
        break;
      }
    }
    worker.join();
  }
  if (interrupted) throw py::error_already_set();  // the handler's exception, KeyboardInterrupt
  return result.get();                              // or rethrows the worker's exception
}

// The same with the caller's token optional (an argument cancel=None).
template <class Run>
auto run_interruptible(const CancelToken* user, Run&& run) {
  return run_interruptible(user != nullptr ? *user : CancelToken(), std::forward<Run>(run));
}

// The budget, or the options with their budget, holding `token`.
inline Budget with_token(Budget b, const CancelToken& token) {
  b.cancel = token;
  return b;
}
template <class Options>
Options with_token(Options o, const CancelToken& token) {
  o.budget = with_token(o.budget, token);
  return o;
}

}  // namespace sillage::python
