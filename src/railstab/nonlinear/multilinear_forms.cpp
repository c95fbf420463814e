#include <railstab/nonlinear/multilinear_forms.hpp>

#include <railstab/model/equations_of_motion.hpp>

#include <memory>
#include <sstream>

namespace railstab {

Eigen::VectorXcd second_derivative(const MultilinearForms& forms, const Eigen::VectorXcd& u,
                                   const Eigen::VectorXcd& v) {
  const Eigen::VectorXd ur = u.real(), ui = u.imag(), vr = v.real(), vi = v.imag();
  const Eigen::VectorXd re = forms.second(ur, vr) - forms.second(ui, vi);
  const Eigen::VectorXd im = forms.second(ur, vi) + forms.second(ui, vr);
  Eigen::VectorXcd out(re.size());
  out.real() = re;
  out.imag() = im;
  return out;
}

Eigen::VectorXcd third_derivative(const MultilinearForms& forms, const Eigen::VectorXcd& u,
                                  const Eigen::VectorXcd& v, const Eigen::VectorXcd& w) {
  // C(ur + i ui, vr + i vi, wr + i wi): each of the 8 real terms carries
  // i^(number of imaginary parts taken).
  const Eigen::VectorXd a[2] = {u.real(), u.imag()}, b[2] = {v.real(), v.imag()},
                        c[2] = {w.real(), w.imag()};
  Eigen::VectorXcd out = Eigen::VectorXcd::Zero(forms.size);
  const std::complex<double> i_power[4] = {1.0, {0.0, 1.0}, -1.0, {0.0, -1.0}};
  for (int ia = 0; ia < 2; ++ia)
    for (int ib = 0; ib < 2; ++ib)
      for (int ic = 0; ic < 2; ++ic) {
        // A zero part adds nothing: skip its evaluation (real arguments).
        if (a[ia].isZero(0.0) || b[ib].isZero(0.0) || c[ic].isZero(0.0)) continue;
        out += i_power[ia + ib + ic] * forms.third(a[ia], b[ib], c[ic]).cast<std::complex<double>>();
      }
  return out;
}

namespace {

// One evaluation of the model in Dual3 along full-state directions.
VecX<Dual3> model_dual3(const Model& model, Workspace<Dual3>& ws, double speed, double t,
                        const Eigen::VectorXd& x, const Eigen::VectorXd& u,
                        const Eigen::VectorXd& v, const Eigen::VectorXd& w) {
  VecX<Dual3> X(x.size()), Xdot;
  for (Eigen::Index i = 0; i < x.size(); ++i) X(i) = seed_dual3(x(i), u(i), v(i), w(i));
  evaluate_rhs<Dual3>(model, ws, t, speed, X, Xdot);
  return Xdot;
}

void require_size(const Eigen::VectorXd& a, Eigen::Index n, const char* what, const char* where) {
  if (a.size() != n) {
    std::ostringstream msg;
    msg << where << ": " << what << " has size " << a.size() << ", expected " << n;
    throw std::invalid_argument(msg.str());
  }
}

// kept = all states when empty.
MultilinearForms forms_on(const Model& model, double speed, double t, const Eigen::VectorXd& x,
                          std::vector<int> kept) {
  const int N = model.state_size();
  require_size(x, N, "the state x", "model_multilinear_forms");
  for (int k : kept)
    if (k < 0 || k >= N)
      throw std::invalid_argument("model_multilinear_forms: kept state index " + std::to_string(k) +
                                  " outside the state (size " + std::to_string(N) + ")");
  if (kept.empty())
    for (int k = 0; k < N; ++k) kept.push_back(k);
  MultilinearForms forms;
  forms.size = int(kept.size());
  auto ws = std::make_shared<Workspace<Dual3>>(model);
  auto count = forms.evaluations;
  const Model* m = &model;
  auto embed = [kept, N](const Eigen::VectorXd& a, const char* what) {
    require_size(a, Eigen::Index(kept.size()), what, "model_multilinear_forms");
    Eigen::VectorXd full = Eigen::VectorXd::Zero(N);
    for (size_t i = 0; i < kept.size(); ++i) full(kept[i]) = a(Eigen::Index(i));
    return full;
  };
  auto evaluate = [m, ws, count, speed, t, x, kept, embed](const Eigen::VectorXd& u,
                                                           const Eigen::VectorXd& v,
                                                           const Eigen::VectorXd& w, bool third) {
    ++*count;
    const VecX<Dual3> y = model_dual3(*m, *ws, speed, t, x, embed(u, "u"), embed(v, "v"),
                                      embed(w, "w"));
    Eigen::VectorXd out(Eigen::Index(kept.size()));
    for (size_t i = 0; i < kept.size(); ++i) {
      const Dual3& yi = y(kept[i]);
      out(Eigen::Index(i)) = third ? dual3_third_uvw(yi) : dual3_second_uv(yi);
    }
    return out;
  };
  const int n = forms.size;
  forms.second = [evaluate, n](const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
    return evaluate(u, v, Eigen::VectorXd::Zero(n), false);
  };
  forms.third = [evaluate](const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                           const Eigen::VectorXd& w) { return evaluate(u, v, w, true); };
  return forms;
}

}  // namespace

MultilinearForms model_multilinear_forms(const Model& model, double speed_m_per_s, double t_s,
                                         const Eigen::VectorXd& x, std::vector<int> kept_states) {
  if (kept_states.empty())
    throw std::invalid_argument("model_multilinear_forms: no kept states (use full_state_forms "
                                "for the whole state)");
  return forms_on(model, speed_m_per_s, t_s, x, std::move(kept_states));
}

MultilinearForms full_state_forms(const Model& model, double speed_m_per_s, double t_s,
                                  const Eigen::VectorXd& x) {
  return forms_on(model, speed_m_per_s, t_s, x, {});
}

Eigen::VectorXd model_directional_derivative(const Model& model, double speed_m_per_s, double t_s,
                                             const Eigen::VectorXd& x, const Eigen::VectorXd& u) {
  const Eigen::Index N = model.state_size();
  require_size(x, N, "the state x", "model_directional_derivative");
  require_size(u, N, "the direction u", "model_directional_derivative");
  Workspace<Dual3> ws(model);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(N);
  const VecX<Dual3> y = model_dual3(model, ws, speed_m_per_s, t_s, x, u, zero, zero);
  Eigen::VectorXd out(N);
  for (Eigen::Index i = 0; i < N; ++i) out(i) = dual3_first_u(y(i));
  return out;
}

}  // namespace railstab
