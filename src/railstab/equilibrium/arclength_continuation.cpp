#include <railstab/equilibrium/arclength_continuation.hpp>

#include <railstab/core/coordinates.hpp>
#include <railstab/linear/jacobian.hpp>
#include <railstab/model/equations_of_motion.hpp>
#include <railstab/linalg/dense_decompositions.hpp>

#include <algorithm>
#include <cmath>
#include <new>
#include <sstream>
#include <stdexcept>

namespace railstab {

double SpeedPath::length_scale() const { return std::max(1.0, std::abs(to_ - from_)); }

std::string SpeedPath::describe(double lambda) const {
  std::ostringstream s;
  s.precision(6);
  s << "V = " << speed_at(lambda) << " m/s";
  return s.str();
}

namespace {

// Scale of each unknown (its unit in the arclength): positions and element
// states in millimetres (milliradians), a wheelset's spin rate as r0 Omega in
// m/s (it moves by 1/r0 per m/s of speed, so a speed path weighs it like
// the speed itself).
Eigen::VectorXd unknown_scales(const Model& model, const std::vector<int>& unknowns) {
  Eigen::VectorXd s(Eigen::Index(unknowns.size()));
  const int n = model.n_coordinates;
  for (size_t j = 0; j < unknowns.size(); ++j) {
    const int k = unknowns[j];
    s(Eigen::Index(j)) = 1e-3;
    if (model.is_rate(k)) {
      const auto [b, c] = model.coordinate_of_state[size_t(k - n)];
      (void)c;
      const double r0 = model.bodies[size_t(b)].nominal_q(int(CoordinateIndex::z));
      s(Eigen::Index(j)) = 1.0 / std::max(r0, 0.05);
    }
  }
  return s;
}

// The acceleration rows (the equations of the full equilibrium).
std::vector<int> acceleration_rows(const Model& model) {
  std::vector<int> rows;
  for (int k = model.n_coordinates; k < model.state_size(); ++k) rows.push_back(k);
  return rows;
}

}  // namespace

ArclengthResult continue_by_arclength(SteadyStatePath& path, const Eigen::VectorXd& start,
                                      const ArclengthOptions& options) {
  const Model& model0 = path.model_at(0.0);
  if (start.size() != model0.state_size())
    throw std::invalid_argument("continue_by_arclength: start has " + std::to_string(start.size()) +
                                " entries, the model " + std::to_string(model0.state_size()) +
                                " states");
  const std::vector<int> unknowns = equilibrium_unknowns(model0);
  const std::vector<int> rows = acceleration_rows(model0);
  // The models along the path share their structure: one plan serves all.
  const RhsJacobianPlan plan = equilibrium_jacobian_plan(model0);
  const Eigen::VectorXd scale = unknown_scales(model0, unknowns);
  const int m = int(unknowns.size());
  const double L = path.length_scale();
  const double t = options.time_s;

  // z = (w, Lambda): w = u / scale, Lambda = L lambda.
  Eigen::VectorXd base = start;
  {
    const int n = model0.n_coordinates;
    for (int k = 0; k < n; ++k)
      if (!is_spin_angle(model0, k)) base(n + k) = 0.0;  // at rest relative to the track
  }
  auto state_of = [&](const Eigen::VectorXd& z) {
    Eigen::VectorXd x = base;
    for (int j = 0; j < m; ++j) x(unknowns[size_t(j)]) = z(j) * scale(j);
    return x;
  };
  auto z_of = [&](const Eigen::VectorXd& x, double lambda) {
    Eigen::VectorXd z(m + 1);
    for (int j = 0; j < m; ++j) z(j) = x(unknowns[size_t(j)]) / scale(j);
    z(m) = L * lambda;
    return z;
  };
  auto residual = [&](const Eigen::VectorXd& x, double lambda) {
    const Eigen::VectorXd f = rhs(path.model_at(lambda), path.speed_at(lambda), t, x);
    Eigen::VectorXd r(m);
    for (int i = 0; i < m; ++i) r(i) = f(rows[size_t(i)]);
    return r;
  };
  // [F_u S, F_lambda / L]: m x (m + 1). F_lambda by central differences:
  // F is smooth in lambda (speed and track curvature enter analytically).
  auto extended_jacobian = [&](const Eigen::VectorXd& x, double lambda) {
    Eigen::MatrixXd A(m, m + 1);
    const double V = path.speed_at(lambda);
    A.leftCols(m) = rhs_jacobian_ad(path.model_at(lambda), plan, V, t, x) * scale.asDiagonal();
    const double h = 1e-6;
    const Eigen::VectorXd fp = residual(x, lambda + h);
    const Eigen::VectorXd fm = residual(x, lambda - h);
    A.col(m) = (fp - fm) / (2.0 * h * L);
    return A;
  };

  ArclengthResult out;
  out.last_lambda = 0.0;
  out.last_state = base;
  out.furthest_state = base;
  auto fail = [&](const std::string& why) {
    out.failure = why;
    return out;
  };

  // The first tangent: the null vector of [F_u S, F_lambda / L], oriented
  // towards increasing lambda.
  Eigen::VectorXd z = z_of(base, 0.0);
  Eigen::VectorXd tangent;
  try {
    const Eigen::MatrixXd A = extended_jacobian(base, 0.0);
    Eigen::MatrixXd B(m + 1, m + 1);
    B.topRows(m) = A;
    B.row(m).setZero();
    B(m, m) = 1.0;  // dLambda = 1, then normalised
    Eigen::VectorXd rhs_t = Eigen::VectorXd::Zero(m + 1);
    rhs_t(m) = 1.0;
    tangent = B.partialPivLu().solve(rhs_t);
    if (!tangent.allFinite()) return fail("the start's Jacobian is singular");
    tangent.normalize();
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    return fail(std::string("the model cannot be evaluated at the start: ") + e.what());
  }

  double ds = std::min(options.initial_step, options.max_step);
  double lambda = 0.0;
  Eigen::VectorXd x = base;
  Eigen::VectorXd previous_z = z;
  double previous_lambda = 0.0;
  while (out.steps < options.max_steps) {
    if (ds < options.min_step) {
      std::ostringstream why;
      why << "the continuation step fell below " << options.min_step
          << " (the corrector does not converge however short the step)";
      return fail(why.str());
    }
    // Predictor and corrector.
    const Eigen::VectorXd zp = z + ds * tangent;
    Eigen::VectorXd zc = zp;
    bool converged = false;
    int iterations = 0;
    Eigen::MatrixXd A;
    try {
      for (; iterations < options.max_corrector_iterations; ++iterations) {
        const double lc = zc(m) / L;
        const Eigen::VectorXd xc = state_of(zc);
        const Eigen::VectorXd r = residual(xc, lc);
        if (!r.allFinite()) break;
        const double arc = tangent.dot(zc - zp);
        if (r.cwiseAbs().maxCoeff() <= options.corrector_tolerance && std::abs(arc) < 1e-9 * (1.0 + ds)) {
          converged = true;
          A = extended_jacobian(xc, lc);
          break;
        }
        A = extended_jacobian(xc, lc);
        Eigen::MatrixXd B(m + 1, m + 1);
        B.topRows(m) = A;
        B.row(m) = tangent.transpose();
        Eigen::VectorXd g(m + 1);
        g.head(m) = r;
        g(m) = arc;
        const Eigen::VectorXd dz = B.partialPivLu().solve(-g);
        if (!dz.allFinite()) break;
        zc += dz;
      }
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception&) {
      converged = false;  // a trial point the model cannot evaluate: shorter step
    }
    // A corrector that ends far from its prediction left the branch.
    if (converged && (zc - zp).norm() > std::max(0.5 * ds, 10.0 * options.min_step)) converged = false;
    if (!converged) {
      ds *= 0.5;
      continue;
    }
    // The new tangent, oriented along the old one (through a fold).
    Eigen::MatrixXd B(m + 1, m + 1);
    B.topRows(m) = A;
    B.row(m) = tangent.transpose();
    Eigen::VectorXd e = Eigen::VectorXd::Zero(m + 1);
    e(m) = 1.0;
    Eigen::VectorXd new_tangent = B.partialPivLu().solve(e);
    if (!new_tangent.allFinite() || new_tangent.norm() == 0.0) {
      ds *= 0.5;
      continue;
    }
    new_tangent.normalize();
    if (new_tangent.dot(tangent) < 0.0) new_tangent = -new_tangent;
    if ((new_tangent(m) > 0.0) != (tangent(m) > 0.0)) {
      const double a = tangent(m), b = new_tangent(m), h = (zc - z).norm();
      ArclengthResult::Fold fold;
      fold.before_lambda = lambda;
      fold.after_lambda = zc(m) / L;
      const double vertex = (z(m) + a * a * h / (2.0 * (a - b))) / L;
      fold.lambda = a > 0.0 ? std::max({vertex, fold.before_lambda, fold.after_lambda})
                            : std::min({vertex, fold.before_lambda, fold.after_lambda});
      fold.before_state = x;
      fold.after_state = state_of(zc);
      out.fold_points.push_back(std::move(fold));
    }

    previous_z = z;
    previous_lambda = lambda;
    z = zc;
    lambda = zc(m) / L;
    x = state_of(zc);
    tangent = new_tangent;
    ++out.steps;

    if (lambda >= 1.0) {
      // Past the end: Newton at lambda = 1 exactly from the secant
      // interpolation between the last two points.
      const double f = (1.0 - previous_lambda) / (lambda - previous_lambda);
      const Eigen::VectorXd guess = state_of(previous_z + f * (z - previous_z));
      EquilibriumOptions eo;
      eo.time_s = t;
      eo.acceleration_tolerance = options.acceleration_tolerance;
      eo.pseudo_transient_fallback = false;
      eo.jacobian_plan = &plan;
      try {
        out.end = solve_equilibrium(path.model_at(1.0), path.speed_at(1.0), guess, eo);
        out.reached = true;
        out.last_lambda = 1.0;
        out.last_state = out.end.state;
        return out;
      } catch (const EquilibriumError&) {
        // Back to the last point before the end, with a step that lands
        // nearer to it.
        z = previous_z;
        lambda = previous_lambda;
        x = state_of(z);
        ds *= 0.5;
        continue;
      }
    }
    out.last_lambda = lambda;
    out.last_state = x;
    if (lambda > out.furthest_lambda) {
      out.furthest_lambda = lambda;
      out.furthest_state = x;
    }
    if (options.stop) {
      std::string why = options.stop(lambda, x);
      if (!why.empty()) {
        out.stop_reason = std::move(why);
        return out;
      }
    }
    if (lambda < -options.max_backtrack / L || path.speed_at(lambda) < 1.0) {
      std::ostringstream why;
      why << "the branch turned back at a fold and ran back beyond its start to "
          << path.describe(lambda) << " (" << out.fold_points.size() << " fold(s))";
      return fail(why.str());
    }
    if (iterations <= 3) ds = std::min(options.max_step, 1.5 * ds);
  }
  std::ostringstream why;
  why << "no end within " << options.max_steps << " continuation steps";
  return fail(why.str());
}

}  // namespace railstab
