// A long job (a render, a sheet) run from Python so that Python stays in charge: the job runs on a thread
// of its own while the calling thread waits without the GIL, taking it back every few milliseconds to let
// Python handle signals (Ctrl-C raises KeyboardInterrupt there, and only there: CPython runs signal handlers
// on the main thread) and to report progress. A Python exception from either cancels the job through its
// JobControl, waits for it to stop, and propagates; the job's own exceptions propagate as they are.
#pragma once

#include "renderer/python/module_support.h"
#include "renderer/util/job_control.h"

#include <chrono>
#include <future>
#include <thread>

namespace glossy::python {

// progress: None, or callable(done, total) called with the job's tiles (total 0 while unknown) when they move.
template <class Work>
auto runInterruptible(JobControl& control, const py::object& progress, Work&& work) {
  using Result = decltype(work());
  std::packaged_task<Result()> task(std::forward<Work>(work));
  std::future<Result> result = task.get_future();
  std::thread worker(std::move(task));
  // Each change of (done, total), from the first tile or the first known total on.
  uint64_t reportedDone = 0, reportedTotal = 0;
  auto report = [&] {
    const uint64_t total = control.total.load(), done = control.done.load();
    if (progress.is_none() || (done == reportedDone && total == reportedTotal)) return;
    reportedDone = done, reportedTotal = total;
    progress(done, total);
  };
  try {
    for (;;) {
      bool finished;
      {
        py::gil_scoped_release noGil;
        finished = result.wait_for(std::chrono::milliseconds(50)) == std::future_status::ready;
      }
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (finished) break;
      report();
    }
    report();
  } catch (...) {
    control.cancelled = true;
    {
      py::gil_scoped_release noGil;
      worker.join();
    }
    throw;
  }
  worker.join();
  return result.get();
}

}  // namespace glossy::python
