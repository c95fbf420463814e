#include "progress_relay.hpp"

namespace py = pybind11;

namespace railstab::python {

ProgressRelay::ProgressRelay(py::object callback) : callback_(std::move(callback)) {
  if (!callback_.is_none() && !PyCallable_Check(callback_.ptr()))
    throw py::type_error("progress: expected a callable (or None), got " +
                         std::string(py::str(py::type::of(callback_).attr("__name__"))));
}

template <class T> void ProgressRelay::call(const T& argument) {
  std::lock_guard<std::mutex> lock(mutex_);  // one call at a time, in order
  if (error_) return;
  py::gil_scoped_acquire gil;
  try {
    callback_(argument);
  } catch (py::error_already_set& e) {
    error_ = std::make_unique<py::error_already_set>(std::move(e));
  }
}

std::function<void(const std::string&)> ProgressRelay::lines() {
  if (callback_.is_none()) return {};
  return [this](const std::string& line) { call(line); };
}

std::function<void(double)> ProgressRelay::times() {
  if (callback_.is_none()) return {};
  return [this](double t) { call(t); };
}

void ProgressRelay::rethrow() {
  if (error_) {
    py::error_already_set e = std::move(*error_);
    error_.reset();
    throw e;
  }
}

}  // namespace railstab::python
