// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file progress_callback.h
/// @brief The library's Interrupter driven by a Python callable, and running C++ work
///        with the GIL released.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <future>
#include <mutex>
#include <string>
#include <vector>

#include "isovdb/progress.h"

namespace isovdb::python {

namespace py = pybind11;

/// Calls `callback(stage: str, percent: int)` whenever a stage's percentage changes
/// (from any worker thread; the GIL is taken for the call, so calls are serialised).
/// While the work runs (run()), the Python caller's thread waits and runs Python's
/// signal handlers every 50 ms, so Ctrl-C (a Jupyter "interrupt kernel") stops the
/// work with KeyboardInterrupt whichever thread the work is on. When the callback or a
/// signal handler raises, every later wasInterrupted() answers true, the library
/// throws Interrupted, and run() re-raises the Python exception instead.
class CallbackProgress final : public Interrupter {
 public:
  /// `callback` None: reports nothing; only a signal interrupts.
  explicit CallbackProgress(py::object callback);
  ~CallbackProgress() override;

  void start(const char* name) override;
  void end() override;
  bool wasInterrupted(int percent) override;

  /// Runs `work` on a worker thread with the GIL released, the caller's thread
  /// watching for signals. Re-raises the callback's or the signal handler's exception
  /// when one raised (whether or not the work stopped because of it).
  template <typename Work>
  void run(Work&& work) {
    std::exception_ptr workError;
    {
      py::gil_scoped_release release;
      auto done = std::async(std::launch::async, [&] {
        try {
          work();
        } catch (...) {
          workError = std::current_exception();
        }
      });
      while (done.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) checkSignals();
    }
    if (workError) {
      try {
        std::rethrow_exception(workError);
      } catch (const Interrupted&) {
        rethrowCallbackError();
        throw;
      }
    }
    rethrowCallbackError();
  }

 private:
  /// Runs Python's signal handlers (with the GIL); a raising handler interrupts the work.
  void checkSignals();
  void rethrowCallbackError();
  /// Records the Python exception being raised (the first one wins) and answers true
  /// from now on. @pre the GIL is held.
  void fail();

  py::object callback_;
  std::mutex mutex_;  ///< stages_, lastPercent_ (taken before the GIL, never after)
  std::vector<std::string> stages_;
  int lastPercent_ = -2;
  std::atomic<bool> failed_{false};
  std::exception_ptr error_;  ///< written with the GIL held
};

}  // namespace isovdb::python
