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
  if (!callback_) return false;
  std::lock_guard lock(mutex_);
  if (failed_) return true;
  if (percent == lastPercent_) return false;
  lastPercent_ = percent;
  const std::string stage = stages_.empty() ? std::string("working") : stages_.back();
  py::gil_scoped_acquire gil;
  try {
    callback_(stage, percent);
  } catch (py::error_already_set&) {
    error_ = std::current_exception();
    failed_ = true;
  }
  return failed_;
}

void CallbackProgress::rethrowCallbackError() {
  if (error_) {
    std::exception_ptr error = error_;
    error_ = nullptr;
    std::rethrow_exception(error);
  }
}

}  // namespace isovdb::python
