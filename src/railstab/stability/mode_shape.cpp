#include <railstab/stability/mode_shape.hpp>

#include <railstab/linear/jacobian.hpp>
#include <railstab/stability/modes.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace railstab {

Eigen::VectorXd coordinate_inertia(const Model& model) {
  const int n = model.n_coordinates;
  Eigen::VectorXd m(n);
  for (int k = 0; k < n; ++k) {
    const auto [b, c] = model.coordinate_of_state[size_t(k)];
    const Body& body = model.bodies[size_t(b)];
    m(k) = c < 3 ? body.mass_kg : body.inertia_kg_m2(c - 3);
  }
  return m;
}

Eigen::MatrixXd suspension_stiffness(const Model& model, double speed_m_per_s, double t_s,
                                     const Eigen::VectorXd& x) {
  const int n = model.n_coordinates;
  if (x.size() != model.state_size())
    throw std::invalid_argument("suspension_stiffness: state has " + std::to_string(x.size()) +
                                " entries, the model " + std::to_string(model.state_size()));
  // du/dt = M^-1 (F_contact + F_inertial + F_elements + F_gravity): the
  // difference of the two Jacobians is the elements' and gravity's part.
  const Eigen::MatrixXd all = rhs_jacobian_ad(model, speed_m_per_s, t_s, x, ForceSelection::all);
  const Eigen::MatrixXd contact =
      rhs_jacobian_ad(model, speed_m_per_s, t_s, x, ForceSelection::contact_and_inertia);
  const Eigen::MatrixXd d_acc_d_q = (all - contact).block(n, 0, n, n);
  return -(coordinate_inertia(model).asDiagonal() * d_acc_d_q);
}

ModeShapeBasis mode_shape_basis(const Model& model, const LinearModel& lin) {
  ModeShapeBasis basis;
  basis.kept_of.assign(size_t(model.state_size()), -1);
  for (size_t i = 0; i < lin.kept_states.size(); ++i)
    basis.kept_of[size_t(lin.kept_states[i])] = int(i);
  basis.inertia = coordinate_inertia(model);
  return basis;
}

ModeShape mode_shape(const Model& model, const LinearModel& lin, const Eigen::MatrixXd& stiffness,
                     std::complex<double> lambda, const Eigen::VectorXcd& vector) {
  return mode_shape(model, lin, mode_shape_basis(model, lin), stiffness, lambda, vector);
}

ModeShape mode_shape(const Model& model, const LinearModel& lin, const ModeShapeBasis& basis,
                     const Eigen::MatrixXd& stiffness, std::complex<double> lambda,
                     const Eigen::VectorXcd& vector) {
  const int n = model.n_coordinates;
  if (vector.size() != Eigen::Index(lin.kept_states.size()))
    throw std::invalid_argument("mode_shape: eigenvector has " + std::to_string(vector.size()) +
                                " entries, the linear model keeps " +
                                std::to_string(lin.kept_states.size()) + " states");
  const bool with_potential = stiffness.size() > 0;
  if (with_potential && (stiffness.rows() != n || stiffness.cols() != n))
    throw std::invalid_argument("mode_shape: stiffness must be " + std::to_string(n) + " x " +
                                std::to_string(n) + " (one row per free coordinate) or empty");
  const std::vector<int>& kept_of = basis.kept_of;
  Eigen::VectorXcd q = Eigen::VectorXcd::Zero(n), u = Eigen::VectorXcd::Zero(n);
  for (int k = 0; k < n; ++k) {
    const int iq = kept_of[size_t(k)], iu = kept_of[size_t(n + k)];
    if (iu >= 0) u(k) = vector(iu);
    if (iq >= 0)
      q(k) = vector(iq);
    else if (iu >= 0 && std::abs(lambda) > 0.0)
      q(k) = u(k) / lambda;  // a removed cyclic position: q = u / lambda
    if (iu < 0) u(k) = lambda * q(k);
  }
  ModeShape shape;
  // Reference coordinate: largest lateral, else translation, else any.
  const Eigen::VectorXd abs_q = q.cwiseAbs();  // each modulus once (hypot)
  // No free body coordinate (n = 0): the mode is an element's internal state
  // alone (a series damper relaxing, lambda = -k_s / c); it has no body
  // motion to describe. maxCoeff of an empty vector reads past its end.
  const double largest = n > 0 ? abs_q.maxCoeff() : 0.0;
  auto pick = [&](auto eligible) {
    int best = -1;
    for (int k = 0; k < n; ++k) {
      if (!eligible(model.coordinate_of_state[size_t(k)].second)) continue;
      if (best < 0 || abs_q(k) > abs_q(best)) best = k;
    }
    return best >= 0 && abs_q(best) > 1e-6 * largest ? best : -1;
  };
  int ref = pick([](int c) { return c == 1; });
  if (ref < 0) ref = pick([](int c) { return c < 3; });
  if (ref < 0) ref = pick([](int) { return true; });
  shape.reference = ref;
  if (ref >= 0) {
    const std::complex<double> s = 1.0 / q(ref);
    q *= s;
    u *= s;
    q(ref) = 1.0;  // exactly, not 1 + round-off
  }
  const Eigen::VectorXd& m = basis.inertia;
  double kinetic = 0.0, potential = 0.0, potential_scale = 0.0;
  shape.coordinates.resize(size_t(n));
  for (int k = 0; k < n; ++k) {
    CoordinateMotion& c = shape.coordinates[size_t(k)];
    std::tie(c.body, c.coordinate) = model.coordinate_of_state[size_t(k)];
    c.displacement = q(k);
    c.kinetic_share = m(k) * std::norm(u(k));
    kinetic += c.kinetic_share;
  }
  // The potential shares only with a stiffness: O(n^2) per mode (a speed
  // sweep describes every mode at every speed without one, and computing
  // them on a zero matrix was most of its cost).
  if (with_potential) {
    const Eigen::MatrixXd K_s = 0.5 * (stiffness + stiffness.transpose());
    const Eigen::VectorXcd Kq = K_s.cast<std::complex<double>>() * q;
    const Eigen::VectorXd abs_q_hat = q.cwiseAbs();  // of the normalised q
    for (int k = 0; k < n; ++k) {
      CoordinateMotion& c = shape.coordinates[size_t(k)];
      c.potential_share = (std::conj(q(k)) * Kq(k)).real();
      potential += c.potential_share;
      potential_scale += abs_q_hat(k) * (K_s.row(k).cwiseAbs() * abs_q_hat).value();
    }
  }
  // Round-off of the quadratic form is ~eps times its terms' magnitudes.
  shape.potential_defined =
      with_potential && potential > 1e-9 * potential_scale && potential_scale > 0.0;
  for (CoordinateMotion& c : shape.coordinates) {
    c.kinetic_share = kinetic > 0.0 ? c.kinetic_share / kinetic : 0.0;
    c.potential_share = shape.potential_defined ? c.potential_share / potential : 0.0;
  }
  return shape;
}

std::string coordinate_label(const Model& model, const CoordinateMotion& c) {
  return model.bodies[size_t(c.body)].name + " " + coordinate_word(c.coordinate);
}

}  // namespace railstab
