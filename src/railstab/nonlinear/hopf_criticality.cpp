#include <railstab/nonlinear/hopf_criticality.hpp>

#include <railstab/equilibrium/speed_continuation.hpp>
#include <railstab/linear/linearization.hpp>

#include <railstab/linalg/dense_decompositions.hpp>

#include <cmath>
#include <ctime>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace railstab {

std::string hopf_kind_name(HopfKind kind) {
  switch (kind) {
    case HopfKind::supercritical: return "supercritical";
    case HopfKind::subcritical: return "subcritical";
    case HopfKind::degenerate: return "degenerate";
  }
  return "degenerate";
}

namespace {

using cd = std::complex<double>;

double cpu_seconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

// Unit 2-norm, largest-magnitude entry real and positive.
Eigen::VectorXcd normalised(Eigen::VectorXcd v) {
  v /= v.norm();
  Eigen::Index k = 0;
  v.cwiseAbs().maxCoeff(&k);
  v *= std::conj(v(k)) / std::abs(v(k));
  return v;
}

// A's kernel (right, K) and left kernel (P) from the SVD: the singular
// vectors whose singular values are below tolerance * the largest.
struct Kernel {
  Eigen::MatrixXd right, left;
};
Kernel kernel_of(const Eigen::MatrixXd& A, double tolerance) {
  Eigen::BDCSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  const double limit = tolerance * (s.size() > 0 ? s(0) : 0.0);
  int m = 0;
  for (Eigen::Index i = s.size() - 1; i >= 0 && s(i) <= limit; --i) ++m;
  Kernel k;
  k.right = svd.matrixV().rightCols(m);
  k.left = svd.matrixU().rightCols(m);
  return k;
}

}  // namespace

