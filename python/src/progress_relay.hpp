#pragma once
// A Python progress callback for an analysis that runs without the GIL.
//
// The analyses report progress through std::function (a line of text, or
// the simulated time); a relay turns each call into a call of the Python
// callable, taking the GIL for it (from whichever thread calls: a study's
// workers too). An exception the callable raises must not travel through
// the analysis (a speed sweep takes any exception at a speed as "no result
// there"): the relay keeps the first one, calls the callable no more, and
// rethrow() raises it once the analysis has returned.
#include <pybind11/pybind11.h>

#include <functional>
#include <memory>
#include <mutex>
#include <string>

namespace railstab::python {

class ProgressRelay {
 public:
  // `callback`: None (no progress) or a callable taking one argument.
  explicit ProgressRelay(pybind11::object callback);
  // Empty when there is no callback, so the analysis skips building lines.
  std::function<void(const std::string&)> lines();
  std::function<void(double)> times();
  // With the GIL held, after the analysis: the callback's exception, if any.
  void rethrow();

 private:
  template <class T> void call(const T& argument);
  pybind11::object callback_;
  std::mutex mutex_;
  std::unique_ptr<pybind11::error_already_set> error_;
};

}  // namespace railstab::python
