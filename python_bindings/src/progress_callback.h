// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file progress_callback.h
/// @brief The library's Interrupter driven by a Python callable, and running C++ work
///        with the GIL released.
#pragma once

#include <pybind11/pybind11.h>

#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "isovdb/progress.h"

namespace isovdb::python {

namespace py = pybind11;

/// Calls `callback(stage: str, percent: int)` whenever a stage's percentage changes
/// (from any worker thread; the GIL is taken for the call, so calls are serialised).
/// Calls made on the thread that created it (the Python caller's) also run Python's
/// signal handlers, so Ctrl-C (a Jupyter "interrupt kernel") stops the work with
/// KeyboardInterrupt. When the callback or a signal handler raises, every later
/// wasInterrupted() answers true, the library throws Interrupted, and run() re-raises
/// the Python exception instead.
class CallbackProgress final : public Interrupter {
 public:
  /// `callback` None: reports nothing, never interrupts.
  explicit CallbackProgress(py::object callback);
  ~CallbackProgress() override;

  void start(const char* name) override;
  void end() override;
  bool wasInterrupted(int percent) override;

  /// Runs `work` with the GIL released. Re-raises the callback's exception when it
  /// raised (whether or not the work stopped because of it).
  template <typename Work>
  void run(Work&& work) {
    try {
      py::gil_scoped_release release;
      work();
    } catch (const Interrupted&) {
      rethrowCallbackError();
      throw;
    }
    rethrowCallbackError();
  }

 private:
  void rethrowCallbackError();
  /// Records the Python exception being raised and answers true from now on.
  void fail();

  py::object callback_;
  std::thread::id caller_ = std::this_thread::get_id();
  std::mutex mutex_;
  std::vector<std::string> stages_;
  int lastPercent_ = -2;
  bool failed_ = false;
  std::exception_ptr error_;
};

}  // namespace isovdb::python