HopfCoefficient hopf_coefficient(const Eigen::MatrixXd& A, const MultilinearForms& forms,
                                 std::complex<double> eigenvalue_guess,
                                 const HopfOptions& options) {
  const Eigen::Index n = A.rows();
  if (A.cols() != n || n < 2)
    throw std::invalid_argument("hopf_coefficient: A must be square with at least 2 rows (is " +
                                std::to_string(A.rows()) + " x " + std::to_string(A.cols()) + ")");
  if (forms.size != n || !forms.second || !forms.third)
    throw std::invalid_argument("hopf_coefficient: the forms act on " + std::to_string(forms.size) +
                                "-vectors, A is " + std::to_string(n) + " x " + std::to_string(n));
  const int evaluations_before = *forms.evaluations;
  HopfCoefficient h;

  // lambda and q: the eigenpair nearest the guess, then polished by two
  // steps of inverse iteration with the same shift; p by inverse iteration
  // on (A - lambda I)^H.
  Eigen::EigenSolver<Eigen::MatrixXd> eig(A, true);
  if (eig.info() != Eigen::Success) throw std::runtime_error("hopf_coefficient: eigen-solve failed");
  const cd guess(eigenvalue_guess.real(), std::abs(eigenvalue_guess.imag()));
  Eigen::Index best = 0;
  (eig.eigenvalues().array() - guess).abs().minCoeff(&best);
  cd lambda = eig.eigenvalues()(best);
  Eigen::VectorXcd q = eig.eigenvectors().col(best);
  if (lambda.imag() < 0.0) {
    lambda = std::conj(lambda);
    q = q.conjugate().eval();
  }
  const double normA = A.norm();
  if (!(lambda.imag() > 1e-12 * std::max(normA, 1.0))) {
    std::ostringstream msg;
    msg << "hopf_coefficient: the eigenvalue nearest " << eigenvalue_guess << " is " << lambda
        << ", real: no Hopf pair";
    throw std::runtime_error(msg.str());
  }
  // The shift sits 1e-10 |lambda| off lambda so that (A - shift I) is
  // regular even where lambda is exact (a test system's +-i): each step
  // then reduces the other eigenvectors' share by ~1e-10 |lambda| / gap.
  const cd shift = lambda + 1e-10 * std::max(1.0, std::abs(lambda)) * cd(M_SQRT1_2, M_SQRT1_2);
  const Eigen::MatrixXcd M = A.cast<cd>() - shift * Eigen::MatrixXcd::Identity(n, n);
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(M);
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu_adjoint(M.adjoint());
  q = normalised(q);
  for (int step = 0; step < 2; ++step) q = normalised(lu.solve(q));
  Eigen::VectorXcd p = q;  // not orthogonal to the left vector (<p_true, q> != 0)
  for (int step = 0; step < 3; ++step) {
    p = lu_adjoint.solve(p);
    p /= p.norm();
  }
  p /= std::conj(p.dot(q));  // <p, q> = p^H q = 1
  h.eigenvalue = lambda;
  h.omega0 = lambda.imag();
  h.real_part = lambda.real();
  h.q = q;
  h.p = p;
  h.eigen_residual =
      std::max((A.cast<cd>() * q - lambda * q).norm(),
               (A.transpose().cast<cd>() * p - std::conj(lambda) * p).norm() / p.norm()) /
      std::max(normA, std::numeric_limits<double>::min());

  // h11 = -A^{-1} B(q, qbar), in the complement of A's kernel.
  const Eigen::VectorXcd qbar = q.conjugate();
  const Eigen::VectorXd b11 = second_derivative(forms, q, qbar).real();
  const Eigen::VectorXcd b20 = second_derivative(forms, q, q);
  const double scale = std::max({b11.norm(), b20.norm(), std::numeric_limits<double>::min()});
  const Kernel kernel = kernel_of(A, options.kernel_tolerance);
  const Eigen::Index m = kernel.right.cols();
  h.kernel_dimension = int(m);
  if (m == 0) {
    h.h11 = -Eigen::PartialPivLU<Eigen::MatrixXd>(A).solve(b11);
  } else {
    // Non-defective kernel: P^T K regular (the bordered matrix is then too).
    const Eigen::MatrixXd PK = kernel.left.transpose() * kernel.right;
    const Eigen::JacobiSVD<Eigen::MatrixXd> pk(PK);
    if (pk.singularValues()(m - 1) < 1e-8)
      throw std::runtime_error("hopf_coefficient: A's zero eigenvalue is defective (a Jordan "
                               "block: its left and right null vectors are orthogonal); "
                               "A^{-1} B(q, qbar) has no bounded solution");
    Eigen::MatrixXd bordered = Eigen::MatrixXd::Zero(n + m, n + m);
    bordered.topLeftCorner(n, n) = A;
    bordered.topRightCorner(n, m) = kernel.right;
    bordered.bottomLeftCorner(m, n) = kernel.right.transpose();
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + m);
    rhs.head(n) = b11;
    const Eigen::VectorXd sol = Eigen::FullPivLU<Eigen::MatrixXd>(bordered).solve(rhs);
    h.h11 = -sol.head(n);
    h.kernel_drift = sol.tail(m).norm() / scale;
    for (Eigen::Index j = 0; j < m; ++j) {
      const Eigen::VectorXcd kq =
          second_derivative(forms, kernel.right.col(j).cast<cd>(), q);
      h.kernel_coupling = std::max(h.kernel_coupling, kq.norm() / scale);
    }
  }
  // h20 = (2 i w0 I - A)^{-1} B(q, q).
  const Eigen::MatrixXcd S =
      cd(0.0, 2.0 * h.omega0) * Eigen::MatrixXcd::Identity(n, n) - A.cast<cd>();
  h.h20 = Eigen::PartialPivLU<Eigen::MatrixXcd>(S).solve(b20);

  // 2 c1 = <p, C(q, q, qbar)> + 2 <p, B(q, h11)> + <p, B(qbar, h20)>.
  h.cubic_term = p.dot(third_derivative(forms, q, q, qbar));
  h.h11_term = 2.0 * p.dot(second_derivative(forms, q, h.h11.cast<cd>()));
  h.h20_term = p.dot(second_derivative(forms, qbar, h.h20));
  const cd twice_c1 = h.cubic_term + h.h11_term + h.h20_term;
  h.c1 = 0.5 * twice_c1;
  h.first_lyapunov_coefficient = h.c1.real() / h.omega0;
  const double size_of_terms = std::abs(h.cubic_term) + std::abs(h.h11_term) + std::abs(h.h20_term);
  if (std::abs(twice_c1.real()) <= options.degenerate_tolerance * size_of_terms)
    h.kind = HopfKind::degenerate;
  else
    h.kind = h.first_lyapunov_coefficient < 0.0 ? HopfKind::supercritical : HopfKind::subcritical;
  h.form_evaluations = *forms.evaluations - evaluations_before;
  return h;
}

double cycle_radius_squared(const HopfCoefficient& hopf, double real_part) {
  if (hopf.kind == HopfKind::degenerate) return std::numeric_limits<double>::quiet_NaN();
  const double rho2 = -real_part / hopf.c1.real();
  return rho2 >= 0.0 ? rho2 : std::numeric_limits<double>::quiet_NaN();
}

namespace {

// The linear model at speed V from the steady state x0 at V0.
LinearModel linear_model_at(const Model& model, double V0, const Eigen::VectorXd& x0, double V,
                            double time_s) {
  EquilibriumOptions eq;
  eq.time_s = time_s;
  const EquilibriumResult e = continue_equilibrium_in_speed(model, V0, x0, V, eq);
  LinearizationOptions lin;
  lin.time_s = time_s;
  return linearize(model, V, e.state, lin);
}

}  // namespace

