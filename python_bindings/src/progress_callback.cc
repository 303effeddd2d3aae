// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "progress_callback.h"

namespace isovdb::python {

CallbackProgress::CallbackProgress(py::object callback)
    : callback_(callback.is_none() ? py::object() : std::move(callback)) {}

CallbackProgress::~CallbackProgress() {
  // The stored Python exception must be released with the GIL held (we hold it here:
  // the object lives on the binding function's stack).
  error_ = nullptr;
}

void CallbackProgress::start(const char* name) {
  std::lock_guard lock(mutex_);
  stages_.emplace_back(name ? name : "working");
  lastPercent_ = -2;
}

void CallbackProgress::end() {
  std::lock_guard lock(mutex_);
  if (!stages_.empty()) stages_.pop_back();
  lastPercent_ = -2;
}

bool CallbackProgress::wasInterrupted(int percent) {
  if (failed_ || !callback_) return failed_;
  std::lock_guard lock(mutex_);
  if (failed_ || percent == lastPercent_) return failed_;
  lastPercent_ = percent;
  py::gil_scoped_acquire gil;
  try {
    callback_(stages_.empty() ? std::string("working") : stages_.back(), percent);
  } catch (py::error_already_set&) {
    if (!error_) error_ = std::current_exception();
    failed_ = true;
  }
  return failed_;
}

void CallbackProgress::checkSignals() {
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) fail();
}

void CallbackProgress::fail() {
  try {
    throw py::error_already_set();  // takes the pending Python exception
  } catch (py::error_already_set&) {
    if (!error_) error_ = std::current_exception();
  }
  failed_ = true;
}

void CallbackProgress::rethrowCallbackError() {
  if (error_) {
    std::exception_ptr error = error_;
    error_ = nullptr;
    std::rethrow_exception(error);
  }
}

}  // namespace isovdb::python
