#pragma once
// The second and third derivatives of a vector field f: R^n -> R^n at a point
// x0 as multilinear forms (Kuznetsov, Elements of Applied Bifurcation
// Theory, 3rd ed., (3.17) and 5.4):
//
//   B(u, v)    = d^2/(ds dt)        f(x0 + s u + t v)        at s = t = 0,
//   C(u, v, w) = d^3/(ds dt dr)     f(x0 + s u + t v + r w)  at 0,
//
// symmetric in their arguments. Evaluated exactly by nested forward AD
// (core/nested_dual.hpp, Dual3 = Dual<Dual<Dual<double>>>): one evaluation
// of f in Dual3 seeded with x0 + e1 u + e2 v + e3 w gives B(u, v) (the e1 e2
// coefficient) and C(u, v, w) (the e1 e2 e3 coefficient); no step size.
//
// Complex arguments (the Hopf eigenvector q) by multilinearity over the real
// and imaginary parts: B(ur + i ui, vr + i vi) = B(ur, vr) - B(ui, vi)
// + i (B(ur, vi) + B(ui, vr)), and the same with 8 real terms for C.
//
// For the railway model (model_multilinear_forms) the forms act on the
// linear model's reduced state (linear/linearization.hpp: cyclic positions
// removed): a reduced vector is embedded into the full state with zeros in
// the removed coordinates, and only the kept rows of f are returned. That
// is the full system's forms restricted to the kept states as long as the
// removed coordinates do not enter f at any order (a cyclic coordinate:
// the spin angle of an axisymmetric wheelset); full_state_forms gives the
// forms on the full state, so a test can check that they do not.
#include <railstab/core/nested_dual.hpp>
#include <railstab/core/scalar.hpp>
#include <railstab/model/model.hpp>

#include <Eigen/Dense>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace railstab {

struct MultilinearForms {
  int size = 0;  // n: arguments and values are n-vectors
  std::function<Eigen::VectorXd(const Eigen::VectorXd&, const Eigen::VectorXd&)> second;
  std::function<Eigen::VectorXd(const Eigen::VectorXd&, const Eigen::VectorXd&,
                                const Eigen::VectorXd&)>
      third;
  // Real evaluations made so far (each one evaluation of f in Dual3).
  std::shared_ptr<int> evaluations = std::make_shared<int>(0);
};

// Complex arguments by multilinearity (4 real evaluations for B, 8 for C).
Eigen::VectorXcd second_derivative(const MultilinearForms& forms, const Eigen::VectorXcd& u,
                                   const Eigen::VectorXcd& v);
Eigen::VectorXcd third_derivative(const MultilinearForms& forms, const Eigen::VectorXcd& u,
                                  const Eigen::VectorXcd& v, const Eigen::VectorXcd& w);

// f(x0 + e1 u + e2 v + e3 w) for a callable f templated on the scalar:
// f(const VecX<T>& x) -> VecX<T>, called here with T = Dual3 (a test
// system, or anything written once for every scalar).
template <class F>
Eigen::Matrix<Dual3, Eigen::Dynamic, 1> evaluate_dual3(const F& f, const Eigen::VectorXd& x0,
                                                       const Eigen::VectorXd& u,
                                                       const Eigen::VectorXd& v,
                                                       const Eigen::VectorXd& w) {
  VecX<Dual3> x(x0.size());
  for (Eigen::Index i = 0; i < x0.size(); ++i) x(i) = seed_dual3(x0(i), u(i), v(i), w(i));
  return f(x);
}

// The forms of a callable f (as above) at x0.
template <class F> MultilinearForms multilinear_forms(F f, const Eigen::VectorXd& x0) {
  MultilinearForms forms;
  forms.size = int(x0.size());
  auto count = forms.evaluations;
  auto check = [n = x0.size()](const Eigen::VectorXd& a, const char* what) {
    if (a.size() != n)
      throw std::invalid_argument(std::string("multilinear_forms: argument ") + what + " has size " +
                                  std::to_string(a.size()) + ", the system has " +
                                  std::to_string(n) + " states");
  };
  forms.second = [f, x0, count, check](const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
    check(u, "u");
    check(v, "v");
    ++*count;
    const VecX<Dual3> y = evaluate_dual3(f, x0, u, v, Eigen::VectorXd::Zero(x0.size()));
    Eigen::VectorXd out(y.size());
    for (Eigen::Index i = 0; i < y.size(); ++i) out(i) = dual3_second_uv(y(i));
    return out;
  };
  forms.third = [f, x0, count, check](const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                                      const Eigen::VectorXd& w) {
    check(u, "u");
    check(v, "v");
    check(w, "w");
    ++*count;
    const VecX<Dual3> y = evaluate_dual3(f, x0, u, v, w);
    Eigen::VectorXd out(y.size());
    for (Eigen::Index i = 0; i < y.size(); ++i) out(i) = dual3_third_uvw(y(i));
    return out;
  };
  return forms;
}

// The model's forms at the state x (full state, an equilibrium or not) and
// speed V, on the reduced state `kept_states` (LinearModel::kept_states:
// arguments and values are kept_states.size()-vectors). evaluate_rhs in
// Dual3 (instantiated in model/equations_of_motion.cpp). The model must
// outlive the forms.
MultilinearForms model_multilinear_forms(const Model& model, double speed_m_per_s, double t_s,
                                         const Eigen::VectorXd& x,
                                         std::vector<int> kept_states);

// The same on the full state (every coordinate, none removed).
MultilinearForms full_state_forms(const Model& model, double speed_m_per_s, double t_s,
                                  const Eigen::VectorXd& x);

// First derivative f'(x) u of the model along u (full state) by the same
// Dual3 evaluation: for checking the forms against the AD Jacobian.
Eigen::VectorXd model_directional_derivative(const Model& model, double speed_m_per_s, double t_s,
                                             const Eigen::VectorXd& x, const Eigen::VectorXd& u);

}  // namespace railstab