HopfCriticality hopf_criticality(const Model& model, double speed_m_per_s,
                                 const Eigen::VectorXd& equilibrium,
                                 std::complex<double> eigenvalue_guess,
                                 const HopfOptions& options, double time_s) {
  const double start = cpu_seconds();
  if (equilibrium.size() != model.state_size())
    throw std::invalid_argument("hopf_criticality: the steady state has " +
                                std::to_string(equilibrium.size()) + " entries, the model " +
                                std::to_string(model.state_size()) + " states");
  if (!(options.speed_step_m_per_s > 0.0) || options.speed_step_m_per_s >= speed_m_per_s)
    throw std::invalid_argument("hopf_criticality: speed_step_m_per_s must be in (0, V)");
  HopfCriticality r;
  r.speed_m_per_s = speed_m_per_s;
  LinearizationOptions lin_opt;
  lin_opt.time_s = time_s;
  const LinearModel lin = linearize(model, speed_m_per_s, equilibrium, lin_opt);
  r.kept_states = lin.kept_states;
  r.state_names = lin.state_names;
  const MultilinearForms forms =
      model_multilinear_forms(model, speed_m_per_s, time_s, equilibrium, lin.kept_states);
  r.hopf = hopf_coefficient(lin.A, forms, eigenvalue_guess, options);
  r.first_lyapunov_coefficient = r.hopf.first_lyapunov_coefficient;
  r.kind = r.hopf.kind;

  // d Re(lambda)/dV = Re(p^H dA/dV q), dA/dV by a central difference.
  const double h = options.speed_step_m_per_s;
  const LinearModel up = linear_model_at(model, speed_m_per_s, equilibrium, speed_m_per_s + h, time_s);
  const LinearModel down =
      linear_model_at(model, speed_m_per_s, equilibrium, speed_m_per_s - h, time_s);
  if (up.kept_states != lin.kept_states || down.kept_states != lin.kept_states)
    throw std::runtime_error("hopf_criticality: the linear model at V +- h keeps other states "
                             "than at V (a coordinate is cyclic at one speed only)");
  const Eigen::MatrixXcd dA = ((up.A - down.A) / (2.0 * h)).cast<std::complex<double>>();
  r.real_part_speed_derivative = r.hopf.p.dot(dA * r.hopf.q).real();
  const double slope = r.real_part_speed_derivative;
  r.critical_speed_m_per_s =
      slope != 0.0 ? speed_m_per_s - r.hopf.real_part / slope : speed_m_per_s;

  const double l1 = r.first_lyapunov_coefficient;
  r.amplitude_per_sqrt_speed = Eigen::VectorXd::Zero(r.hopf.q.size());
  if (r.kind != HopfKind::degenerate && slope != 0.0) {
    // rho^2 = -slope (V - Vc) / Re(c1) > 0  <=>  sign(V - Vc) = -sign(slope l1).
    r.cycle_side = (slope * l1 < 0.0) ? 1 : -1;
    const double rho_per_sqrt_speed = std::sqrt(std::abs(slope) / (r.hopf.omega0 * std::abs(l1)));
    r.amplitude_per_sqrt_speed = 2.0 * rho_per_sqrt_speed * r.hopf.q.cwiseAbs();
  }
  r.seconds = cpu_seconds() - start;
  return r;
}

HopfCriticality hopf_criticality(const Model& model, const CriticalSpeedResult& result,
                                 const HopfOptions& options) {
  const StabilityPoint& at = result.at_critical;
  if (!result.critical_speed_found)
    throw std::invalid_argument("hopf_criticality: the critical-speed search found no critical "
                                "speed (no Hopf point to analyse)");
  if (at.least_stable < 0 || at.least_stable >= int(at.modes.size()))
    throw std::invalid_argument("hopf_criticality: the critical speed's point has no least "
                                "stable mode");
  return hopf_criticality(model, at.speed_m_per_s, at.equilibrium.state,
                          at.modes[size_t(at.least_stable)].eigenvalue, options, at.time_s);
}

double predicted_amplitude(const HopfCriticality& h, const std::string& state_name,
                           double speed_m_per_s) {
  for (size_t k = 0; k < h.state_names.size(); ++k) {
    if (h.state_names[k] != state_name) continue;
    const double dv = speed_m_per_s - h.critical_speed_m_per_s;
    if (h.cycle_side == 0 || dv * h.cycle_side < 0.0) return 0.0;
    return h.amplitude_per_sqrt_speed(Eigen::Index(k)) * std::sqrt(std::abs(dv));
  }
  std::ostringstream msg;
  msg << "predicted_amplitude: no kept state named '" << state_name << "' (kept:";
  for (const std::string& s : h.state_names) msg << " " << s;
  msg << ")";
  throw std::invalid_argument(msg.str());
}

}  // namespace railstab
