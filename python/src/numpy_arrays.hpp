#pragma once
// numpy arrays from the library's vectors, copied (the results outlive the
// C++ structures they come from). Built with the GIL held.
#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Dense>

#include <complex>
#include <vector>

namespace railstab::python {

template <class T> pybind11::array_t<T> array_of(const std::vector<T>& v) {
  pybind11::array_t<T> a(pybind11::ssize_t(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

// A dense matrix, row-major as numpy expects by default: m[i, j] = M(i, j).
template <class Scalar>
pybind11::array_t<Scalar> array_of(const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& m) {
  pybind11::array_t<Scalar> a({pybind11::ssize_t(m.rows()), pybind11::ssize_t(m.cols())});
  auto r = a.template mutable_unchecked<2>();
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) r(i, j) = m(i, j);
  return a;
}

}  // namespace railstab::python
