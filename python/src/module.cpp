// railstab._railstab: the compiled half of the Python package (the other
// half, python/railstab/__init__.py, gives the functions their keywords,
// defaults and result objects). Every function takes a scene path and the
// --set texts, prepares the scene, runs the analysis with the GIL released
// and returns plain Python objects: the command's JSON text and numpy arrays.
//
// Errors: every C++ exception becomes a Python exception carrying the
// command line's message (setup/model_error_context.hpp's words in place of
// an internal function name):
//   railstab.InputError (ValueError): the input is wrong: a scene file (its
//     key and what was expected: SceneError), an argument out of range
//     (std::invalid_argument);
//   railstab.Error (RuntimeError): the analysis failed (no equilibrium, an
//     integration that gave up, a model error), and the base of both.
#include "bindings.hpp"

#include <railstab/core/version.hpp>
#include <railstab/scene_reading/scene_error.hpp>
#include <railstab/setup/model_error_context.hpp>

#include <exception>
#include <new>
#include <stdexcept>

namespace py = pybind11;

PYBIND11_MODULE(_railstab, m) {
  m.doc() = "railstab's analyses in-process (use the package railstab, not this module)";
  // Created with PyErr_NewException so that InputError can have two bases.
  static py::handle error = PyErr_NewException("railstab.Error", PyExc_RuntimeError, nullptr);
  const py::tuple input_bases = py::make_tuple(error, py::handle(PyExc_ValueError));
  static py::handle input_error = PyErr_NewException("railstab.InputError", input_bases.ptr(), nullptr);
  m.attr("Error") = error;
  m.attr("InputError") = input_error;
  py::register_exception_translator([](std::exception_ptr p) {
    if (!p) return;
    try {
      std::rethrow_exception(p);
    } catch (const railstab::SceneError& e) {
      PyErr_SetString(input_error.ptr(), railstab::without_function_name(e.what()).c_str());
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(input_error.ptr(), railstab::without_function_name(e.what()).c_str());
    } catch (const std::bad_alloc&) {
      PyErr_SetString(PyExc_MemoryError, "railstab: out of memory");
    } catch (const py::builtin_exception&) {
      throw;  // pybind11's own (type_error, ...): its translator sets them
    } catch (const py::error_already_set&) {
      throw;  // a Python exception (a progress callback's): raised as it was
    } catch (const std::exception& e) {
      PyErr_SetString(error.ptr(), railstab::without_function_name(e.what()).c_str());
    }
  });
  m.attr("__version__") = railstab::railstab_version();
  railstab::python::bind_stability(m);
  railstab::python::bind_time_domain(m);
  railstab::python::bind_studies(m);
}
